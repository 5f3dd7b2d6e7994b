#include "campaign/floor_arrays.hpp"

#include "campaign/sample.hpp"
#include "simulation/simulate_row.hpp"

namespace pound {

const std::vector<FloorArrayField>& floor_array_fields() {
  using O = SampleOutcome;
  using F = FloorResponse;
  static const std::vector<FloorArrayField> fields = {
      {"peak_disp_pounding", "m", "peak floor displacement relative to the ground, pounding",
       &O::disp_pounding, &F::disp_pounding},
      {"peak_disp_free", "m", "peak floor displacement relative to the ground, no pounding",
       &O::disp_free, &F::disp_free},
      {"peak_drift_ratio_pounding", "-", "peak drift ratio of the storey below the floor, pounding",
       &O::peak_drift_ratio_pounding, &F::peak_drift_ratio_pounding, "peak_drift_pounding"},
      {"peak_drift_ratio_free", "-", "peak drift ratio of the storey below the floor, no pounding",
       &O::peak_drift_ratio_free, &F::peak_drift_ratio_free, "peak_drift_free"},
      {"peak_accel_pounding", "m/s^2", "peak absolute floor acceleration, pounding",
       &O::accel_pounding, &F::accel_pounding},
      {"peak_accel_free", "m/s^2", "peak absolute floor acceleration, no pounding", &O::accel_free,
       &F::accel_free},
      {"residual_drift_pounding", "-",
       "|drift| of the storey below the floor at the end of the run / storey height, pounding",
       &O::residual_drift_pounding, &F::residual_drift_ratio_pounding},
      {"residual_drift_free", "-",
       "|drift| of the storey below the floor at the end of the run / storey height, no pounding",
       &O::residual_drift_free, &F::residual_drift_ratio_free},
      {"ductility_pounding", "-",
       "peak storey drift / yield drift Fy / k0, pounding (NaN without yield_shears)",
       &O::ductility_pounding, &F::ductility_pounding},
      {"ductility_free", "-",
       "peak storey drift / yield drift Fy / k0, no pounding (NaN without yield_shears)",
       &O::ductility_free, &F::ductility_free},
      {"hysteretic_energy_pounding", "J",
       "hysteretic energy dissipated by the storey below the floor, pounding",
       &O::hysteretic_energy_pounding, &F::hysteretic_energy_pounding},
      {"hysteretic_energy_free", "J",
       "hysteretic energy dissipated by the storey below the floor, no pounding",
       &O::hysteretic_energy_free, &F::hysteretic_energy_free},
  };
  return fields;
}

namespace {
const char* const kResponse = "/response/";
}  // namespace

std::string stored_dataset_path(hid_t file, const std::string& path) {
  if (H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0) return path;
  for (const auto& f : floor_array_fields()) {
    if (!f.former_name || path != kResponse + std::string(f.name)) continue;
    const std::string former = kResponse + std::string(f.former_name);
    if (H5Lexists(file, former.c_str(), H5P_DEFAULT) > 0) return former;
  }
  return path;
}

std::string current_dataset_path(const std::string& path) {
  for (const auto& f : floor_array_fields())
    if (f.former_name && path == kResponse + std::string(f.former_name))
      return kResponse + std::string(f.name);
  return path;
}

}  // namespace pound

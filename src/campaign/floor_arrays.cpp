#include "campaign/floor_arrays.hpp"

#include "campaign/sample.hpp"
#include "simulation/simulate_row.hpp"

namespace pound {

namespace {

const char* const kResponse = "/response/";

// One measure of the table, with pounding and without: the arrays <name>_pounding and
// <name>_free, meaning "<what>, pounding<note>" and "<what>, no pounding<note>".
struct Measure {
  const char* name;
  const char* unit;
  const char* what;
  std::vector<double> SampleOutcome::*pounding;
  std::vector<double> SampleOutcome::*free;
  double FloorResponse::*source_pounding;
  double FloorResponse::*source_free;
  const char* note = "";
  const char* former = "";  ///< the name in files written before it was renamed ("": none)
};

}  // namespace

const std::vector<FloorArrayField>& floor_array_fields() {
  using O = SampleOutcome;
  using F = FloorResponse;
  static const std::vector<FloorArrayField> fields = [] {
    const Measure measures[] = {
        {"peak_disp", "m", "peak floor displacement relative to the ground", &O::disp_pounding,
         &O::disp_free, &F::disp_pounding, &F::disp_free},
        {"peak_drift_ratio", "-", "peak drift ratio of the storey below the floor",
         &O::peak_drift_ratio_pounding, &O::peak_drift_ratio_free, &F::peak_drift_ratio_pounding,
         &F::peak_drift_ratio_free, "", "peak_drift"},
        {"peak_accel", "m/s^2", "peak absolute floor acceleration", &O::accel_pounding,
         &O::accel_free, &F::accel_pounding, &F::accel_free},
        {"residual_drift", "-",
         "|drift| of the storey below the floor at the end of the run / storey height",
         &O::residual_drift_pounding, &O::residual_drift_free, &F::residual_drift_ratio_pounding,
         &F::residual_drift_ratio_free},
        {"ductility", "-", "peak storey drift / yield drift Fy / k0", &O::ductility_pounding,
         &O::ductility_free, &F::ductility_pounding, &F::ductility_free,
         " (NaN without yield_shears)"},
        {"hysteretic_energy", "J", "hysteretic energy dissipated by the storey below the floor",
         &O::hysteretic_energy_pounding, &O::hysteretic_energy_free, &F::hysteretic_energy_pounding,
         &F::hysteretic_energy_free},
    };
    std::vector<FloorArrayField> out;
    for (const Measure& m : measures)
      for (const bool pounding : {true, false}) {
        const std::string run = pounding ? "_pounding" : "_free";
        const std::string former = *m.former ? m.former + run : "";
        out.push_back({m.name + run, m.unit,
                       m.what + std::string(pounding ? ", pounding" : ", no pounding") + m.note,
                       pounding ? m.pounding : m.free, pounding ? m.source_pounding : m.source_free,
                       former});
      }
    return out;
  }();
  return fields;
}

std::string stored_dataset_path(hid_t file, const std::string& path) {
  if (H5Lexists(file, path.c_str(), H5P_DEFAULT) > 0) return path;
  for (const auto& f : floor_array_fields()) {
    if (f.former_name.empty() || path != kResponse + f.name) continue;
    const std::string former = kResponse + f.former_name;
    if (H5Lexists(file, former.c_str(), H5P_DEFAULT) > 0) return former;
  }
  return path;
}

std::string current_dataset_path(const std::string& path) {
  for (const auto& f : floor_array_fields())
    if (!f.former_name.empty() && path == kResponse + f.former_name) return kResponse + f.name;
  return path;
}

}  // namespace pound

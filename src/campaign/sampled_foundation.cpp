#include "campaign/sampled_foundation.hpp"

#include <limits>
#include <string>

#include "core/error.hpp"
#include "structure/foundation.hpp"

namespace pound {
namespace {

// Sets one cone parameter (Vs, rho, nu or r) of building b's foundation.
template <double Foundation::*member>
void set_foundation(SampleModel& m, int b, double v) {
  m.row.buildings[static_cast<std::size_t>(b)].foundation.*member = v;
}

// Sets one soil parameter (Vs, rho or nu) under every building on the soil (a cone or a
// Gazetas footing): one site.
template <double Foundation::*member>
void set_site_soil(SampleModel& m, int, double v) {
  for (Building& b : m.row.buildings)
    if (on_soil(b.foundation.kind)) b.foundation.*member = v;
}

// A factor on building b's sway and rocking springs and dashpots (foundation = springs).
void scale_springs(SampleModel& m, int b, double factor) {
  Foundation& f = m.row.buildings[static_cast<std::size_t>(b)].foundation;
  f.sway_stiffness *= factor;
  f.rocking_stiffness *= factor;
  f.sway_damping *= factor;
  f.rocking_damping *= factor;
}

void check_kind(const SampledParameter& p, const BuildingRow& row, const Options& smp,
                FoundationKind needed, const char* what) {
  const Foundation& f = row.buildings[static_cast<std::size_t>(p.building)].foundation;
  if (f.kind == needed) return;
  const std::string b = "building" + std::to_string(p.building + 1);
  throw InputError(smp.where(p.key) + ": " + b + ".foundation is '" + foundation_kind_name(f.kind) +
                   "'; " + what + " sampled only with " + b +
                   ".foundation = " + foundation_kind_name(needed));
}

void check_cone(const SampledParameter& p, const BuildingRow& row, const Options& smp) {
  check_kind(p, row, smp, FoundationKind::cone, "the footing radius of a cone is");
}

// A building's own soil key: its foundation stands on the soil (cone or gazetas).
void check_soil(const SampledParameter& p, const BuildingRow& row, const Options& smp) {
  const FoundationKind k = row.buildings[static_cast<std::size_t>(p.building)].foundation.kind;
  if (on_soil(k)) return;
  const std::string b = "building" + std::to_string(p.building + 1);
  throw InputError(smp.where(p.key) + ": " + b + ".foundation is '" + foundation_kind_name(k) +
                   "'; the soil under it is sampled only with " + b +
                   ".foundation = cone or gazetas");
}

void check_springs(const SampledParameter& p, const BuildingRow& row, const Options& smp) {
  check_kind(p, row, smp, FoundationKind::springs,
             "the factor on the foundation's springs and dashpots is");
}

// The site's soil key (soil_shear_velocity, ...): some building stands on a cone, and no
// building's own key for the same soil is sampled beside it.
void check_site_soil(const SampledParameter& p, const BuildingRow& row, const Options& smp) {
  bool cone = false;
  for (std::size_t b = 0; b < row.buildings.size(); ++b) {
    cone = cone || on_soil(row.buildings[b].foundation.kind);
    const std::string own = "building" + std::to_string(b + 1) + "." + p.key;
    if (is_sampled(smp, own))
      throw InputError(smp.where(p.key) + ": " + p.key +
                       " sets the soil under every building on the soil; sample it there or as " +
                       own + ", not both");
  }
  if (!cone)
    throw InputError(smp.where(p.key) +
                     ": no building has foundation = cone or gazetas; the site's soil is "
                     "sampled only under them");
}

constexpr ValidRange kPositive{};
constexpr ValidRange kPoisson{true, -std::numeric_limits<double>::infinity(), 0.5, false,
                              "soil_poisson must stay in [0, 0.5); truncate below 0.5"};

}  // namespace

std::vector<SampledParameterSpec> with_foundation_parameters(
    std::vector<SampledParameterSpec> table) {
  using F = Foundation;
  const SampleStage direct = SampleStage::direct;
  table.insert(
      table.end(),
      {
          {"soil_density", "kg/m^3",
           "cone, gazetas: density rho of the soil under every building on the soil, one site "
           "(distribution)",
           direct, kPositive, set_site_soil<&F::soil_density>, check_site_soil},
          {"soil_poisson", "-",
           "cone, gazetas: Poisson's ratio nu of the soil under every building on the soil, in "
           "[0, 0.5) "
           "(distribution)",
           direct, kPoisson, set_site_soil<&F::soil_poisson>, check_site_soil},
          {"soil_shear_velocity", "m/s",
           "cone, gazetas: shear wave velocity Vs of the soil under every building on the soil, "
           "one site "
           "(distribution)",
           direct, kPositive, set_site_soil<&F::soil_shear_velocity>, check_site_soil},
          {"building#.soil_shear_velocity", "m/s",
           "cone, gazetas: shear wave velocity Vs of the soil under the building (distribution)",
           direct, kPositive, set_foundation<&F::soil_shear_velocity>, check_soil},
          {"building#.soil_density", "kg/m^3",
           "cone, gazetas: density rho of the soil under the building (distribution)", direct,
           kPositive, set_foundation<&F::soil_density>, check_soil},
          {"building#.soil_poisson", "-",
           "cone, gazetas: Poisson's ratio nu of the soil under the building, in [0, 0.5) "
           "(distribution)",
           direct, kPoisson, set_foundation<&F::soil_poisson>, check_soil},
          {"building#.foundation_radius", "m",
           "cone: radius r of the building's circular footing (distribution)", direct, kPositive,
           set_foundation<&F::radius>, check_cone},
          {"building#.foundation_scale", "-",
           "springs: factor on the building's sway and rocking springs and dashpots "
           "(distribution)",
           direct, kPositive, scale_springs, check_springs},
      });
  return table;
}

}  // namespace pound

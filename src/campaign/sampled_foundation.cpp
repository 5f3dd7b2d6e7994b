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

// Sets one soil parameter (Vs, rho or nu) under every building on a cone: one site.
template <double Foundation::*member>
void set_site_soil(SampleModel& m, int, double v) {
  for (Building& b : m.row.buildings)
    if (b.foundation.kind == FoundationKind::cone) b.foundation.*member = v;
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
  check_kind(p, row, smp, FoundationKind::cone, "the soil and footing of a cone are");
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
    cone = cone || row.buildings[b].foundation.kind == FoundationKind::cone;
    const std::string own = "building" + std::to_string(b + 1) + "." + p.key;
    if (is_sampled(smp, own))
      throw InputError(smp.where(p.key) + ": " + p.key +
                       " sets the soil under every building on a cone; sample it there or as " +
                       own + ", not both");
  }
  if (!cone)
    throw InputError(smp.where(p.key) +
                     ": no building has foundation = cone; the site's soil is sampled only "
                     "under cone foundations");
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
           "cone: density rho of the soil under every building on a cone, one site "
           "(distribution)",
           direct, kPositive, set_site_soil<&F::soil_density>, check_site_soil},
          {"soil_poisson", "-",
           "cone: Poisson's ratio nu of the soil under every building on a cone, in [0, 0.5) "
           "(distribution)",
           direct, kPoisson, set_site_soil<&F::soil_poisson>, check_site_soil},
          {"soil_shear_velocity", "m/s",
           "cone: shear wave velocity Vs of the soil under every building on a cone, one site "
           "(distribution)",
           direct, kPositive, set_site_soil<&F::soil_shear_velocity>, check_site_soil},
          {"building#.soil_shear_velocity", "m/s",
           "cone: shear wave velocity Vs of the soil under the building (distribution)", direct,
           kPositive, set_foundation<&F::soil_shear_velocity>, check_cone},
          {"building#.soil_density", "kg/m^3",
           "cone: density rho of the soil under the building (distribution)", direct, kPositive,
           set_foundation<&F::soil_density>, check_cone},
          {"building#.soil_poisson", "-",
           "cone: Poisson's ratio nu of the soil under the building, in [0, 0.5) (distribution)",
           direct, kPoisson, set_foundation<&F::soil_poisson>, check_cone},
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

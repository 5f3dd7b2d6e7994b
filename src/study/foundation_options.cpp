#include "study/foundation_options.hpp"

#include <cmath>

namespace pound {

std::vector<OptionSpec> foundation_option_specs() {
  const std::string springs = "springs: ", cone = "cone: ", gazetas = "gazetas: ",
                    soil = "cone and gazetas: ", all = "springs, cone and gazetas: ";
  return {
      {"building#.foundation", "", "fixed",
       "the base on the soil: fixed (moves with the ground), springs (sway and rocking springs "
       "and dashpots), cone (a rigid circular surface footing on a half-space, Wolf 1994) or "
       "gazetas (a rigid rectangular surface footing on it, Gazetas 1991), in both solvers "
       "(docs/ssi.md)"},
      {"building#.sway_stiffness", "N/m", "", springs + "sway spring K_x > 0"},
      {"building#.rocking_stiffness", "N m/rad", "", springs + "rocking spring K_theta > 0"},
      {"building#.sway_damping", "N s/m", "", springs + "sway dashpot C_x > 0"},
      {"building#.rocking_damping", "N m s/rad", "", springs + "rocking dashpot C_theta > 0"},
      {"building#.foundation_radius", "m", "",
       cone + "radius r > 0 of the circular footing (a square of side B: B / sqrt(pi) for "
              "sway, B (3 pi)^(-1/4) for rocking)"},
      {"building#.foundation_length", "m", "",
       gazetas + "side > 0 of the rectangular footing along the row (the plane of sway and "
                 "rocking)"},
      {"building#.foundation_width", "m", "", gazetas + "side > 0 of the footing across the row"},
      {"building#.soil_shear_velocity", "m/s", "", soil + "shear wave velocity Vs > 0 of the soil"},
      {"building#.soil_density", "kg/m^3", "", soil + "mass density rho > 0 of the soil"},
      {"building#.soil_poisson", "-", "", soil + "Poisson's ratio nu of the soil, in [0, 0.5)"},
      {"building#.foundation_mass", "kg", "0",
       all + "mass m_0 >= 0 of the base slab (a base too light for its spring and dashpot, "
             "its own root above 1e4 / T_min, is taken as massless: docs/ssi.md)"},
      {"building#.foundation_inertia", "kg m^2", "0",
       all + "rotary inertia I_0 >= 0 of the base about the base"},
      {"building#.floor_inertias", "kg m^2", "0",
       all + "each floor's rotary inertia about its own centre, >= 0 (one value for all "
             "floors, or a list)"},
  };
}

namespace {

// A key's value checked by `valid`, or the message `what` naming it.
template <class Valid>
double checked(const Options& opt, const std::string& key, const std::string& what, Valid valid) {
  const double x = opt.get_double(key);
  if (!valid(x)) throw opt.invalid(key, "valid: " + what);
  return x;
}

bool positive(double x) {
  return x > 0.0;
}
bool nonnegative(double x) {
  return x >= 0.0;
}
bool poisson(double x) {
  return x >= 0.0 && x < 0.5;
}

constexpr unsigned bit(FoundationKind k) {
  return 1u << static_cast<unsigned>(k);
}
constexpr unsigned kEvery = 0;  // every flexible kind reads it (and none needs it)
constexpr unsigned kSoil = bit(FoundationKind::cone) | bit(FoundationKind::gazetas);

struct FoundationKey {
  const char* key;             // after the building's prefix
  unsigned kinds;              // the kinds that read and need it (bits), or kEvery
  double Foundation::*member;  // where it goes
  const char* what;            // what is valid
  bool (*valid)(double);       // its range
};

constexpr FoundationKey kKeys[] = {
    {"sway_stiffness", bit(FoundationKind::springs), &Foundation::sway_stiffness,
     "a sway stiffness K_x > 0 N/m", positive},
    {"rocking_stiffness", bit(FoundationKind::springs), &Foundation::rocking_stiffness,
     "a rocking stiffness K_theta > 0 N m/rad", positive},
    {"sway_damping", bit(FoundationKind::springs), &Foundation::sway_damping,
     "a sway damping C_x > 0 N s/m", positive},
    {"rocking_damping", bit(FoundationKind::springs), &Foundation::rocking_damping,
     "a rocking damping C_theta > 0 N m s/rad", positive},
    {"foundation_radius", bit(FoundationKind::cone), &Foundation::radius,
     "a footing radius r > 0 m", positive},
    {"foundation_length", bit(FoundationKind::gazetas), &Foundation::length,
     "a footing length > 0 m along the row", positive},
    {"foundation_width", bit(FoundationKind::gazetas), &Foundation::width,
     "a footing width > 0 m across the row", positive},
    {"soil_shear_velocity", kSoil, &Foundation::soil_shear_velocity,
     "a shear wave velocity Vs > 0 m/s", positive},
    {"soil_density", kSoil, &Foundation::soil_density, "a soil density rho > 0 kg/m^3", positive},
    {"soil_poisson", kSoil, &Foundation::soil_poisson, "a Poisson's ratio nu in [0, 0.5)", poisson},
    {"foundation_mass", kEvery, &Foundation::foundation_mass, "a foundation mass m_0 >= 0 kg",
     nonnegative},
    {"foundation_inertia", kEvery, &Foundation::foundation_inertia,
     "a rotary inertia I_0 >= 0 kg m^2", nonnegative},
};

// floor_inertias: one value for every floor or one per floor, each >= 0.
std::vector<double> floor_inertias(const Options& opt, const std::string& key, std::size_t n) {
  return opt.get_per_floor(key, n, "valid: floor rotary inertias >= 0 kg m^2",
                           [](double x) { return x >= 0.0; });
}

}  // namespace

Foundation foundation_from_options(const Options& opt, const std::string& pre, std::size_t floors) {
  Foundation f;
  const std::string name = opt.get_string(pre + "foundation");
  if (!parse_foundation_kind(name, f.kind))
    throw opt.invalid(pre + "foundation", "valid: " + foundation_kind_names());
  // Every given key is checked for its range; only the building's kind keeps it.
  for (const auto& k : kKeys) {
    const std::string key = pre + k.key;
    const bool used = f.flexible() && (k.kinds == kEvery || (k.kinds & bit(f.kind)) != 0);
    if (!opt.given(key)) {
      // Named where the foundation was chosen (the same line whichever study file lacks it).
      if (used && k.kinds != kEvery)
        throw opt.invalid(pre + "foundation", "needs " + key + ", " + k.what + " (missing)");
      continue;
    }
    const double x = checked(opt, key, k.what, k.valid);
    if (used) f.*k.member = x;
  }
  const std::string fi = pre + "floor_inertias";
  if (opt.given(fi)) {
    auto v = floor_inertias(opt, fi, floors);
    if (f.flexible()) f.floor_inertias = std::move(v);
  }
  return f;
}

}  // namespace pound

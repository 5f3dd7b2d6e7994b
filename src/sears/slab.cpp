#include "sears/slab.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace pound::sears {

double Slab::wave_speed() const {
  return chi * std::sqrt(E_Pa / rho_kg_m3);
}

double Slab::omega(int n) const {
  return n * M_PI * wave_speed() / length_m;
}

double Slab::first_mode_period() const {
  return 2.0 * length_m / wave_speed();
}

void validate(const Slab& slab, const char* what) {
  auto bad = [&](const char* name, double v, const char* valid) {
    return InputError(std::string(what) + ": " + name + " = " + std::to_string(v) +
                      " is invalid; " + valid);
  };
  auto pos = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!pos(slab.length_m)) throw bad("length", slab.length_m, "must be > 0 [m]");
  if (!pos(slab.E_Pa)) throw bad("E", slab.E_Pa, "must be > 0 [Pa]");
  if (!pos(slab.rho_kg_m3)) throw bad("rho", slab.rho_kg_m3, "must be > 0 [kg/m^3]");
  if (!pos(slab.mass_kg)) throw bad("mass", slab.mass_kg, "must be > 0 [kg]");
  if (!(std::isfinite(slab.poisson) && slab.poisson >= 0.0 && slab.poisson < 0.5))
    throw bad("poisson", slab.poisson, "must be in [0, 0.5) [-]");
  if (!(std::isfinite(slab.chi) && slab.chi > 0.0 && slab.chi <= 1.0))
    throw bad("chi", slab.chi, "must be in (0, 1] [-]");
}

}  // namespace pound::sears

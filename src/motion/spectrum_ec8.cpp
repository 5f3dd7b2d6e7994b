#include "motion/spectrum_ec8.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "motion/ground_motion.hpp"

namespace pound {

Ec8Parameters ec8_parameters(Ec8Type type, Ec8Ground ground) {
  // EN 1998-1:2004 Table 3.2 (Type 1) and Table 3.3 (Type 2): S, TB [s], TC [s], TD [s].
  static const Ec8Parameters type1[] = {{1.00, 0.15, 0.4, 2.0},
                                        {1.20, 0.15, 0.5, 2.0},
                                        {1.15, 0.20, 0.6, 2.0},
                                        {1.35, 0.20, 0.8, 2.0},
                                        {1.40, 0.15, 0.5, 2.0}};
  static const Ec8Parameters type2[] = {{1.00, 0.05, 0.25, 1.2},
                                        {1.35, 0.05, 0.25, 1.2},
                                        {1.50, 0.10, 0.25, 1.2},
                                        {1.80, 0.10, 0.30, 1.2},
                                        {1.60, 0.05, 0.25, 1.2}};
  const auto i = static_cast<std::size_t>(ground);
  return type == Ec8Type::type1 ? type1[i] : type2[i];
}

double ec8_eta(double damping) {
  // EN 1998-1 eq. (3.6): eta = sqrt(10 / (5 + xi)) >= 0.55, xi in percent.
  return std::max(0.55, std::sqrt(10.0 / (5.0 + 100.0 * damping)));
}

Ec8Spectrum::Ec8Spectrum(Ec8Type type, Ec8Ground ground, double ag, double damping)
    : type_(type),
      ground_(ground),
      ag_(ag),
      damping_(damping),
      eta_(ec8_eta(damping)),
      p_(ec8_parameters(type, ground)) {
  if (!(ag > 0.0)) throw InputError("Eurocode 8 spectrum: ag must be > 0");
  if (!(damping >= 0.0 && damping < 1.0))
    throw InputError("Eurocode 8 spectrum: damping must be in [0, 1)");
}

double Ec8Spectrum::sa(double T) const {
  // EN 1998-1 clause 3.2.2.2, eqs. (3.2)-(3.5). The code gives the spectrum up to 4 s; the
  // TD branch (constant displacement) is continued beyond (Annex A extends it differently
  // for T > 4 s, which is outside the range used here).
  const double base = ag_ * p_.S;
  if (T < p_.TB) return base * (1.0 + T / p_.TB * (eta_ * 2.5 - 1.0));  // (3.2)
  if (T <= p_.TC) return base * eta_ * 2.5;                             // (3.3)
  if (T <= p_.TD) return base * eta_ * 2.5 * p_.TC / T;                 // (3.4)
  return base * eta_ * 2.5 * p_.TC * p_.TD / (T * T);                   // (3.5)
}

std::string Ec8Spectrum::describe() const {
  std::ostringstream s;
  s << "Eurocode 8 Type " << (type_ == Ec8Type::type1 ? 1 : 2) << " elastic spectrum, ground type "
    << "ABCDE"[static_cast<int>(ground_)] << ", ag = " << ag_ / kGravity << " g, S = " << p_.S
    << ", TB = " << p_.TB << " s, TC = " << p_.TC << " s, TD = " << p_.TD << " s, damping "
    << 100.0 * damping_ << " % (eta = " << eta_ << "); EN 1998-1:2004 3.2.2.2, Tables 3.2/3.3";
  return s.str();
}

}  // namespace pound

#pragma once
// Contact laws whose damping grows with the penetration rate over the approach velocity:
//   F = k delta^n (1 + zeta ddelta),   zeta = c(e) / v0,   F clamped at >= 0,
// one implementation of three published laws that differ only in the exponent n and in the
// relation c(e) between the damping and the coefficient of restitution:
//   hertzdamp     n = 1.5, c = 3 (1 - e^2) / 4   Muthukumar & DesRoches 2006, with the
//                 Lankarani-Nikravesh damping, which assumed e close to 1: the returned e
//                 exceeds the nominal one and the error grows as e falls (Khatiwada et al. 2014)
//   hertzdamp-ye  n = 1.5, c = 8 (1 - e) / (5 e)  modified Hertzdamp (Ye, Li & Zhu 2009)
//   kelvin-ye     n = 1,   c = 3 (1 - e) / (2 e)  modified Kelvin, or linear Hunt-Crossley
//                 (Ye, Li & Zhu 2009)
// Ye's relations come from an energy balance that treats the damping as small: the returned e
// differs from the nominal one.
// Uses: k [N/m^n], e, v0_min.
#include <memory>

#include "contact/contact_law.hpp"

namespace pound {

class RateDampedContact : public ContactLaw {
 public:
  /// exponent n = 1 or 1.5 [-]; zeta_v0 = c(e) [-].
  RateDampedContact(const ContactParameters& p, double exponent, double zeta_v0);
  double force(double delta, double ddelta, double v0) const override;

 private:
  double k_;       // [N/m^n]
  bool hertz_;     // n = 1.5 (else 1)
  double factor_;  // zeta v0 = c(e) [-]
  double v0_min_;  // [m/s]
};

/// The three laws of the registry (hertzdamp, hertzdamp-ye, kelvin-ye).
std::unique_ptr<ContactLaw> make_hertzdamp(const ContactParameters& p);
std::unique_ptr<ContactLaw> make_hertzdamp_ye(const ContactParameters& p);
std::unique_ptr<ContactLaw> make_kelvin_ye(const ContactParameters& p);

}  // namespace pound

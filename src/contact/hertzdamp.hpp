#pragma once
// Hertzdamp (Muthukumar & DesRoches 2006) with the Lankarani-Nikravesh damping:
//   F = k delta^1.5 (1 + zeta ddelta),   zeta = 3 (1 - e^2) / (4 v0),   F clamped at >= 0.
// Lankarani-Nikravesh assumed e close to 1: the returned e exceeds the nominal one and the
// error grows as e falls (Khatiwada et al. 2014).
// Uses: k [N/m^1.5], e, v0_min.
#include "contact/contact_law.hpp"

namespace pound {

class Hertzdamp : public ContactLaw {
 public:
  explicit Hertzdamp(const ContactParameters& p);
  double force(double delta, double ddelta, double v0) const override;

 private:
  double k_;       // [N/m^1.5]
  double factor_;  // zeta v0 = 3 (1 - e^2) / 4 [-]
  double v0_min_;  // [m/s]
};

}  // namespace pound

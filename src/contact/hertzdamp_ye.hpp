#pragma once
// Modified Hertzdamp (Ye, Li & Zhu 2009):
//   F = k delta^1.5 (1 + zeta ddelta),   zeta = 8 (1 - e) / (5 e v0),   F clamped at >= 0.
// Derived for a Hertz law with an energy balance that treats the damping as small.
// Uses: k [N/m^1.5], e, v0_min.
#include "contact/contact_law.hpp"

namespace pound {

class HertzdampYe : public ContactLaw {
 public:
  explicit HertzdampYe(const ContactParameters& p);
  double force(double delta, double ddelta, double v0) const override;

 private:
  double k_;       // [N/m^1.5]
  double factor_;  // zeta v0 = 8 (1 - e) / (5 e) [-]
  double v0_min_;  // [m/s]
};

}  // namespace pound

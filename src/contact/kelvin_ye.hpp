#pragma once
// Modified Kelvin, or linear Hunt-Crossley, model (Ye, Li & Zhu 2009):
//   F = k delta (1 + zeta ddelta),   zeta = 3 (1 - e) / (2 e v0),   F clamped at >= 0.
// Ye's relation is a small-damping approximation: the returned e differs from the nominal.
// Uses: k [N/m], e, v0_min.
#include "contact/contact_law.hpp"

namespace pound {

class KelvinYe : public ContactLaw {
 public:
  explicit KelvinYe(const ContactParameters& p);
  double force(double delta, double ddelta, double v0) const override;

 private:
  double k_;       // [N/m]
  double factor_;  // zeta v0 = 3 (1 - e) / (2 e) [-]
  double v0_min_;  // [m/s]
};

}  // namespace pound

#pragma once
// MLVe, modified linear viscoelastic contact (Mahmoud 2008; Mahmoud & Jankowski 2011; Th. 3.2):
//   F = k delta + c ddelta  while ddelta > 0 (approach),   F = k delta  while ddelta <= 0,
//   c = 2 xi sqrt(k m1 m2 / (m1 + m2)), F clamped at >= 0.
// xi from e: xi_relation = "exact" (default) inverts the exact restitution of this law,
// e = exp(-xi acos(xi)/sqrt(1-xi^2)) (physics.md section 2), so the nominal e is honoured to
// solver precision; "published" uses Mahmoud & Jankowski's approximation
// xi = (1 - e^2) / (e (e (pi - 2) + 2)), within about 3 % in e.
// Uses: k [N/m], e, m1, m2, xi_relation.
#include "contact/contact_law.hpp"

namespace pound {

class ModifiedLinearViscoelastic : public ContactLaw {
 public:
  explicit ModifiedLinearViscoelastic(const ContactParameters& p);
  double force(double delta, double ddelta, double v0) const override;

 private:
  double k_;  // contact stiffness [N/m]
  double c_;  // approach dashpot coefficient [N s/m]
};

}  // namespace pound

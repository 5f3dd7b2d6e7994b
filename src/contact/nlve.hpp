#pragma once
// NlVe, nonlinear viscoelastic contact (Jankowski 2005; Th. 3.3):
//   F = beta delta^1.5 + c ddelta  while ddelta > 0,   F = beta delta^1.5  otherwise,
//   c = 2 xi sqrt(beta sqrt(delta) m1 m2 / (m1 + m2)),
//   xi = (9 sqrt(5) / 2) (1 - e^2) / (e (e (9 pi - 16) + 16)),   F clamped at >= 0.
// The xi(e) relation is Jankowski's approximation: the returned e is close to, not equal
// to, the nominal one (see docs/contact-models.md for the measured values).
// Uses: k = beta [N/m^1.5], e, m1, m2.
#include "contact/contact_law.hpp"

namespace pound {

class NonlinearViscoelastic : public ContactLaw {
 public:
  explicit NonlinearViscoelastic(const ContactParameters& p);
  double force(double delta, double ddelta, double v0) const override;

 private:
  double beta_;  // Hertz-type stiffness [N/m^1.5]
  double c0_;    // 2 xi sqrt(beta m1 m2/(m1+m2)); c = c0 delta^(1/4) [N s/m^(5/4)]
};

}  // namespace pound

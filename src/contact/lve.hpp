#pragma once
// LVe, linear viscoelastic contact (Anagnostopoulos 1988, 2004; Th. 3.1):
//   F = k delta + c ddelta,   c = 2 xi sqrt(k m1 m2 / (m1 + m2)),
//   xi = -ln e / sqrt(pi^2 + (ln e)^2).
// As published the dashpot acts through the whole contact, so F turns tensile just before
// separation (delta -> 0 with ddelta < 0); this behaviour is kept, and the contact ends when
// delta returns to 0, which makes the nominal e exact for a free two-mass impact.
// Uses: k [N/m], e, m1, m2.
#include "contact/contact_law.hpp"

namespace pound {

class LinearViscoelastic : public ContactLaw {
 public:
  explicit LinearViscoelastic(const ContactParameters& p);
  double force(double delta, double ddelta, double v0) const override;

 private:
  double k_;  // contact stiffness [N/m]
  double c_;  // dashpot coefficient [N s/m]
};

}  // namespace pound

#pragma once
// Stereomechanical impact (Goldsmith 1960): an instantaneous velocity jump at contact,
//   v1' = v1 - (1 + e) m2 / (m1 + m2) (v1 - v2),   v2' = v2 + (1 + e) m1 / (m1 + m2) (v1 - v2),
// which conserves momentum and returns the separation velocity e (v1 - v2). No force history:
// the integrator locates the instant of contact exactly and applies the jump there.
// Uses: e.
#include "contact/contact_law.hpp"

namespace pound {

class Stereomechanical : public ContactLaw {
 public:
  explicit Stereomechanical(const ContactParameters& p);
  double force(double, double, double) const override { return 0.0; }
  bool impulsive() const override { return true; }
  double restitution() const override { return e_; }

 private:
  double e_;  // coefficient of restitution [-]
};

}  // namespace pound

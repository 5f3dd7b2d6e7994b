#include "contact/nlve.hpp"

#include <algorithm>
#include <cmath>

#include "contact/restitution.hpp"

namespace pound {

NonlinearViscoelastic::NonlinearViscoelastic(const ContactParameters& p)
    : beta_(p.k), c0_(2.0 * nlve_damping_ratio(p.e) * std::sqrt(p.k * reduced_mass(p.m1, p.m2))) {}

// Th. 3.3: F = beta delta^1.5 + c ddelta (approach only), c = c0 delta^(1/4).
double NonlinearViscoelastic::force(double delta, double ddelta, double) const {
  const double d = std::max(delta, 0.0);
  const double sd = std::sqrt(d);
  double f = beta_ * d * sd;
  if (ddelta > 0.0) f += c0_ * std::sqrt(sd) * ddelta;
  return std::max(f, 0.0);
}

}  // namespace pound

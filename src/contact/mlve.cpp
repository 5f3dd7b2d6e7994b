#include "contact/mlve.hpp"

#include <algorithm>
#include <cmath>

#include "contact/restitution.hpp"

namespace pound {

ModifiedLinearViscoelastic::ModifiedLinearViscoelastic(const ContactParameters& p) : k_(p.k) {
  const double xi = p.xi_relation == "published" ? mlve_damping_ratio_published(p.e)
                                                 : mlve_damping_ratio_exact(p.e);
  c_ = 2.0 * xi * std::sqrt(p.k * reduced_mass(p.m1, p.m2));
}

// Th. 3.2: approach-only dashpot, never tensile.
double ModifiedLinearViscoelastic::force(double delta, double ddelta, double) const {
  const double f = ddelta > 0.0 ? k_ * delta + c_ * ddelta : k_ * delta;
  return std::max(f, 0.0);
}

}  // namespace pound

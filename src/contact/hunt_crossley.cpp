#include "contact/hunt_crossley.hpp"

#include <algorithm>
#include <cmath>

#include "contact/restitution.hpp"

namespace pound {

HuntCrossley::HuntCrossley(const ContactParameters& p, double exponent)
    : k_(p.k), n_(exponent), a_(hunt_crossley_factor(p.e)), v0_min_(p.v0_min) {}

// Th. 4.20: F = k delta^n (1 + a ddelta / v0), clamped at >= 0.
double HuntCrossley::force(double delta, double ddelta, double v0) const {
  const double d = std::max(delta, 0.0);
  const double elastic = n_ == 1.0 ? k_ * d : k_ * d * std::sqrt(d);
  return std::max(elastic * (1.0 + a_ * ddelta / std::max(v0, v0_min_)), 0.0);
}

}  // namespace pound

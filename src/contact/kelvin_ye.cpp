#include "contact/kelvin_ye.hpp"

#include <algorithm>
#include <cmath>

namespace pound {

KelvinYe::KelvinYe(const ContactParameters& p)
    : k_(p.k), factor_(1.5 * (1.0 - p.e) / p.e), v0_min_(p.v0_min) {}

// F = k delta^1.0 (1 + zeta ddelta), Ye et al. 2009: zeta = 3 (1 - e) / (2 e v0); clamped at >= 0.
double KelvinYe::force(double delta, double ddelta, double v0) const {
  const double d = std::max(delta, 0.0);
  const double zeta = factor_ / std::max(v0, v0_min_);
  return std::max(k_ * d * (1.0 + zeta * ddelta), 0.0);
}

}  // namespace pound

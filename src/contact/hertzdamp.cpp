#include "contact/hertzdamp.hpp"

#include <algorithm>
#include <cmath>

namespace pound {

Hertzdamp::Hertzdamp(const ContactParameters& p)
    : k_(p.k), factor_(0.75 * (1.0 - p.e * p.e)), v0_min_(p.v0_min) {}

// F = k delta^1.5 (1 + zeta ddelta), Lankarani-Nikravesh: zeta = 3 (1 - e^2) / (4 v0); clamped at
// >= 0.
double Hertzdamp::force(double delta, double ddelta, double v0) const {
  const double d = std::max(delta, 0.0);
  const double zeta = factor_ / std::max(v0, v0_min_);
  return std::max(k_ * d * std::sqrt(d) * (1.0 + zeta * ddelta), 0.0);
}

}  // namespace pound

#include "contact/rate_damped.hpp"

#include <algorithm>
#include <cmath>

namespace pound {

RateDampedContact::RateDampedContact(const ContactParameters& p, double exponent, double zeta_v0)
    : k_(p.k), hertz_(exponent == 1.5), factor_(zeta_v0), v0_min_(p.v0_min) {}

// F = k delta^n (1 + zeta ddelta), zeta = c(e) / v0; clamped at >= 0.
double RateDampedContact::force(double delta, double ddelta, double v0) const {
  const double d = std::max(delta, 0.0);
  const double zeta = factor_ / std::max(v0, v0_min_);
  const double elastic = hertz_ ? k_ * d * std::sqrt(d) : k_ * d;
  return std::max(elastic * (1.0 + zeta * ddelta), 0.0);
}

// Lankarani-Nikravesh: zeta = 3 (1 - e^2) / (4 v0).
std::unique_ptr<ContactLaw> make_hertzdamp(const ContactParameters& p) {
  return std::make_unique<RateDampedContact>(p, 1.5, 0.75 * (1.0 - p.e * p.e));
}

// Ye et al. 2009: zeta = 8 (1 - e) / (5 e v0).
std::unique_ptr<ContactLaw> make_hertzdamp_ye(const ContactParameters& p) {
  return std::make_unique<RateDampedContact>(p, 1.5, 1.6 * (1.0 - p.e) / p.e);
}

// Ye et al. 2009: zeta = 3 (1 - e) / (2 e v0).
std::unique_ptr<ContactLaw> make_kelvin_ye(const ContactParameters& p) {
  return std::make_unique<RateDampedContact>(p, 1.0, 1.5 * (1.0 - p.e) / p.e);
}

}  // namespace pound

#include "risk/risk_integral.hpp"

#include <algorithm>
#include <cmath>

#include "fragility/lognormal_fit.hpp"

namespace pound {
namespace {

// Phi(z2) - Phi(z1) for z1 <= z2 without cancellation in the upper tail.
double normal_mass(double z1, double z2) {
  if (!(z2 > z1)) return 0.0;
  if (z1 > 0.0) return std::exp(log_normal_cdf(-z1)) - std::exp(log_normal_cdf(-z2));
  return std::exp(log_normal_cdf(z2)) - std::exp(log_normal_cdf(z1));
}

}  // namespace

double mean_annual_frequency(const HazardCurve& h, double theta, double beta, double x_lo,
                             double x_hi) {
  if (!(x_hi > x_lo)) return 0.0;
  const double mu = std::log(theta);
  const double u_lo = x_lo > 0.0 ? std::log(x_lo) : -std::numeric_limits<double>::infinity();
  const double u_hi = std::log(x_hi);
  double nu = 0.0;
  for (const auto& s : h.segments()) {
    // Closed form of the segment (header): the lognormal density shifted by b beta^2.
    const double shift = mu + s.b * beta * beta;
    const double lo = std::max(s.lo, u_lo), hi = std::min(s.hi, u_hi);
    const double mass = normal_mass((lo - shift) / beta, (hi - shift) / beta);
    if (mass > 0.0) nu += std::exp(s.ln_rate(mu) + 0.5 * s.b * s.b * beta * beta) * mass;
  }
  // The boundary terms of the integration by parts (header):
  //   integral_lo^hi P |d lambda| = integral_lo^hi lambda dP + P(lo) lambda(lo) - P(hi) lambda(hi)
  // with P(x) = Phi(ln(x / theta) / beta) from ln Phi (no underflow to 0 in the lower tail).
  // Both vanish over (0, inf): P(0) = 0, lambda(inf) = 0.
  auto p_lambda = [&](double x) {
    return std::exp(log_normal_cdf((std::log(x) - mu) / beta)) * h.rate_at(x);
  };
  if (x_lo > 0.0) nu += p_lambda(x_lo);
  if (std::isfinite(x_hi)) nu -= p_lambda(x_hi);
  // The sum is an integral of a positive function; only rounding can take it below 0 (when
  // P is near 1 over a short range, lambda(lo) - lambda(hi) cancels).
  return std::max(nu, 0.0);
}

double probability_in_years(double maf, double years) {
  return -std::expm1(-maf * years);
}

}  // namespace pound

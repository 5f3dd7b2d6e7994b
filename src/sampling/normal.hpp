#pragma once
// The standard normal distribution, written out so that sampled values do not depend on a
// standard library's distribution internals.
namespace pound {

/// Phi(x) = erfc(-x / sqrt 2) / 2.
double normal_cdf(double x);
/// Phi^-1(p) for p in (0, 1): Acklam's rational approximation (relative error 1.2e-9)
/// polished by one Halley step on Phi(x) - p, which brings it to double precision.
double normal_quantile(double p);

}  // namespace pound

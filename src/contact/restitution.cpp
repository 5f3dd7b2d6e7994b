#include "contact/restitution.hpp"

#include <cmath>

#include "core/error.hpp"

namespace pound {
namespace {
constexpr double kPi = 3.14159265358979323846;

// Bisection on [lo, hi] for a monotone function with f(lo), f(hi) of opposite signs; to
// machine precision (the interval halves until it stops shrinking).
template <class F>
double bisect(F f, double lo, double hi) {
  double flo = f(lo);
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    const double fm = f(mid);
    if ((fm > 0) == (flo > 0)) {
      lo = mid;
      flo = fm;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}
}  // namespace

void check_restitution(double e, const std::string& where) {
  if (!(e > 0.0 && e <= 1.0))
    throw InputError(where + ": coefficient of restitution must be in (0, 1], got " +
                     std::to_string(e));
}

double lve_damping_ratio(double e) {
  const double l = std::log(e);
  return -l / std::sqrt(kPi * kPi + l * l);
}

double mlve_restitution(double xi) {
  if (xi <= 0.0) return 1.0;
  // Near critical damping both branches tend to theta / sin(theta) -> 1 + (1 - xi) / 3.
  if (std::fabs(xi - 1.0) < 1e-8) return std::exp(-xi * (1.0 + (1.0 - xi) / 3.0));
  // (1 - xi)(1 + xi) avoids the cancellation of 1 - xi^2 near xi = 1.
  if (xi < 1.0) return std::exp(-xi * std::acos(xi) / std::sqrt((1.0 - xi) * (1.0 + xi)));
  return std::exp(-xi * std::acosh(xi) / std::sqrt((xi - 1.0) * (xi + 1.0)));
}

double mlve_damping_ratio_exact(double e) {
  if (e >= 1.0) return 0.0;
  // e(xi) decreases monotonically from 1 (xi = 0) towards 0 (xi -> infinity).
  double hi = 1.0;
  while (mlve_restitution(hi) > e) hi *= 2.0;
  return bisect([e](double xi) { return mlve_restitution(xi) - e; }, 0.0, hi);
}

double mlve_damping_ratio_published(double e) {
  return (1.0 - e * e) / (e * (e * (kPi - 2.0) + 2.0));
}

double nlve_damping_ratio(double e) {
  return 9.0 * std::sqrt(5.0) / 2.0 * (1.0 - e * e) / (e * (e * (9.0 * kPi - 16.0) + 16.0));
}

double hunt_crossley_factor(double e) {
  if (e >= 1.0) return 0.0;
  // g(a) = ln((1+a)/(1-e a)) - (1+e) a: g(0) = 0, g'(0) = 0, g''(0) = e^2 - 1 < 0, so g < 0
  // just above 0 and g -> +infinity as a -> 1/e. The root is bracketed in (0, 1/e).
  // Written with log1p for accuracy at small a.
  auto g = [e](double a) { return std::log1p(a) - std::log1p(-e * a) - (1.0 + e) * a; };
  // Move lo to where g is safely negative (small a: g ~ (e^2 - 1) a^2 / 2).
  double lo = 1e-6 * (1.0 - e);
  while (g(lo) >= 0.0 && lo > 1e-300) lo *= 0.5;
  // Near 1/e the logarithm diverges; for very small e the root sits within round-off of 1/e.
  double eps = 1e-3;
  while (g((1.0 - eps) / e) < 0.0 && eps > 1e-15) eps *= 0.1;
  return bisect(g, lo, (1.0 - eps) / e);
}

}  // namespace pound

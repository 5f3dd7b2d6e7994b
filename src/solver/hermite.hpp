#pragma once
// Cubic Hermite interpolation over one step of a quantity known with its time derivative at
// both ends: the row solver's event functions and peaks between steps (fourth-order accurate,
// like the integrator's own error).
#include <algorithm>
#include <cmath>
#include <utility>

namespace pound {

// Cubic Hermite interpolant on theta in [0, 1] of a quantity with values g0, g1 and time
// derivatives d0, d1 over a step of length h.
struct Hermite {
  double g0, g1, m0, m1;  // m = h * derivative
  double at(double th) const {
    const double t2 = th * th, t3 = t2 * th;
    return (2 * t3 - 3 * t2 + 1) * g0 + (t3 - 2 * t2 + th) * m0 + (-2 * t3 + 3 * t2) * g1 +
           (t3 - t2) * m1;
  }
  // Interior stationary points in (0, 1): roots of the derivative (a quadratic).
  int stationary(double out[2]) const {
    const double a = 6 * g0 + 3 * m0 - 6 * g1 + 3 * m1;
    const double b = -6 * g0 - 4 * m0 + 6 * g1 - 2 * m1;
    const double c = m0;
    int n = 0;
    auto push = [&](double r) {
      if (r > 0.0 && r < 1.0) out[n++] = r;
    };
    if (std::fabs(a) < 1e-300) {
      if (std::fabs(b) > 1e-300) push(-c / b);
      return n;
    }
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return 0;
    const double sq = std::sqrt(disc);
    const double q = -0.5 * (b + (b >= 0 ? sq : -sq));
    push(q / a);
    if (q != 0.0) push(c / q);
    if (n == 2 && out[0] > out[1]) std::swap(out[0], out[1]);
    return n;
  }
  double max_over_step() const {
    double s[2], m = std::max(g0, g1);
    const int n = stationary(s);
    for (int i = 0; i < n; ++i) m = std::max(m, at(s[i]));
    return m;
  }
  double min_over_step() const {
    double s[2], m = std::min(g0, g1);
    const int n = stationary(s);
    for (int i = 0; i < n; ++i) m = std::min(m, at(s[i]));
    return m;
  }
  double absmax_over_step() const {
    double s[2], m = std::max(std::fabs(g0), std::fabs(g1));
    const int n = stationary(s);
    for (int i = 0; i < n; ++i) m = std::max(m, std::fabs(at(s[i])));
    return m;
  }
  // Upper bound of |value| over the step: the basis functions of g0 and g1 are >= 0 and sum to
  // 1, those of m0 and m1, theta (1 - theta)^2 and theta^2 (theta - 1), are at most 4/27 in
  // magnitude. The factor 1 + 1e-12 covers the round-off of at().
  double absmax_bound() const {
    return (std::max(std::fabs(g0), std::fabs(g1)) + 4.0 / 27.0 * (std::fabs(m0) + std::fabs(m1))) *
           (1.0 + 1e-12);
  }
  // max(peak, absmax_over_step()), skipping the stationary points when the bound cannot
  // raise the peak.
  double raise_peak(double peak) const {
    return absmax_bound() <= peak ? peak : std::max(peak, absmax_over_step());
  }
};

}  // namespace pound

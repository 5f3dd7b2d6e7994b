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
  // Upper bound of the value over the step, for a quick test before max_over_step(): the basis
  // functions of g0 and g1 are >= 0 and sum to 1, those of m0 and m1, theta (1 - theta)^2 and
  // theta^2 (theta - 1), are at most 4/27 in magnitude.
  double upper_bound() const {
    return std::max(g0, g1) + 4.0 / 27.0 * (std::fabs(m0) + std::fabs(m1));
  }
  // Upper bound of |value| over the step (the same basis bounds). The factor 1 + 1e-12 covers
  // the round-off of at().
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

// Quintic Hermite interpolation over one step of a quantity known with its first and second
// time derivatives at both ends (sixth-order accurate; the standard quintic Hermite basis):
// the peaks of displacements and drifts between steps, where the accelerations are known.
struct QuinticHermite {
  double g0, g1, m0, m1, c0, c1;  // m = h * first derivative, c = h^2 * second derivative
  double at(double t) const {
    const double t2 = t * t, t3 = t2 * t, t4 = t3 * t, t5 = t4 * t;
    return g0 * (1 - 10 * t3 + 15 * t4 - 6 * t5) + m0 * (t - 6 * t3 + 8 * t4 - 3 * t5) +
           c0 * 0.5 * (t2 - 3 * t3 + 3 * t4 - t5) + c1 * 0.5 * (t3 - 2 * t4 + t5) +
           m1 * (-4 * t3 + 7 * t4 - 3 * t5) + g1 * (10 * t3 - 15 * t4 + 6 * t5);
  }
  double slope(double t) const {  // d/dt of at()
    const double t2 = t * t, t3 = t2 * t, t4 = t3 * t;
    return g0 * (-30 * t2 + 60 * t3 - 30 * t4) + m0 * (1 - 18 * t2 + 32 * t3 - 15 * t4) +
           c0 * 0.5 * (2 * t - 9 * t2 + 12 * t3 - 5 * t4) + c1 * 0.5 * (3 * t2 - 8 * t3 + 5 * t4) +
           m1 * (-12 * t2 + 28 * t3 - 15 * t4) + g1 * (30 * t2 - 60 * t3 + 30 * t4);
  }
  double curvature(double t) const {  // d2/dt2 of at()
    const double t2 = t * t, t3 = t2 * t;
    return g0 * (-60 * t + 180 * t2 - 120 * t3) + m0 * (-36 * t + 96 * t2 - 60 * t3) +
           c0 * 0.5 * (2 - 18 * t + 36 * t2 - 20 * t3) + c1 * 0.5 * (6 * t - 24 * t2 + 20 * t3) +
           m1 * (-24 * t + 84 * t2 - 60 * t3) + g1 * (60 * t - 180 * t2 + 120 * t3);
  }
  // The cubic of the same values and slopes.
  Hermite cubic() const { return {g0, g1, m0, m1}; }
  // Upper bound of |value| over the step: the basis functions of g0 and g1 are >= 0 and sum to
  // 1; those of m0 and m1 are at most 16/81 in magnitude, those of c0 and c1 at most 54/3125.
  double absmax_bound() const { return absmax_bound(g0, g1, m0, m1, c0, c1); }
  // The same from the six coefficients (row_solver's peak_bounds: every floor in one pass).
  static double absmax_bound(double g0, double g1, double m0, double m1, double c0, double c1) {
    return (std::max(std::fabs(g0), std::fabs(g1)) + 16.0 / 81.0 * (std::fabs(m0) + std::fabs(m1)) +
            54.0 / 3125.0 * (std::fabs(c0) + std::fabs(c1))) *
           (1.0 + 1e-12);
  }
  // Upper bound of the value over the step (the basis bounds of absmax_bound(), with g0 and g1
  // signed).
  double upper_bound() const {
    return std::max(g0, g1) + 16.0 / 81.0 * (std::fabs(m0) + std::fabs(m1)) +
           54.0 / 3125.0 * (std::fabs(c0) + std::fabs(c1));
  }
  // A stationary point of the cubic at t refined by Newton's method on the quintic's slope (three
  // steps, kept inside (0, 1)).
  double refined(double t) const {
    for (int it = 0; it < 3; ++it) {
      const double d2 = curvature(t);
      if (d2 == 0.0) break;
      const double tn = t - slope(t) / d2;
      if (!(tn > 0.0 && tn < 1.0)) break;
      t = tn;
    }
    return t;
  }
  // The largest value over the step: the ends, the cubic's stationary points refined by
  // Newton's method on the quintic's slope (as refine_peak) and, for a maximum the cubic does not
  // show, the values at theta = k / 8.
  double max_over_step() const {
    double m = std::max(g0, g1);
    double st[2];
    const int n = cubic().stationary(st);
    for (int k = 0; k < n; ++k) {
      const double t = refined(st[k]);
      m = std::max(m, at(t));
    }
    for (int k = 1; k < 8; ++k) m = std::max(m, at(k / 8.0));
    return m;
  }
  // max(peak, |value| over the step): the interior extrema are the cubic's stationary points
  // refined by Newton's method on the quintic's slope (three steps, kept inside (0, 1)); skipped
  // when the bound cannot raise the peak.
  double raise_peak(double peak) const { return absmax_bound() <= peak ? peak : refine_peak(peak); }
  __attribute__((noinline)) double refine_peak(double peak) const {
    const Hermite c = cubic();
    double m = std::max({peak, std::fabs(g0), std::fabs(g1)});
    double st[2];
    const int n = c.stationary(st);
    for (int k = 0; k < n; ++k) {
      const double t = refined(st[k]);
      m = std::max(m, std::fabs(at(t)));
    }
    return m;
  }
};

}  // namespace pound

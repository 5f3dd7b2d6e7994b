// The Hermite interpolants of the row solver's steps (solver/hermite.hpp): exactness on
// polynomials of their degree, the order of their peaks, and their bounds.
#include "solver/hermite.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pound {
namespace {

TEST(QuinticHermite, ReproducesAQuinticAndBoundsIt) {
  // p(s) = 1 - 2s + 0.5 s^2 + 3 s^3 - 4 s^4 + 1.5 s^5 on a step of h = 0.2 (s = h t).
  const double h = 0.2;
  auto p = [](double s) {
    return 1 - 2 * s + 0.5 * s * s + 3 * std::pow(s, 3) - 4 * std::pow(s, 4) + 1.5 * std::pow(s, 5);
  };
  auto dp = [](double s) {
    return -2 + s + 9 * s * s - 16 * std::pow(s, 3) + 7.5 * std::pow(s, 4);
  };
  auto d2p = [](double s) { return 1 + 18 * s - 48 * s * s + 30 * std::pow(s, 3); };
  const QuinticHermite q{p(0), p(h), h * dp(0), h * dp(h), h * h * d2p(0), h * h * d2p(h)};
  double maxabs = 0.0;
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0;
    EXPECT_NEAR(q.at(t), p(h * t), 1e-14);
    EXPECT_NEAR(q.slope(t), h * dp(h * t), 1e-13);
    EXPECT_NEAR(q.curvature(t), h * h * d2p(h * t), 1e-12);
    maxabs = std::max(maxabs, std::fabs(q.at(t)));
  }
  EXPECT_GE(q.absmax_bound(), maxabs);
}

TEST(QuinticHermite, PeakOfASinusoidBetweenStepsIsSixthOrder) {
  // sin(w s) sampled every T / 20 (the row solver's step cap), the peak inside a step: the
  // quintic's peak is within (w h)^6 / 46080 = 2e-8 of 1 (the cubic's within 1e-5), and the
  // error falls 64 times when the step halves.
  const double w = 2 * M_PI;
  double err[2];
  for (int k = 0; k < 2; ++k) {
    const double h = 1.0 / (20 << k);
    const double s0 = 0.25 - 0.37 * h;  // the peak at s = 1/4 lies inside the step
    const QuinticHermite q{std::sin(w * s0),
                           std::sin(w * (s0 + h)),
                           h * w * std::cos(w * s0),
                           h * w * std::cos(w * (s0 + h)),
                           -h * h * w * w * std::sin(w * s0),
                           -h * h * w * w * std::sin(w * (s0 + h))};
    err[k] = 1.0 - q.raise_peak(0.0);
    if (k == 0) {
      EXPECT_LT(std::fabs(err[0]), 2e-8);
      EXPECT_GT(std::fabs(1.0 - q.cubic().raise_peak(0.0)), 100 * std::fabs(err[0]));
    }
  }
  EXPECT_GT(std::log2(std::fabs(err[0] / err[1])), 5.5) << err[0] << " " << err[1];
}

}  // namespace
}  // namespace pound

#include "contact/restitution.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"

namespace pound {
namespace {

TEST(Restitution, LveDampingRatioReproducesLogDecrementOfHalfCycle) {
  // A linear oscillator released at delta = 0 with rate v0 returns to delta = 0 after half a
  // damped period with rate -v0 exp(-xi pi / sqrt(1 - xi^2)).
  for (double e : {0.1, 0.4, 0.65, 0.9}) {
    const double xi = lve_damping_ratio(e);
    EXPECT_NEAR(std::exp(-xi * M_PI / std::sqrt(1 - xi * xi)), e, 1e-14);
  }
  EXPECT_NEAR(lve_damping_ratio(0.4), 0.27999,
              1e-4);  // hand value: -ln 0.4 / sqrt(pi^2 + ln^2 0.4)
}

TEST(Restitution, HuntCrossleyFactorSolvesItsDefiningEquation) {
  for (double e : {0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    const double a = hunt_crossley_factor(e);
    EXPECT_GT(a, 0.0);
    EXPECT_LT(a, 1.0 / e);
    EXPECT_NEAR((1 + e) * a, std::log((1 + a) / (1 - e * a)), 1e-12 * (1 + a));
  }
  // For small e the root lies within round-off of 1/e (1 - e a ~ exp(-(1 + e)/e)): check it
  // brackets a sign change instead of the ill-conditioned residual.
  const double e = 0.05, a = hunt_crossley_factor(e);
  auto g = [e](double x) { return std::log1p(x) - std::log1p(-e * x) - (1 + e) * x; };
  EXPECT_LT(g(a * (1 - 1e-9)), 0.0);
  EXPECT_GT(g(std::min(a * (1 + 1e-9), (1 - 1e-16) / e)), 0.0);
  EXPECT_EQ(hunt_crossley_factor(1.0), 0.0);
  // Near e = 1 the small-damping expansion gives a ~ 3 (1 - e) / 2 (Hunt & Crossley).
  EXPECT_NEAR(hunt_crossley_factor(0.999) / (1.5 * 0.001), 1.0, 2e-3);
}

TEST(Restitution, MlveExactInversionRoundTripsAndPublishedFormulaIsClose) {
  for (double e : {0.1, 0.3, 1.0 / M_E, 0.5, 0.8, 0.95}) {
    const double xi = mlve_damping_ratio_exact(e);
    EXPECT_NEAR(mlve_restitution(xi), e, 1e-12);
    const double e_pub = mlve_restitution(mlve_damping_ratio_published(e));
    EXPECT_NEAR(e_pub / e, 1.0, 0.04) << "e = " << e;
  }
  EXPECT_NEAR(mlve_damping_ratio_exact(std::exp(-1.0)), 1.0, 1e-9);  // critical damping
}

TEST(Restitution, RejectsValuesOutsideUnitInterval) {
  EXPECT_THROW(check_restitution(0.0, "e"), InputError);
  EXPECT_THROW(check_restitution(1.2, "e"), InputError);
  EXPECT_THROW(check_restitution(std::nan(""), "e"), InputError);
  EXPECT_NO_THROW(check_restitution(1.0, "e"));
}

}  // namespace
}  // namespace pound

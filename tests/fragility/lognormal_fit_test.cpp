// The maximum-likelihood lognormal fit (Baker 2015): known theta and beta recovered from
// binomial data drawn from a lognormal CDF, the per-sample (Bernoulli) fit, the cases without a
// finite estimate, and the tails of ln Phi.
#include "fragility/lognormal_fit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sampling/counter_rng.hpp"
#include "sampling/normal.hpp"

namespace pound {
namespace {

constexpr double kTheta = 2.5;  // m/s^2
constexpr double kBeta = 0.4;

double p_true(double x) {
  return normal_cdf(std::log(x / kTheta) / kBeta);
}

// n analyses at each of 10 levels 0.5..5 m/s^2, z ~ Binomial(n, p(x)) with a fixed seed.
std::vector<Observation> synthetic_stripes(long n, std::uint64_t seed) {
  const CounterRng rng(seed, 11);
  std::vector<Observation> obs;
  for (int j = 0; j < 10; ++j) {
    Observation o{0.5 * (j + 1), n, 0};
    for (long i = 0; i < n; ++i)
      o.z += rng.uniform(std::uint64_t(j), std::uint64_t(i)) < p_true(o.im);
    obs.push_back(o);
  }
  return obs;
}

TEST(LognormalFit, RecoversThetaAndBetaFromExactFractions) {
  // z = n p(x) rounded, n = 10^7: the likelihood maximum sits on the generating curve to
  // within the rounding of the counts (relative error < 1e-5).
  std::vector<Observation> obs;
  for (int j = 0; j < 8; ++j) {
    const double x = 0.6 * (j + 1);
    obs.push_back({x, 10000000, std::lround(1e7 * p_true(x))});
  }
  const LognormalFit f = fit_lognormal(obs);
  ASSERT_TRUE(f.finite()) << to_string(f.status);
  EXPECT_NEAR(f.theta, kTheta, 1e-5 * kTheta);
  EXPECT_NEAR(f.beta, kBeta, 1e-5 * kBeta);
  EXPECT_LT(f.iterations, 30);
}

TEST(LognormalFit, RecoversThetaAndBetaFromBinomialDraws) {
  // 10 stripes x 200 analyses. The estimate must lie within 3 asymptotic standard errors
  // (about 0.03 in ln theta and 0.03 in beta here) of the truth, for 5 seeds.
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const LognormalFit f = fit_lognormal(synthetic_stripes(200, seed));
    ASSERT_TRUE(f.finite());
    EXPECT_LT(std::sqrt(f.var_ln_theta), 0.03);
    EXPECT_LT(std::sqrt(f.var_beta), 0.03);
    EXPECT_NEAR(std::log(f.theta), std::log(kTheta), 3 * std::sqrt(f.var_ln_theta)) << seed;
    EXPECT_NEAR(f.beta, kBeta, 3 * std::sqrt(f.var_beta)) << seed;
  }
}

TEST(LognormalFit, PerSampleBernoulliFitRecoversContinuousIntensities) {
  // 3000 analyses with lognormal intensities (median 2.5, dispersion 0.6), one outcome each.
  const CounterRng rng(3, 5);
  std::vector<Observation> obs;
  for (std::uint64_t i = 0; i < 3000; ++i) {
    const double x = kTheta * std::exp(0.6 * normal_quantile(rng.uniform(i, 0)));
    obs.push_back({x, 1, rng.uniform(i, 1) < p_true(x) ? 1L : 0L});
  }
  const LognormalFit f = fit_lognormal(obs);
  ASSERT_TRUE(f.finite());
  EXPECT_NEAR(std::log(f.theta), std::log(kTheta), 3 * std::sqrt(f.var_ln_theta));
  EXPECT_NEAR(f.beta, kBeta, 3 * std::sqrt(f.var_beta));
  EXPECT_LT(std::sqrt(f.var_beta), 0.05);
}

TEST(LognormalFit, AllOrNoneExceedingHasNoFiniteEstimate) {
  std::vector<Observation> none = {{1, 20, 0}, {2, 20, 0}, {3, 20, 0}};
  std::vector<Observation> all = {{1, 20, 20}, {2, 20, 20}, {3, 20, 20}};
  EXPECT_EQ(fit_lognormal(none).status, FitStatus::none_exceed);
  EXPECT_EQ(fit_lognormal(all).status, FitStatus::all_exceed);
  EXPECT_FALSE(fit_lognormal(all).finite());
  EXPECT_TRUE(std::isnan(fit_lognormal(none).probability(2.0)));
  EXPECT_EQ(fit_lognormal({}).status, FitStatus::no_data);
  // What the data do say: theta above 3, or below 1.
  EXPECT_EQ(fit_lognormal(none).theta_lo, 3.0);
  EXPECT_TRUE(std::isinf(fit_lognormal(none).theta_hi));
  EXPECT_EQ(fit_lognormal(all).theta_lo, 0.0);
  EXPECT_EQ(fit_lognormal(all).theta_hi, 1.0);
}

TEST(LognormalFit, SeparatedAndUnidentifiableCasesHaveNoFiniteEstimate) {
  // Complete separation: none exceed at 1 and 2, all at 3 -> beta -> 0.
  // Theta lies between 2 and 3: there the likelihood tends to 1 as beta -> 0.
  const LognormalFit sep = fit_lognormal({{1, 20, 0}, {2, 20, 0}, {3, 20, 20}});
  EXPECT_EQ(sep.status, FitStatus::separated);
  EXPECT_NEAR(sep.theta_lo, 2.0, 1e-15);
  EXPECT_NEAR(sep.theta_hi, 3.0, 1e-15);
  // Quasi-complete: one stripe with both outcomes, the others all or none; theta between the
  // stripes either side, and only below when nothing is all-exceeding.
  const LognormalFit quasi = fit_lognormal({{1, 20, 0}, {2, 20, 7}, {3, 20, 20}});
  EXPECT_EQ(quasi.status, FitStatus::separated);
  EXPECT_EQ(quasi.theta_lo, 1.0);
  EXPECT_EQ(quasi.theta_hi, 3.0);
  const LognormalFit top = fit_lognormal({{1, 20, 0}, {2, 20, 0}, {3, 20, 2}});
  EXPECT_EQ(top.status, FitStatus::separated);
  EXPECT_EQ(top.theta_lo, 2.0);
  EXPECT_TRUE(std::isinf(top.theta_hi));
  // One intensity only.
  EXPECT_EQ(fit_lognormal({{2, 20, 7}}).status, FitStatus::single_intensity);
  // Falling with intensity.
  EXPECT_EQ(fit_lognormal({{1, 20, 15}, {2, 20, 10}, {3, 20, 4}}).status,
            FitStatus::not_increasing);
  // Overlap at two stripes: a finite estimate.
  EXPECT_TRUE(fit_lognormal({{1, 20, 0}, {2, 20, 7}, {3, 20, 18}}).finite());
}

TEST(LognormalFit, LogPhiAndMillsRatioInTheTails) {
  // ln Phi(-40) = -804.608442013754 (series to 1e-13); continuity at the switch x = -30.
  EXPECT_NEAR(log_normal_cdf(-40.0), -804.6084420137538, 1e-9);
  EXPECT_NEAR(log_normal_cdf(-30.0 - 1e-9), log_normal_cdf(-30.0 + 1e-9), 1e-7);
  EXPECT_NEAR(normal_mills(-30.0 - 1e-9), normal_mills(-30.0 + 1e-9), 1e-7);
  EXPECT_NEAR(log_normal_cdf(0.0), std::log(0.5), 1e-15);
  EXPECT_NEAR(log_normal_cdf(9.0), -1.1285884059538e-19, 1e-30);
  EXPECT_NEAR(normal_mills(0.0), 2.0 / std::sqrt(2.0 * M_PI), 1e-15);
  // Far-tail counts do not stop the fit: an analysis at 100 theta that does not exceed.
  const LognormalFit f = fit_lognormal({{1, 50, 5}, {2, 50, 25}, {4, 50, 45}, {200, 1, 0}});
  EXPECT_TRUE(std::isfinite(f.loglik));
}

}  // namespace
}  // namespace pound

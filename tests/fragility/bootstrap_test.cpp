// Bootstrap bands (resampling within stripes) against the asymptotic band from the inverse
// Fisher information on a large synthetic data set, and determinism of the draws.
#include "fragility/bootstrap.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sampling/counter_rng.hpp"
#include "sampling/normal.hpp"

namespace pound {
namespace {

// 10 stripes 0.5..5 m/s^2 with n analyses each; outcome ~ Bernoulli(Phi(ln(x/2.5)/0.4)).
void synthetic(long n, ExceedanceDesign* d, std::vector<char>* z) {
  const CounterRng rng(42, 7);
  for (int j = 0; j < 10; ++j) d->levels.push_back(0.5 * (j + 1));
  for (int j = 0; j < 10; ++j)
    for (long i = 0; i < n; ++i) {
      d->im.push_back(d->levels[std::size_t(j)]);
      d->stripe.push_back(j);
      const double p = normal_cdf(std::log(d->levels[std::size_t(j)] / 2.5) / 0.4);
      z->push_back(rng.uniform(std::uint64_t(j), std::uint64_t(i)) < p);
    }
}

TEST(Bootstrap, AnalysesLeftOutAreNotCounted) {
  // Two stripes of three analyses; one of each is left out of the curve (no finite EDP).
  ExceedanceDesign d;
  d.levels = {1.0, 2.0};
  d.im = {1, 1, 1, 2, 2, 2};
  d.stripe = {0, 0, 0, 1, 1, 1};
  const std::vector<char> z = {kLeftOut, 0, 1, 1, kLeftOut, 1};
  const auto o = observations(d, z);
  ASSERT_EQ(o.size(), 2u);
  EXPECT_EQ(o[0].n, 2);
  EXPECT_EQ(o[0].z, 1);
  EXPECT_EQ(o[1].n, 2);
  EXPECT_EQ(o[1].z, 2);
  // A resample drawing a left-out analysis twice counts neither draw.
  const auto r = observations(d, z, {0, 0, 2, 4, 4, 5});
  EXPECT_EQ(r[0].n, 1);
  EXPECT_EQ(r[1].n, 1);
  // Continuous intensities: one observation per analysis that is not left out.
  ExceedanceDesign c;
  c.im = {1.0, 1.5, 2.0, 3.0};
  c.stripe = {-1, -1, -1, -1};
  const auto oc = observations(c, {0, kLeftOut, 1, 1});
  ASSERT_EQ(oc.size(), 3u);
  EXPECT_EQ(oc[1].im, 2.0);
}

TEST(Bootstrap, NinetyPercentBandAgreesWithAsymptoticBand) {
  // 4000 analyses, 1000 replicates: the percentile band of ln theta and of beta must have the
  // width of the asymptotic band 2 z95 sd within 15 % (Monte Carlo error of the 5 % and 95 %
  // quantiles of 1000 replicates is about 5 %), and the same centre within 0.25 of its width.
  ExceedanceDesign d;
  std::vector<char> z;
  synthetic(400, &d, &z);
  const LognormalFit f = fit_lognormal(observations(d, z));
  ASSERT_TRUE(f.finite());
  const auto reps = bootstrap_fits(d, {z}, {1000, 9});
  std::vector<double> lt, b;
  for (const auto& r : reps[0]) {
    lt.push_back(r.finite() ? std::log(r.theta) : NAN);
    b.push_back(r.finite() ? r.beta : NAN);
  }
  const Interval il = percentile_interval(lt, 0.90), ib = percentile_interval(b, 0.90);
  EXPECT_EQ(il.finite, 1000);
  const double z95 = normal_quantile(0.95);
  const double wl = 2 * z95 * std::sqrt(f.var_ln_theta), wb = 2 * z95 * std::sqrt(f.var_beta);
  EXPECT_NEAR((il.hi - il.lo) / wl, 1.0, 0.15);
  EXPECT_NEAR((ib.hi - ib.lo) / wb, 1.0, 0.15);
  EXPECT_NEAR(0.5 * (il.lo + il.hi), std::log(f.theta), 0.25 * wl);
  EXPECT_NEAR(0.5 * (ib.lo + ib.hi), f.beta, 0.25 * wb);
}

TEST(Bootstrap, ResamplesWithinStripesAndIsDeterministic) {
  ExceedanceDesign d;
  std::vector<char> z;
  synthetic(30, &d, &z);
  const auto a = bootstrap_fits(d, {z, z}, {50, 3});
  const auto b = bootstrap_fits(d, {z}, {50, 3});
  ASSERT_EQ(a.size(), 2u);
  for (int r = 0; r < 50; ++r) {
    EXPECT_EQ(a[0][r].theta, b[0][r].theta);  // same seed, same draws
    EXPECT_EQ(a[0][r].theta, a[1][r].theta);  // every curve sees the same analyses
  }
  // Each replicate keeps 30 analyses per stripe.
  const auto obs = observations(d, z, std::vector<std::size_t>(d.im.size(), 0));
  for (const auto& o : obs) EXPECT_EQ(o.n, o.im == 0.5 ? 300 : 0);
}

TEST(Bootstrap, PercentileInterval) {
  std::vector<double> v;
  for (int i = 0; i <= 100; ++i) v.push_back(i);
  v.push_back(NAN);
  const Interval iv = percentile_interval(v, 0.90);
  EXPECT_DOUBLE_EQ(iv.lo, 5.0);
  EXPECT_DOUBLE_EQ(iv.hi, 95.0);
  EXPECT_EQ(iv.finite, 101);
  EXPECT_TRUE(std::isnan(percentile_interval({NAN}, 0.9).lo));
}

}  // namespace
}  // namespace pound

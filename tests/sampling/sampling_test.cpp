#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "core/error.hpp"
#include "sampling/counter_rng.hpp"
#include "sampling/distribution.hpp"
#include "sampling/keyed_permutation.hpp"
#include "sampling/latin_hypercube.hpp"
#include "sampling/normal.hpp"

namespace pound {
namespace {

TEST(Normal, QuantileMatchesTabulatedValuesAndInvertsTheCdf) {
  EXPECT_NEAR(normal_quantile(0.975), 1.959963984540054, 1e-14);
  EXPECT_NEAR(normal_quantile(0.5), 0.0, 1e-15);
  EXPECT_NEAR(normal_quantile(0.001), -3.090232306167814, 1e-13);
  EXPECT_NEAR(normal_quantile(1e-10), -6.361340902404056, 1e-11);
  for (double p : {1e-12, 1e-6, 0.01, 0.3, 0.7, 0.99, 1 - 1e-9})
    EXPECT_NEAR(normal_cdf(normal_quantile(p)) / p, 1.0, 1e-12) << p;
}

TEST(CounterRng, SameKeyAndCounterGiveSameNumberAndStreamsDiffer) {
  const CounterRng a(42, stream_id("e")), b(42, stream_id("e")), c(42, stream_id("k"));
  EXPECT_EQ(a.bits(7, 3), b.bits(7, 3));
  EXPECT_NE(a.bits(7, 3), c.bits(7, 3));
  EXPECT_NE(a.bits(7, 3), a.bits(8, 3));
  // Mean and variance of 1e5 uniforms: 1/2 and 1/12 within 5 standard errors.
  double s = 0, s2 = 0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double u = a.uniform(i);
    ASSERT_GT(u, 0.0);
    ASSERT_LT(u, 1.0);
    s += u;
    s2 += u * u;
  }
  EXPECT_NEAR(s / n, 0.5, 5 * std::sqrt(1.0 / 12 / n));
  EXPECT_NEAR(s2 / n - (s / n) * (s / n), 1.0 / 12, 5 * 0.0745 / std::sqrt(double(n)));
}

TEST(Distribution, QuantilesOfEachForm) {
  EXPECT_DOUBLE_EQ(Distribution::parse("0.05", "k").value(0.3), 0.05);
  EXPECT_DOUBLE_EQ(Distribution::parse("uniform(1, 3)", "k").value(0.25), 1.5);
  EXPECT_NEAR(Distribution::parse("normal(10, 2)", "k").value(0.975), 10 + 2 * 1.959963984540054,
              1e-12);
  EXPECT_NEAR(Distribution::parse("lognormal(50, 0.4)", "k").value(0.5), 50.0, 1e-12);
  EXPECT_NEAR(Distribution::parse("lognormal(50, 0.4)", "k").value(0.975),
              50.0 * std::exp(0.4 * 1.959963984540054), 1e-10);
  // Truncation: the median of normal(0, 1, 0, 10) is Phi^-1(0.75).
  const auto t = Distribution::parse("normal(0, 1, 0, 10)", "k");
  EXPECT_NEAR(t.value(0.5), normal_quantile(0.75), 1e-12);
  EXPECT_GE(t.value(1e-15), 0.0);
  const auto d = Distribution::parse("discrete(lve: 1, sears: 3)", "model");
  EXPECT_EQ(d.label(0.2), "lve");
  EXPECT_EQ(d.label(0.3), "sears");
}

TEST(Distribution, BadTextNamesKeyAndValidForms) {
  for (const char* bad : {"abc", "uniform(1)", "normal(0, -1)", "gauss(1, 2)", "uniform(3, 1)",
                          "lognormal(0, 1)", "discrete(a: -1)", "uniform(1, 2"}) {
    try {
      Distribution::parse(bad, "study.ini:7: key 'sample.gap'");
      FAIL() << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("study.ini:7"), std::string::npos) << e.what();
    }
  }
}

TEST(LatinHypercube, EachStratumIsUsedExactlyOncePerDimension) {
  const std::uint64_t n = 257;
  LatinHypercube lhs(7, n);
  for (std::uint64_t stream : {stream_id("e"), stream_id("gap")}) {
    std::set<std::uint64_t> strata;
    for (std::uint64_t i = 0; i < n; ++i) {
      const double u = lhs.uniform(stream, i);
      strata.insert(static_cast<std::uint64_t>(u * n));
    }
    EXPECT_EQ(strata.size(), n);
  }
  // A fresh object (another rank) gives the same numbers.
  LatinHypercube other(7, n);
  EXPECT_EQ(other.uniform(stream_id("gap"), 100), lhs.uniform(stream_id("gap"), 100));
}

}  // namespace
}  // namespace pound

namespace pound {
namespace {

TEST(KeyedPermutation, IsABijectionForSizesThatAreNotPowersOfTwo) {
  // Issue 13: every index of [0, n) is hit exactly once, for n around powers of two (where the
  // Feistel domain 2^(2w) is 1x to 4x n and the cycle walk is longest or shortest).
  for (std::uint64_t n :
       {1ull, 2ull, 3ull, 5ull, 7ull, 63ull, 64ull, 65ull, 1000ull, 4095ull, 4097ull, 100003ull}) {
    const KeyedPermutation p(2026, stream_id("gap"), n);
    std::vector<char> hit(n, 0);
    for (std::uint64_t i = 0; i < n; ++i) {
      const std::uint64_t j = p(i);
      ASSERT_LT(j, n) << n;
      EXPECT_EQ(hit[j], 0) << "n = " << n << ": " << j << " twice";
      hit[j] = 1;
    }
  }
}

TEST(KeyedPermutation, AnIndexOutsideTheDomainIsRefusedNotWalkedForever) {
  // Cycle walking from i >= n need not come back below n: before this check, pi(815) of a
  // 20-sample permutation never returned (bench_speed's `sample 815` hung).
  const KeyedPermutation p(2026, stream_id("gap"), 20);
  EXPECT_LT(p(19), 20u);
  EXPECT_THROW(p(20), std::out_of_range);
  EXPECT_THROW(p(815), std::out_of_range);
}

TEST(KeyedPermutation, LooksRandomAndDependsOnTheKey) {
  // A permutation of 10,000 indices: the rank correlation of i and pi(i) is that of a random
  // permutation (|rho| < 4 / sqrt(n - 1) = 0.04, four standard errors), it has about one fixed
  // point (Poisson with mean 1: at most 10), and permutations of other keys agree with it about
  // as often.
  const std::uint64_t n = 10000;
  const KeyedPermutation a(1, 11, n), b(2, 11, n), c(1, 12, n);
  double sxy = 0.0, mean = (n - 1) / 2.0, var = 0.0;
  int fixed = 0, same_b = 0, same_c = 0;
  for (std::uint64_t i = 0; i < n; ++i) {
    const double x = double(i) - mean, y = double(a(i)) - mean;
    sxy += x * y;
    var += x * x;
    fixed += a(i) == i;
    same_b += a(i) == b(i);
    same_c += a(i) == c(i);
  }
  EXPECT_LT(std::fabs(sxy / var), 4.0 / std::sqrt(n - 1.0));
  EXPECT_LE(fixed, 10);
  EXPECT_LE(same_b, 10);
  EXPECT_LE(same_c, 10);
}

TEST(LatinHypercube, StrataAreAPermutationForLargeCountsWithoutStoringThem) {
  // 10^9 samples: the object stays small (no permutation is stored) and two samples far apart
  // land in distinct strata; the stratum of a sample is the same on any rank (a fresh object).
  const std::uint64_t n = 1000000000ull;
  LatinHypercube lhs(3, n);
  const std::uint64_t s = stream_id("k_factor");
  std::set<std::uint64_t> seen;
  for (std::uint64_t i = 0; i < 2000; ++i) seen.insert(lhs.stratum(s, i * 499999ull));
  EXPECT_EQ(seen.size(), 2000u);
  LatinHypercube other(3, n);
  EXPECT_EQ(other.stratum(s, 123456789), lhs.stratum(s, 123456789));
  const double u = lhs.uniform(s, 123456789);
  EXPECT_EQ(static_cast<std::uint64_t>(u * double(n)), lhs.stratum(s, 123456789));
}

}  // namespace
}  // namespace pound

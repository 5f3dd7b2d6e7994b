// Spearman and partial rank correlations: exact values for monotone relations, near zero for
// independent data, and the partial one removing a confounder.
#include "fragility/rank_correlation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sampling/counter_rng.hpp"

namespace pound {
namespace {

TEST(RankCorrelation, RanksShareTies) {
  const auto r = ranks({3.0, 1.0, 3.0, 2.0});
  EXPECT_EQ(r, (std::vector<double>{3.5, 1.0, 3.5, 2.0}));
}

TEST(RankCorrelation, MonotoneRelationIsOneIndependentNearZero) {
  const CounterRng rng(5, 1);
  std::vector<double> x, y, u;
  for (std::uint64_t i = 0; i < 1000; ++i) {
    x.push_back(rng.uniform(i, 0));
    u.push_back(rng.uniform(i, 1));
    y.push_back(std::exp(5 * x.back()));  // monotone, far from linear
  }
  EXPECT_DOUBLE_EQ(spearman(x, y), 1.0);
  EXPECT_LT(pearson(x, y), 0.9);
  std::vector<double> neg;
  for (double v : x) neg.push_back(-v * v * v);
  EXPECT_DOUBLE_EQ(spearman(x, neg), -1.0);
  // Independent: standard error 1/sqrt(n - 1) = 0.032; allow 3 of them.
  EXPECT_LT(std::abs(spearman(x, u)), 0.095);
  EXPECT_TRUE(std::isnan(spearman(x, std::vector<double>(1000, 2.0))));
}

TEST(RankCorrelation, PartialRankCorrelationRemovesTheOtherParameters) {
  // y = x1 + 0.1 noise; x2 = x1 + small noise is correlated with y only through x1; x3 is
  // independent. Spearman(x2, y) is high, PRCC(x2 | x1, x3) near 0, PRCC(x1) near 1.
  const CounterRng rng(8, 2);
  std::vector<double> x1, x2, x3, y;
  for (std::uint64_t i = 0; i < 2000; ++i) {
    x1.push_back(rng.uniform(i, 0));
    x2.push_back(x1.back() + 0.2 * rng.uniform(i, 1));
    x3.push_back(rng.uniform(i, 2));
    y.push_back(std::exp(x1.back() + 0.1 * rng.uniform(i, 3)));
  }
  const std::vector<std::vector<double>> cols = {x1, x2, x3};
  EXPECT_GT(spearman(x2, y), 0.9);
  EXPECT_GT(partial_rank_correlation(cols, y, 0), 0.8);  // 0.89 with this seed
  EXPECT_LT(std::abs(partial_rank_correlation(cols, y, 1)), 0.1);
  EXPECT_LT(std::abs(partial_rank_correlation(cols, y, 2)), 0.07);  // 3 / sqrt(2000)
  // With no other column, PRCC is Spearman.
  EXPECT_NEAR(partial_rank_correlation({x3}, y, 0), spearman(x3, y), 1e-12);
}

}  // namespace
}  // namespace pound

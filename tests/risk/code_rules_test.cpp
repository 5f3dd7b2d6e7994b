// The code rules and Der Kiureghian's (1981) correlation coefficient.
#include "risk/code_rules.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pound {
namespace {

TEST(CodeRules, CorrelationCoefficientOfDerKiureghian) {
  // Equal periods: the responses are fully correlated.
  EXPECT_NEAR(cqc_correlation(0.5, 0.05, 0.5, 0.05), 1.0, 1e-15);
  // Equal periods, unequal damping: 2 sqrt(xi_a xi_b) / (xi_a + xi_b).
  EXPECT_NEAR(cqc_correlation(0.5, 0.02, 0.5, 0.08), 0.8, 1e-15);
  // Equal damping: the general form reduces to 8 xi^2 (1 + r) r^1.5 / ((1 - r^2)^2 +
  // 4 xi^2 r (1 + r)^2), symmetric in the two periods.
  for (double xi : {0.02, 0.05, 0.1})
    for (double r : {0.3, 0.55, 0.8, 0.95}) {
      const double want = 8 * xi * xi * (1 + r) * std::pow(r, 1.5) /
                          (std::pow(1 - r * r, 2) + 4 * xi * xi * r * std::pow(1 + r, 2));
      EXPECT_NEAR(cqc_correlation(1.0, xi, 1.0 / r, xi), want, 1e-14) << xi << " " << r;
      EXPECT_NEAR(cqc_correlation(1.0 / r, xi, 1.0, xi), want, 1e-14) << "symmetric";
    }
  // The chapter 8 pair (T1 0.53 s and 0.29 s, 5 %): r = 0.547, rho = 0.0249 (evaluated by hand),
  // nearly independent responses, so DDC is close to SRSS.
  EXPECT_NEAR(cqc_correlation(0.29, 0.05, 0.53, 0.05), 0.02485, 1e-5);
}

TEST(CodeRules, AbsSrssAndDoubleDifference) {
  const double a = 0.03, b = 0.04;
  EXPECT_DOUBLE_EQ(separation_gap(SeparationRule::abs, a, b, 0.3), 0.07);
  EXPECT_DOUBLE_EQ(separation_gap(SeparationRule::srss, a, b, 0.3), 0.05);
  // DDC: SRSS for independent responses, |a - b| for fully correlated ones, the absolute sum
  // for opposite ones; between SRSS and |a - b| in between.
  EXPECT_DOUBLE_EQ(separation_gap(SeparationRule::ddc, a, b, 0.0), 0.05);
  EXPECT_NEAR(separation_gap(SeparationRule::ddc, a, b, 1.0), 0.01, 1e-15);
  EXPECT_NEAR(separation_gap(SeparationRule::ddc, a, b, -1.0), 0.07, 1e-15);
  const double g = separation_gap(SeparationRule::ddc, a, b, 0.5);
  EXPECT_NEAR(g, std::sqrt(0.0009 + 0.0016 - 0.0012), 1e-15);
  EXPECT_STREQ(to_string(SeparationRule::ddc), "ddc");
}

// EN 1998-1 4.4.2.7(3): 0.7 x SRSS where the floors coincide, the SRSS gap itself otherwise
// (and where the floors are not known); rho plays no part.
TEST(CodeRules, Ec8IsSrssReducedBySevenTenthsOnlyWhereTheFloorsCoincide) {
  const double a = 0.03, b = 0.04;  // SRSS 0.05
  EXPECT_NEAR(separation_gap(SeparationRule::ec8, a, b, 0.3, Ec8Case::floors_coincide), 0.035,
              1e-15);
  EXPECT_DOUBLE_EQ(separation_gap(SeparationRule::ec8, a, b, 0.3, Ec8Case::floors_offset), 0.05);
  EXPECT_DOUBLE_EQ(separation_gap(SeparationRule::ec8, a, b, 0.9, Ec8Case::floors_unknown), 0.05);
  EXPECT_DOUBLE_EQ(separation_gap(SeparationRule::ec8, a, b, 0.3), 0.05);  // no case: no cut
  EXPECT_EQ(ec8_factor(Ec8Case::floors_coincide), 0.7);
  EXPECT_EQ(ec8_factor(Ec8Case::floors_offset), 1.0);
  EXPECT_STREQ(to_string(SeparationRule::ec8), "ec8");
  EXPECT_STREQ(to_string(Ec8Case::floors_coincide), "floors_coincide");
  EXPECT_STREQ(to_string(Ec8Case::floors_offset), "floors_offset");
  EXPECT_STREQ(describe(Ec8Case::floors_coincide), "floors coincide: 0.7 x SRSS");
  EXPECT_STREQ(describe(Ec8Case::floors_offset), "floors do not coincide: SRSS");
}

}  // namespace
}  // namespace pound

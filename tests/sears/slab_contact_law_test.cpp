// The Sears contact law with the struck columns in series (issue 36; sears/slab_contact_law.hpp):
// the end-of-step force of a flat law is that of k_eff = k k_col / (k + k_col), and a Hertz law's
// satisfies delta_c + F / k_col + S F = delta_pred with F = k delta_c^1.5.
#include "sears/slab_contact_law.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pound::sears {
namespace {

TEST(SlabContactLaw, AFlatLawInSeriesWithAColumnIsTheSeriesStiffness) {
  SlabContactLaw law;
  law.kind = ContactKind::flat;
  law.stiffness = 1.0e9;  // [N/m]
  const double k_col = 2.5e8, S = 3e-10, dp = 2e-3;
  law.series_compliance_m_per_N = 1.0 / k_col;
  const double k_eff = 1.0e9 * k_col / (1.0e9 + k_col);
  // F = k_eff (dp - S F)  =>  F = k_eff dp / (1 + k_eff S).
  EXPECT_NEAR(law.solve_implicit(dp, S), k_eff * dp / (1.0 + k_eff * S), 1e-12 * k_eff * dp);
  // The lumped duration pi sqrt(m / k_eff).
  EXPECT_NEAR(law.lumped_duration(4e4, 1.0), M_PI * std::sqrt(4e4 / k_eff), 1e-12);
  EXPECT_DOUBLE_EQ(law.solve_implicit(-1e-3, S), 0.0);
}

TEST(SlabContactLaw, AHertzLawInSeriesSolvesTheSeriesRoot) {
  SlabContactLaw law;
  law.kind = ContactKind::hertz;
  law.stiffness = 3e9;  // [N/m^1.5]
  const double k_col = 4e7, S = 1e-9;
  law.series_compliance_m_per_N = 1.0 / k_col;
  for (double dp : {1e-6, 1e-4, 3e-3}) {
    const double F = law.solve_implicit(dp, S);
    ASSERT_GT(F, 0.0);
    const double dc = std::cbrt(F / 3e9 * F / 3e9);  // the law's own penetration (F / k)^(2/3)
    EXPECT_NEAR(dc + F / k_col + S * F, dp, 1e-12 * dp) << dp;
  }
  // Without the column the same law is stiffer.
  SlabContactLaw bare = law;
  bare.series_compliance_m_per_N = 0.0;
  EXPECT_GT(bare.solve_implicit(1e-3, S), law.solve_implicit(1e-3, S));
  // The cap keeps its meaning: min(F, PF_max).
  law.force_cap_N = 1e4;
  EXPECT_DOUBLE_EQ(law.solve_implicit(3e-3, S), 1e4);
}

}  // namespace
}  // namespace pound::sears

// A contact law in series with the struck columns (issue 36, contact/column_series.hpp).
#include "contact/column_series.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace pound {
namespace {

TEST(ColumnSeries, LinearLawsTakeTheSeriesStiffness) {
  ContactParameters p;
  p.k = 2e9;
  p.e = 1.0;  // lve without dashpot: F = k_eff delta
  p.m1 = p.m2 = 1e5;
  const auto law = column_law(find_contact_model("lve", "test"), p, 6e8);
  EXPECT_NEAR(law->force(1e-3, 0.0, 0.1), 2e9 * 6e8 / 2.6e9 * 1e-3, 1e-6);
  // A slab site (infinite k_col) is the law itself.
  const auto slab =
      column_law(find_contact_model("lve", "test"), p, std::numeric_limits<double>::infinity());
  EXPECT_EQ(slab->force(1e-3, 0.0, 0.1), 2e9 * 1e-3);
}

TEST(ColumnSeries, HertzLawsSplitTheApproachBetweenLawAndColumn) {
  ContactParameters p;
  p.k = 3.21e9;
  p.e = 0.6;
  p.m1 = p.m2 = 5e4;
  const double kc = 8e8, delta = 2e-3;
  const auto law = column_law(find_contact_model("hc-hertz", "test"), p, kc);
  const auto* series = dynamic_cast<const SeriesHertz*>(law.get());
  ASSERT_NE(series, nullptr);
  // At rest (rate 0) F = k dc^1.5 with dc + F / kc = delta: bisection written here.
  double lo = 0.0, hi = delta;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid + p.k * std::pow(mid, 1.5) / kc > delta ? hi : lo) = mid;
  }
  const double F = law->force(delta, 0.0, 0.2);
  EXPECT_NEAR(F, p.k * std::pow(lo, 1.5), 1e-9 * F);
  EXPECT_NEAR(series->law_penetration(delta, 0.0, 0.2) + F / kc, delta, 1e-15);
  // Approaching, the dashpot adds force; the root still splits the approach.
  const double Fa = law->force(delta, 0.15, 0.2);
  EXPECT_GT(Fa, F);
  EXPECT_NEAR(series->law_penetration(delta, 0.15, 0.2) + Fa / kc, delta, 1e-15);
  // A very stiff column leaves the law alone.
  const auto stiff = column_law(find_contact_model("hc-hertz", "test"), p, 1e18);
  const auto bare = find_contact_model("hc-hertz", "test").make(p);
  EXPECT_NEAR(stiff->force(delta, 0.1, 0.2), bare->force(delta, 0.1, 0.2),
              1e-6 * bare->force(delta, 0.1, 0.2));
}

}  // namespace
}  // namespace pound

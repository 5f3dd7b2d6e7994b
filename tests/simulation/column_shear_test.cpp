// The shear on the struck face's columns at slab-to-column sites (issue 36): the demand
// formula worked by hand, the free run's demand against the storey's own peak drift, and the
// ratios to column_shear_strength per site and per building.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/buildings.hpp"
#include "../support/ground_motions.hpp"
#include "simulation/simulate_row.hpp"
#include "structure/building_row.hpp"

namespace pound {
namespace {

TEST(ColumnShear, TheDemandAddsTheImpactLoadToTheSwayShear) {
  ContactSite s;
  s.face_share = 0.5;
  s.shape = 0.5;
  // V_sway = 0.5 x 2e5 = 1e5 N; P = 3e5 N toward +x: below 1e5 + 1.5e5, above 1e5 - 1.5e5.
  EXPECT_DOUBLE_EQ(column_shear_demand(s, 2e5, 3e5), 2.5e5);
  s.struck_sign = -1.0;  // the left building struck: P = -3e5 N; below -5e4, above 2.5e5
  EXPECT_DOUBLE_EQ(column_shear_demand(s, 2e5, 3e5), 2.5e5);
  s.struck_sign = 1.0;
  s.shape = 0.2;  // below 1e5 + 0.8 x 3e5 = 3.4e5, above 1e5 - 0.2 x 3e5 = 4e4
  EXPECT_DOUBLE_EQ(column_shear_demand(s, 2e5, 3e5), 3.4e5);
  EXPECT_DOUBLE_EQ(column_shear_demand(s, -2e5, 0.0), 1e5);  // no contact: |V_sway|
}

TEST(ColumnShear, TheFreeRunCarriesTheSwayShearAndTheRatiosFollowTheStrength) {
  // Left: 2 storeys of 3 m; right: 2 of 3.5 m (sites: L floor 1 on R storey 1, R floor 1 on L
  // storey 2, L floor 2 on R storey 2).
  BuildingRow row = test::offset_pair(0.002, 0.05);
  row.buildings[1].face_column_share = 0.25;
  row.buildings[1].column_shear_strength = {4e5, 3e5};
  ContactSpec spec;
  spec.model = "hc-linear";
  spec.params.k = 1e9;
  spec.params.e = 0.6;
  const RowSimulation s = simulate_row(row, test::sine_pulse(), spec, IntegratorSettings{});
  ASSERT_EQ(s.sites.size(), 3u);
  // Site 0 strikes R's storey 1: without contact its columns carry phi k d of the storey's
  // drift, sampled at the steps' ends, so at most phi k times the storey's peak drift and
  // within 0.1 % of it (steps of at most T/20).
  const double peak_drift = s.free.peak_drift(2);  // R's floor 1: storey 1
  const double sway = 0.25 * 8.0e7 * peak_drift;
  EXPECT_LE(s.sites[0].column_shear_free, sway * (1 + 1e-12));
  EXPECT_GE(s.sites[0].column_shear_free, sway * 0.999);
  EXPECT_GT(s.sites[0].column_shear_pounding, 0.0);
  EXPECT_TRUE(std::isnan(s.sites[1].column_shear_ratio_pounding));  // L has no strength
  EXPECT_DOUBLE_EQ(s.sites[0].column_shear_ratio_free, s.sites[0].column_shear_free / 4e5);
  EXPECT_DOUBLE_EQ(s.sites[2].column_shear_ratio_pounding, s.sites[2].column_shear_pounding / 3e5);
  // The building's ratio: the larger of its struck storeys'.
  EXPECT_DOUBLE_EQ(
      s.column_shear_ratio_pounding[1],
      std::max(s.sites[0].column_shear_ratio_pounding, s.sites[2].column_shear_ratio_pounding));
  EXPECT_TRUE(std::isnan(s.column_shear_ratio_pounding[0]));
  EXPECT_GT(s.sites[0].impacts + s.sites[2].impacts, 0);  // the row pounds
}

}  // namespace
}  // namespace pound

// simulate_row: the free run against the closed-form step response of an SDOF building, the
// pounding run equal to the free one when the gap is never closed, and the homogeneity of a
// linear contact at zero gap.
#include "simulation/simulate_row.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support/buildings.hpp"

namespace pound {
namespace {

Building sdof(double m, double k, double xi) {
  return test::uniform_building(1, m, k, xi, DampingKind::modal);
}

// Two SDOF buildings (10 t) with storey stiffnesses k1, k2 [N/m] and the gap [m] between them.
BuildingRow sdof_pair(double k1, double k2, double gap) {
  BuildingRow row;
  row.buildings = {sdof(1e4, k1, 0.05), sdof(1e4, k2, 0.05)};
  row.gaps = {{gap}};
  return row;
}

ContactSpec contact_of(const std::string& model, double k, double e) {
  ContactSpec c;
  c.model = model;
  c.params.k = k;
  c.params.e = e;
  return c;
}

// A ground acceleration step of a0 [m/s^2] held for `seconds`.
GroundMotion step_motion(double a0, double seconds, double dt = 0.01) {
  GroundMotion g;
  g.name = "step";
  g.dt = dt;
  g.accel.assign(static_cast<std::size_t>(seconds / dt) + 1, a0);
  return g;
}

TEST(SimulateRow, FreeRunMatchesTheClosedFormStepResponse) {
  // m u'' + c u' + k u = -m a0 from rest: the first peak, at t = pi / w_d, is
  // |u| = a0 / w^2 (1 + exp(-pi xi / sqrt(1 - xi^2))) (Chopra, Dynamics of Structures, 4.3).
  const double m = 2.0e4, k = 8.0e6, a0 = 1.5;
  const double w = std::sqrt(k / m);
  for (double xi : {0.0, 0.05}) {
    BuildingRow row;
    row.buildings = {sdof(m, k, xi), sdof(m, 3 * k, xi)};
    row.gaps = {{10.0}};  // never closed
    ContactSpec contact;
    contact.model = "lve";
    contact.params.k = 1e9;
    const RowSimulation s = simulate_row(row, step_motion(a0, 1.0), contact, IntegratorSettings{});
    const double peak = a0 / (w * w) * (1.0 + std::exp(-M_PI * xi / std::sqrt(1.0 - xi * xi)));
    ASSERT_EQ(s.floors.size(), 2u);
    EXPECT_NEAR(s.floors[0].disp_free, peak, 1e-7 * peak) << "xi " << xi;
    EXPECT_NEAR(s.floors[0].peak_drift_ratio_free, peak / 3.0, 1e-7 * peak) << "xi " << xi;
    // Undamped: the absolute acceleration is -w^2 u, so its peak is 2 a0. Accelerations are
    // sampled at step ends (docs/integration.md) and steps are at most T / 20, so the sampled
    // peak lies within 1 - cos(pi / 20) = 1.2 % below it, and never above.
    if (xi == 0.0) {
      EXPECT_LE(s.floors[0].accel_free, 2.0 * a0 * (1.0 + 1e-7));
      EXPECT_GE(s.floors[0].accel_free, 2.0 * a0 * std::cos(M_PI / 20.0));
    }
  }
}

TEST(SimulateRow, AGapNeverClosedLeavesThePoundingRunEqualToTheFreeOne) {
  const BuildingRow row = sdof_pair(4e6, 1e6, 0.5);
  const ContactSpec contact = contact_of("hc-linear", 1e8, 0.6);
  const RowSimulation s = simulate_row(row, step_motion(2.0, 2.0), contact, IntegratorSettings{});
  ASSERT_EQ(s.sites.size(), 1u);
  EXPECT_EQ(s.sites[0].impacts, 0);
  EXPECT_EQ(s.sites[0].peak_force, 0.0);
  EXPECT_LT(s.sites[0].first_contact, 0.0);
  for (const auto& f : s.floors) {
    EXPECT_EQ(f.disp_pounding, f.disp_free);
    EXPECT_EQ(f.disp_amplification, 1.0);
    EXPECT_EQ(f.drift_amplification, 1.0);
    EXPECT_GT(f.disp_free, 0.0);
  }
}

TEST(SimulateRow, ALinearContactAtZeroGapIsHomogeneousInTheRecord) {
  // Linear buildings, a linear spring-dashpot contact (lve) and a zero gap: the equations are
  // positively homogeneous of degree one, so doubling the record doubles every peak and force
  // and leaves amplifications, impact counts and contact times unchanged.
  const BuildingRow row = sdof_pair(1e6, 4e6, 0.0);
  const ContactSpec contact = contact_of("lve", 5e7, 0.7);
  GroundMotion g;
  g.dt = 0.01;
  for (int i = 0; i <= 300; ++i)
    g.accel.push_back(3.0 * std::sin(2 * M_PI * 1.3 * i * g.dt) * std::exp(-0.5 * i * g.dt));
  GroundMotion g2 = g;
  for (double& a : g2.accel) a *= 2.0;
  IntegratorSettings integ;
  integ.atol = 1e-14;  // let the relative tolerance govern, as it does at both scales
  const RowSimulation s1 = simulate_row(row, g, contact, integ);
  const RowSimulation s2 = simulate_row(row, g2, contact, integ);
  ASSERT_GT(s1.sites[0].impacts, 0);
  EXPECT_EQ(s2.sites[0].impacts, s1.sites[0].impacts);
  EXPECT_NEAR(s2.sites[0].peak_force, 2.0 * s1.sites[0].peak_force, 1e-5 * s1.sites[0].peak_force);
  EXPECT_NEAR(s2.sites[0].first_contact, s1.sites[0].first_contact, 1e-9);
  for (std::size_t i = 0; i < s1.floors.size(); ++i) {
    EXPECT_NEAR(s2.floors[i].disp_pounding, 2.0 * s1.floors[i].disp_pounding,
                1e-5 * s1.floors[i].disp_pounding);
    EXPECT_NEAR(s2.floors[i].disp_amplification, s1.floors[i].disp_amplification, 1e-5);
    // Pounding changes the response here: the test would not see a contact switched off.
    EXPECT_GT(std::fabs(s1.floors[i].disp_amplification - 1.0), 1e-3);
  }
}

}  // namespace
}  // namespace pound

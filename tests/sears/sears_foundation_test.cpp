// The damped Sears model's event stepping on buildings with flexible foundations (issue 29;
// docs/ssi.md, docs/speed.md): coarse steps where the translation bound proves that no contact
// can start (sears/translation_bound.hpp), which on a foundation with mass covers the bases'
// sway and rotation as DOFs of their building, and on a massless base (first-order DOFs) goes
// through the Schur complement of those DOFs; with P-Delta (or tangent-stiffness damping) a
// massless base leaves the bound unproved, and that row takes the located stretches instead
// (sears/sears_located.cpp: lumped steps kept where their own motion stays clear of a contact).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "../support/studies.hpp"

namespace pound::sears {
namespace {

// studies/ch8-five-three.ini at a 2 mm gap, the first 4 s, both buildings on soft soil
// (docs/ssi.md's springs for Vs = 100 m/s under 20 m and 12 m footprints); `mass`: rafts of the
// floors' mass with I_0 = m_0 L^2 / 12 and the floors' J = m L^2 / 12.
using Keys = std::vector<std::pair<std::string, std::string>>;
test::StudyRun soft_pair(bool mass, bool p_delta = false, const Keys& more = {}) {
  Keys keys = {{"pair1.gap", "0.002"},
               {"motion.duration", "4"},
               {"building1.foundation", "springs"},
               {"building1.sway_stiffness", "9.56e8"},
               {"building1.rocking_stiffness", "1.02e11"},
               {"building1.sway_damping", "7.2e7"},
               {"building1.rocking_damping", "4.49e9"},
               {"building2.foundation", "springs"},
               {"building2.sway_stiffness", "5.73e8"},
               {"building2.rocking_stiffness", "2.2e10"},
               {"building2.sway_damping", "2.59e7"},
               {"building2.rocking_damping", "5.82e8"}};
  const Keys rafts = {
      {"building1.foundation_mass", "2.4e5"},     {"building1.foundation_inertia", "8e6"},
      {"building1.floor_inertias", "1.6e6"},      {"building2.foundation_mass", "8.7e4"},
      {"building2.foundation_inertia", "1.04e6"}, {"building2.floor_inertias", "3.48e5"}};
  if (mass) keys.insert(keys.end(), rafts.begin(), rafts.end());
  if (p_delta)
    keys.insert(keys.end(), {{"building1.p_delta", "true"}, {"building2.p_delta", "true"}});
  for (const auto& kv : more) {  // (a key given again replaces the one above)
    keys.erase(std::remove_if(keys.begin(), keys.end(),
                              [&](const auto& x) { return x.first == kv.first; }),
               keys.end());
    keys.push_back(kv);
  }
  std::vector<std::string> args;
  for (const auto& [k, v] : keys) args.insert(args.end(), {"--" + k, v});
  return test::read_study("ch8-five-three.ini", args);
}

// Massive and massless bases: coarse steps, none of which ends in an overlap, and the peaks of
// the fixed stepping (fine steps throughout) within 5e-3 (as on fixed bases,
// sears_event_test.cpp; 5e-6 measured, with 1657 coarse steps of 7721 on the massive bases),
// the same number of impacts. Massless bases with P-Delta: no coarse step.
TEST(SearsFoundation, EventSteppingIsSafeOnFoundations) {
  for (int c = 0; c < 3; ++c) {
    const bool mass = c == 0, p_delta = c == 2;
    SCOPED_TRACE(mass ? "massive bases" : p_delta ? "massless bases, P-Delta" : "massless bases");
    test::StudyRun s = soft_pair(mass, p_delta);
    s.model.stepping = SearsStepping::fixed;
    const SearsRowSimulation f = simulate_sears_row(s.row, s.motion, s.model);
    s.model.stepping = SearsStepping::event;
    const SearsRowSimulation e = simulate_sears_row(s.row, s.motion, s.model);
    EXPECT_EQ(e.counts_pounding.bound_violations, 0);
    if (p_delta) {  // no bound: located stretches on the lumped steps instead (below)
      EXPECT_EQ(e.counts_pounding.coarse, 0);
      EXPECT_GT(e.counts_pounding.lumped, 0);
    } else {
      EXPECT_GT(e.counts_pounding.coarse, 0);
    }
    ASSERT_EQ(e.base.floors.size(), f.base.floors.size());
    double worst = 0.0;
    for (std::size_t i = 0; i < f.base.floors.size(); ++i) {
      const FloorResponse &x = e.base.floors[i], &y = f.base.floors[i];
      EXPECT_NEAR(x.disp_pounding, y.disp_pounding, 5e-3 * y.disp_pounding) << i;
      EXPECT_NEAR(x.peak_drift_ratio_pounding, y.peak_drift_ratio_pounding,
                  5e-3 * y.peak_drift_ratio_pounding)
          << i;
      worst = std::max({worst, std::fabs(x.disp_pounding / y.disp_pounding - 1),
                        std::fabs(x.peak_drift_ratio_pounding / y.peak_drift_ratio_pounding - 1)});
    }
    int impacts = 0;
    for (std::size_t k = 0; k < f.base.sites.size(); ++k) {
      EXPECT_EQ(e.base.sites[k].impacts, f.base.sites[k].impacts) << k;
      impacts += f.base.sites[k].impacts;
    }
    EXPECT_GT(impacts, 3);
    RecordProperty(mass      ? "massive_coarse_steps"
                   : p_delta ? "massless_p_delta_coarse_steps"
                             : "massless_coarse_steps",
                   std::to_string(e.counts_pounding.coarse) + " of " +
                       std::to_string(e.counts_pounding.coarse + e.counts_pounding.fine) +
                       ", worst relative difference " + std::to_string(worst));
  }
}

// The soft pair on massless bases with the raft study's storeys (studies/ssi-soft-soil.ini with
// foundation_mass = 0): IMK storeys (ch8-yielding.ini's yield shears), tangent-stiffness damping
// and P-Delta. No translation bound, so the located stretches (sears_located.cpp).
Keys raft_storeys() {
  return {{"building1.hysteresis", "imk"},
          {"building1.yield_shears", "1106e3, 1032e3, 885e3, 664e3, 369e3"},
          {"building1.damping_stiffness", "tangent"},
          {"building2.hysteresis", "imk"},
          {"building2.yield_shears", "401e3, 334e3, 200e3"},
          {"building2.damping_stiffness", "tangent"}};
}

// Located stretches against fine steps throughout (fixed stepping, what a massless base with
// tangent damping or P-Delta took before issue 38): the same impacts at every site, first
// contacts within a fine step's tolerance, and peak displacements, drifts and contact forces
// within 1e-3.
TEST(SearsFoundation, LocatedStretchesAgreeWithFineStepsOnMasslessBases) {
  for (int c = 0; c < 2; ++c) {
    SCOPED_TRACE(c == 0 ? "elastic, P-Delta" : "IMK, tangent damping, P-Delta");
    test::StudyRun s = soft_pair(false, true, c == 0 ? Keys{} : raft_storeys());
    s.model.stepping = SearsStepping::fixed;
    const SearsRowSimulation f = simulate_sears_row(s.row, s.motion, s.model);
    s.model.stepping = SearsStepping::event;
    const SearsRowSimulation e = simulate_sears_row(s.row, s.motion, s.model);
    EXPECT_EQ(e.counts_pounding.bound_violations, 0);
    EXPECT_GT(e.counts_pounding.lumped, 0);
    double worst = 0.0;
    auto near = [&](double x, double y, double tol, const char* what, std::size_t i) {
      EXPECT_NEAR(x, y, tol * std::fabs(y)) << what << " " << i;
      if (y != 0.0) worst = std::max(worst, std::fabs(x / y - 1));
    };
    ASSERT_EQ(e.base.floors.size(), f.base.floors.size());
    for (std::size_t i = 0; i < f.base.floors.size(); ++i) {
      const FloorResponse &x = e.base.floors[i], &y = f.base.floors[i];
      near(x.disp_pounding, y.disp_pounding, 1e-3, "disp", i);
      near(x.peak_drift_ratio_pounding, y.peak_drift_ratio_pounding, 1e-3, "drift", i);
    }
    int impacts = 0;
    for (std::size_t k = 0; k < f.base.sites.size(); ++k) {
      const SiteResponse &x = e.base.sites[k], &y = f.base.sites[k];
      EXPECT_EQ(x.impacts, y.impacts) << k;
      EXPECT_NEAR(x.first_contact, y.first_contact, 1e-4) << k;
      if (y.impacts > 0) near(x.peak_force, y.peak_force, 1e-3, "force", k);
      impacts += y.impacts;
    }
    EXPECT_GT(impacts, 3);
    RecordProperty(c == 0 ? "elastic_p_delta" : "imk_tangent_p_delta",
                   std::to_string(e.counts_pounding.lumped) + " lumped steps, " +
                       std::to_string(e.counts_pounding.fine) + " fine steps against " +
                       std::to_string(f.counts_pounding.fine) + ", worst relative difference " +
                       std::to_string(worst));
  }
}

// A touch between two lumped steps: the gap set 2 um below the free run's peak approach (taken
// between steps on the lumped solver's interpolant), so that the faces overlap by at most 2 um
// for a few milliseconds around that peak and are apart at the lumped steps' ends unless one
// falls there. A step kept on its end values alone would miss it; the located test (the
// quintic's maximum plus the 1 um margin) must see it, as the fine steps do. 20 um above the
// peak approach: no contact in either.
TEST(SearsFoundation, LocatedStretchesFindATouchBetweenLumpedSteps) {
  test::StudyRun s0 = soft_pair(false, true);
  const SearsRowSimulation free = simulate_sears_row(s0.row, s0.motion, s0.model);
  double peak = -1.0;
  for (const SiteResponse& x : free.base.sites) peak = std::max(peak, x.approach_free);
  ASSERT_GT(peak, 0.0);
  for (const double d : {-2e-6, 2e-5}) {
    SCOPED_TRACE(d);
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", peak + d);
    test::StudyRun s = soft_pair(false, true, {{"pair1.gap", buf}});
    s.model.stepping = SearsStepping::fixed;
    const SearsRowSimulation f = simulate_sears_row(s.row, s.motion, s.model);
    s.model.stepping = SearsStepping::event;
    const SearsRowSimulation e = simulate_sears_row(s.row, s.motion, s.model);
    EXPECT_GT(e.counts_pounding.lumped, 0);
    int fi = 0, ei = 0;  // sites touched (a first contact, however light)
    for (std::size_t k = 0; k < f.base.sites.size(); ++k) {
      fi += f.base.sites[k].first_contact >= 0.0;
      ei += e.base.sites[k].first_contact >= 0.0;
      EXPECT_NEAR(e.base.sites[k].first_contact, f.base.sites[k].first_contact, 1e-3) << k;
    }
    EXPECT_EQ(fi, d < 0.0 ? 1 : 0);
    EXPECT_EQ(ei, fi);
  }
}

}  // namespace
}  // namespace pound::sears

// The damped Sears model's event stepping on buildings with flexible foundations (issue 29;
// docs/ssi.md, docs/speed.md): coarse steps where the translation bound proves that no contact
// can start (sears/translation_bound.hpp), which on a foundation with mass covers the bases'
// sway and rotation as DOFs of their building, and on a massless base (first-order DOFs) goes
// through the Schur complement of those DOFs; with P-Delta (or tangent-stiffness damping) a
// massless base leaves the bound unproved, and that row takes fine steps throughout.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "../support/studies.hpp"

namespace pound::sears {
namespace {

// studies/ch8-five-three.ini at a 2 mm gap, the first 4 s, both buildings on soft soil
// (docs/ssi.md's springs for Vs = 100 m/s under 20 m and 12 m footprints); `mass`: rafts of the
// floors' mass with I_0 = m_0 L^2 / 12 and the floors' J = m L^2 / 12.
test::StudyRun soft_pair(bool mass, bool p_delta = false) {
  using Keys = std::vector<std::pair<std::string, std::string>>;
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
    if (p_delta) {
      EXPECT_EQ(e.counts_pounding.coarse, 0);
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

}  // namespace
}  // namespace pound::sears

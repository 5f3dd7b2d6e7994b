// Golden run of the thesis' chapter 8 practical example (studies/ch8-five-three.ini), run
// through the library as `pound simulate --config studies/ch8-five-three.ini` would run it,
// and the impact-count threshold (ContactPhase, count_impacts).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/options.hpp"
#include "sears/sears_simulation.hpp"
#include "study/row_options.hpp"
#include "study/sears_row_options.hpp"

namespace pound::sears {
namespace {

struct Chapter8Run {
  BuildingRow row;
  SearsRowSimulation sim;
};

Chapter8Run run_study(const std::string& file) {
  Options opt("simulate", "chapter 8 golden run", row_and_sears_option_specs());
  opt.parse({"--config", std::string(POUND_SOURCE_DIR) + "/studies/" + file});
  Chapter8Run r;
  r.row = row_from_options(opt);
  const SearsRowModel model = sears_row_from_options(opt, r.row);
  const GroundMotion motion = motion_from_options(opt);
  r.sim = simulate_sears_row(r.row, motion, model);
  return r;
}

const FloorResponse& floor_of(const SearsRowSimulation& s, int building, int floor) {
  for (const auto& f : s.base.floors)
    if (f.building == building && f.floor == floor) return f;
  throw std::runtime_error("no such floor");
}

const SlabPeaks& slab_of(const SearsRowSimulation& s, int building, int floor) {
  for (const auto& p : s.slabs)
    if (p.building == building && p.floor == floor) return p;
  throw std::runtime_error("no such slab");
}

TEST(SearsStudy, Chapter8FiveThreeGoldenRun) {
  // REGRESSION values, measured with this code on the fixed path (automatic step 33.1 us,
  // N = 100, Release build); the study runs on the default event-driven path (docs/speed.md),
  // which gives them to within 1e-4 (face accelerations 0.2 %). They are NOT the thesis' numbers,
  // which docs/sears.md ("Validation: thesis chapter 8") sets beside them (thesis: about 360 kN at
  // the third floor, almost 8 g at the centre of the 5-storey's third floor, contacts beginning
  // near 2.04, 2.56, 3.05, 5.29 s). Tolerance 1 %: these peaks are converged in the step to about
  // 1e-3 (the thesis' 10 us step changes them in the fourth digit) and the slab-centre
  // accelerations in N to about 2 % (N = 200), so a legitimate change of the step rule stays inside
  // while a change of the model (coupling, signs, damping, contact stiffness) moves them by more.
  // The face acceleration is not converged in N (the 0.7 ms force rise is resolved by only ~1 mode
  // period) and is held here only as a regression value.
  const Chapter8Run r = run_study("ch8-five-three.ini");
  const SearsRowSimulation& s = r.sim;
  ASSERT_EQ(s.base.sites.size(), 3u);
  ASSERT_EQ(s.contacts.size(), 3u);
  auto near = [](double got, double stored) { EXPECT_NEAR(got, stored, 0.01 * stored); };

  // Peak pounding force per floor [N].
  near(s.base.sites[0].peak_force, 196440.0);
  near(s.base.sites[1].peak_force, 358292.0);
  near(s.base.sites[2].peak_force, 528233.0);
  // Third floors: slab centre (the thesis' Figure 8.29 section) and contact face [m/s^2].
  near(slab_of(s, 0, 3).centre_accel, 112.13);
  near(slab_of(s, 1, 3).centre_accel, 174.729);
  near(slab_of(s, 0, 3).face_accel, 682.418);
  // Displacement amplification (pounding / free): 5-storey roof and third floor, 3-storey roof.
  near(floor_of(s, 0, 5).disp_amplification, 0.931449);
  near(floor_of(s, 0, 3).disp_amplification, 0.910208);
  near(floor_of(s, 1, 3).disp_amplification, 1.661529);

  // Impacts: raw contact phases (may shift by one if a microscopic phase appears or not) and
  // the thresholded count (1 % of the site's largest force; no phase is near the threshold).
  const int raw[] = {34, 30, 24}, counted[] = {31, 28, 22};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(s.base.sites[k].impacts, raw[k], 1) << "floor " << k + 1;
    EXPECT_EQ(s.contacts[k].impacts, counted[k]) << "floor " << k + 1;
    EXPECT_EQ(static_cast<int>(s.contacts[k].phases.size()), s.base.sites[k].impacts);
    double impulse = 0.0;
    for (const auto& ph : s.contacts[k].phases) impulse += ph.impulse_Ns;
    EXPECT_NEAR(impulse, s.base.pounding.sites[k].impulse, 1e-9 * impulse);
  }
  // Third floor: the starts of the strong contacts (stored values; the thesis' four contacts
  // begin near 2.04, 2.56, 3.05 and 5.29 s) within 2 ms, and the first counted impact.
  const double stored_starts[] = {1.9557, 2.4749, 2.9531, 5.2885};
  for (double t : stored_starts) {
    bool found = false;
    for (const auto& ph : s.contacts[2].phases)
      if (std::fabs(ph.start_s - t) < 2e-3 && ph.peak_force_N > 0.5 * 528233.0) found = true;
    EXPECT_TRUE(found) << "no contact above half the peak force starting at " << t << " s";
  }
  EXPECT_NEAR(s.contacts[2].first_impact_s, 0.8415, 2e-3);
}

TEST(SearsStudy, ImpactThresholdCountsOnlyPhasesCarryingForce) {
  SiteContacts c;
  c.phases = {{0.10, 0.20, 0.0, 0.0},      // touching without force: never an impact
              {0.30, 0.40, 0.9e3, 10.0},   // 0.9 % of the largest: below the 1 % threshold
              {0.50, 0.60, 1.0e3, 20.0},   // exactly 1 %: counted
              {0.70, 0.80, 100e3, 900.0},  // the largest
              {0.90, -1.0, 50e3, 300.0}};  // still in contact at the end: counted
  count_impacts(c, 0.01);
  EXPECT_EQ(c.impacts, 3);
  EXPECT_DOUBLE_EQ(c.first_impact_s, 0.50);
  count_impacts(c, 0.0);  // no threshold: every phase that carried force
  EXPECT_EQ(c.impacts, 4);
  EXPECT_DOUBLE_EQ(c.first_impact_s, 0.30);
  SiteContacts none;
  count_impacts(none, 0.01);
  EXPECT_EQ(none.impacts, 0);
  EXPECT_DOUBLE_EQ(none.first_impact_s, -1.0);
}

}  // namespace
}  // namespace pound::sears

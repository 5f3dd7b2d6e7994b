// Exact steps of a row with flexible foundations (issue 29; docs/integration.md, "Exact steps"):
// each building with its base has its own propagator (ExactSteps' blocks), and the run agrees
// with Dormand-Prince throughout.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support/buildings.hpp"
#include "motion/motion_reader.hpp"
#include "simulation/simulate_row.hpp"

namespace pound {
namespace {

// The chapter 8 pair under 8 s of El Centro, the 5-storey building on a cone (the soft-soil
// study's footing and soil, a raft as heavy as a floor), the 3-storey one on springs; `law`
// storeys, with P-Delta and tangent-stiffness damping when `p_delta`.
RowSimulation on_soil(const std::string& law, bool p_delta, const IntegratorSettings& integ) {
  BuildingRow row = test::chapter8_pair(0.01);
  const double fy[2] = {4.5e5, 1.7e5};
  for (int b = 0; b < 2; ++b) {
    Building& bd = row.buildings[b];
    bd.hysteresis = law;
    bd.yield_shears.assign(bd.floors(), fy[b]);
    bd.p_delta = p_delta;
    if (p_delta) bd.damping_stiffness = DampingStiffness::tangent;
  }
  row.buildings[0].foundation = test::cone_foundation(11.3, 120.0, 1800.0, 0.4, 48e3, 1.6e6);
  row.buildings[0].foundation.floor_inertias = {1.6e6};
  row.buildings[1].foundation = test::springs_foundation(6.0e8, 2.5e10, 2.6e7, 6.0e8, 29e3, 3.48e5);
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  GroundMotion g = read_motion(spec);
  g.accel.resize(static_cast<std::size_t>(8.0 / g.dt) + 1);
  ContactSpec c;
  c.model = "hc-linear";
  c.params.k = 50 * 8.4e7;
  c.params.e = 0.6;
  RowSimulationOptions o;
  o.extra_time = 2.0;
  o.track_energy = false;
  return simulate_row(row, g, c, integ, o);
}

TEST(FoundationSteps, ExactStepsPerBuildingAgreeWithDormandPrince) {
  // As Yielding.ExactStepsBetweenEventsAgreeWithDormandPrince on fixed bases: both at rtol
  // 1e-10, the same events and impacts, peaks within the Dormand-Prince error; accelerations
  // and contact forces within their sampling at the steps' ends.
  IntegratorSettings exact, dopri;
  exact.rtol = dopri.rtol = 1e-10;
  dopri.exact_free = false;
  for (const std::string law : {"elastic", "bilinear", "imk"}) {
    for (int p_delta = 0; p_delta < 2; ++p_delta) {
      const std::string what = law + (p_delta ? " with P-Delta and tangent damping" : "");
      const RowSimulation e = on_soil(law, p_delta, exact);
      const RowSimulation d = on_soil(law, p_delta, dopri);
      EXPECT_EQ(d.pounding.exact_steps + d.free.exact_steps, 0) << what;
      // (yielding storeys' events hand many grid steps to Dormand-Prince; IMK storeys meet a new
      // tangent stiffness at every excursion, so that few grid points reach a propagator:
      // there the exact steps must at least cost no steps)
      if (law == "imk") {
        EXPECT_GT(e.free.exact_steps, 0) << what;
        EXPECT_LT(e.free.steps, 1.1 * d.free.steps) << what;
      } else {
        EXPECT_GT(e.free.exact_steps, (law == "elastic" ? 0.75 : 0.5) * e.free.steps) << what;
      }
      EXPECT_EQ(e.pounding.events, d.pounding.events) << what;
      EXPECT_EQ(e.free.events, d.free.events) << what;
      auto near = [&](double x, double y, double rel, const char* q) {
        EXPECT_NEAR(x, y, rel * std::fabs(y) + 1e-12) << what << " " << q;
      };
      for (std::size_t i = 0; i < e.floors.size(); ++i) {
        near(e.floors[i].disp_pounding, d.floors[i].disp_pounding, 1e-6, "disp");
        near(e.floors[i].disp_free, d.floors[i].disp_free, 1e-6, "disp free");
        near(e.floors[i].peak_drift_ratio_pounding, d.floors[i].peak_drift_ratio_pounding, 1e-6,
             "drift");
        near(e.floors[i].residual_drift_ratio_free, d.floors[i].residual_drift_ratio_free, 1e-5,
             "residual");
        near(e.floors[i].accel_pounding, d.floors[i].accel_pounding, 1e-2, "accel");
        near(e.floors[i].accel_free, d.floors[i].accel_free, 1e-2, "accel free");
      }
      int impacts = 0;
      for (std::size_t k = 0; k < e.sites.size(); ++k) {
        EXPECT_EQ(e.sites[k].impacts, d.sites[k].impacts) << what;
        impacts += e.sites[k].impacts;
        near(e.sites[k].peak_force, d.sites[k].peak_force, 2e-3, "force");
        near(e.sites[k].approach_free, d.sites[k].approach_free, 1e-6, "approach");
      }
      EXPECT_GT(impacts, 0) << what;
    }
  }
}

}  // namespace
}  // namespace pound

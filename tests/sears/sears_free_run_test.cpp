// The run without pounding of a damped Sears simulation is the lumped solver's free run (issue
// 30): without contacts the floors' physics is the same whatever the contact model, so its
// numbers (every *_free quantity and the free run's approach at each site) are those of a
// lumped model's simulation of the same row, record, storeys and damping. Since issue 38 a row
// of an elastic and a yielding building takes it building by building (apart_pays, solve_apart:
// solver/row_apart.hpp): then its numbers are solve_apart's bit for bit, and the lumped
// simulation's (the row stepped together) to the integration tolerance, the peak accelerations,
// sampled at the steps (docs/integration.md, "Peaks"), to their sampling on the other steps.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../support/studies.hpp"
#include "sears/sears_simulation.hpp"
#include "simulation/contact_spec.hpp"
#include "simulation/simulate_row.hpp"
#include "solver/row_apart.hpp"

namespace pound::sears {
namespace {

TEST(SearsFreeRun, TheFreeRunIsTheLumpedModelsFreeRun) {
  for (const char* law : {"elastic", "bilinear", "imk", "imk, elastic"}) {
    SCOPED_TRACE(law);
    test::StudyRun s = test::read_study("ch8-yielding.ini");
    const bool mixed = std::string(law) == "imk, elastic";
    for (auto& b : s.row.buildings) b.hysteresis = mixed ? "imk" : law;
    if (mixed) s.row.buildings[1].hysteresis = "elastic";
    ASSERT_EQ(apart_pays(s.row), mixed);
    RowSimulationOptions o;
    o.extra_time = 2.0;
    o.collapse_drift_ratio = 0.1;
    const SearsRowSimulation sears = simulate_sears_row(s.row, s.motion, s.model, o);
    ContactSpec hc;
    hc.model = "hc-linear";
    hc.params.e = 0.5;
    hc.params.k = 5e9;
    const RowSimulation lumped = simulate_row(s.row, s.motion, hc, IntegratorSettings{}, o);
    // The raw run: solve_apart's (mixed) or solve's, bit for bit.
    const AssembledRow a0 = assemble(s.row);
    const RowGround ground = RowGround::uniform(s.motion, 2);
    RowProblem fp;
    fp.row = &a0;
    o.apply_to(fp, ground);
    const RowResult own =
        mixed ? solve_apart(s.row, fp, IntegratorSettings{}) : solve(fp, IntegratorSettings{});
    const RowResult& free = sears.base.free;
    EXPECT_EQ(free.steps, own.steps);
    for (int k = 0; k < a0.dofs(); ++k) {
      EXPECT_EQ(free.peak_disp(k), own.peak_disp(k)) << k;
      EXPECT_EQ(free.peak_abs_accel(k), own.peak_abs_accel(k)) << k;
      EXPECT_EQ(free.u_end(k), own.u_end(k)) << k;
    }
    ASSERT_EQ(sears.base.floors.size(), lumped.floors.size());
    int differing = 0;
    for (std::size_t i = 0; i < lumped.floors.size(); ++i) {
      const FloorResponse &a = sears.base.floors[i], &b = lumped.floors[i];
      auto near = [&](double x, double y) { return std::fabs(x - y) <= 1e-6 * std::fabs(y); };
      differing += !near(a.disp_free, b.disp_free) +
                   !near(a.peak_drift_ratio_free, b.peak_drift_ratio_free) +
                   (!mixed && !near(a.accel_free, b.accel_free)) +
                   !near(a.residual_drift_ratio_free, b.residual_drift_ratio_free) +
                   !near(a.hysteretic_energy_free, b.hysteretic_energy_free);
      EXPECT_NEAR(a.disp_free, b.disp_free, 1e-6 * b.disp_free) << i;
      EXPECT_NEAR(a.accel_free, b.accel_free, (mixed ? 1e-3 : 1e-6) * b.accel_free) << i;
    }
    EXPECT_EQ(differing, 0);
    for (std::size_t k = 0; k < lumped.sites.size(); ++k)
      EXPECT_NEAR(sears.base.sites[k].approach_free, lumped.sites[k].approach_free,
                  1e-6 * lumped.sites[k].approach_free)
          << k;
    // The pounding runs do differ (the contact models do): the comparison is not empty.
    double apart = 0.0;
    for (std::size_t i = 0; i < lumped.floors.size(); ++i)
      apart = std::max(
          apart, std::fabs(sears.base.floors[i].disp_pounding - lumped.floors[i].disp_pounding) /
                     lumped.floors[i].disp_pounding);
    EXPECT_GT(apart, 1e-4);
  }
}

}  // namespace
}  // namespace pound::sears

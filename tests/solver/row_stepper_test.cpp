// The lumped sample's two runs with the free run building by building and the pounding run
// forked at a common time (solver/row_stepper.hpp, issue 38 part 1): the first contact found
// across two buildings' step grids where the row run finds it, the fork's re-taken state the
// row's at that time, the pounding run today's forked one, the free run solve_apart's, the
// energy balance closing per building and in the pounding run.
#include "solver/row_stepper.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../support/buildings.hpp"
#include "../support/reference_inputs.hpp"
#include "simulation/contact_spec.hpp"
#include "solver/row_apart.hpp"
#include "solver/row_solver.hpp"
#include "structure/building_row.hpp"

namespace pound {
namespace {

double rel(double a, double b) {
  return std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), 1e-300});
}

// The row's sample with hc-linear contacts (k = 50 times the larger storey stiffness).
GroundMotion elcentro(double scale) {
  GroundMotion m = test::elcentro_first(301);
  for (double& x : m.accel) x *= scale;
  return m;
}

struct Sample {
  explicit Sample(double gap, bool energy = false, double scale = 1.0)
      : row(test::yielding_and_elastic_pair(gap)),
        a(assemble(row)),
        g(RowGround::uniform(elcentro(scale), 2)) {
    ContactSpec c;
    c.model = "hc-linear";
    c.params.k = 50 * 8.4e7;
    c.params.e = 0.6;
    laws = make_site_laws(c, a);
    p.row = &a;
    p.ground = &g;
    p.t_end = g.duration() + 1.0;
    p.track_energy = energy;
    for (const auto& l : laws) p.laws.push_back(l.get());
  }
  RowProblem free() const {
    RowProblem f = p;
    f.laws.clear();
    return f;
  }
  BuildingRow row;
  AssembledRow a;
  RowGround g;
  std::vector<std::unique_ptr<ContactLaw>> laws;
  RowProblem p;
};

// The largest peak approach of the free run (solve_apart) and its site.
int nearest_site(const RowResult& r) {
  int top = 0;
  for (int i = 1; i < static_cast<int>(r.sites.size()); ++i)
    if (r.sites[i].peak_approach > r.sites[top].peak_approach) top = i;
  return top;
}

TEST(RowStepper, AppliesToMixedRowsOnly) {
  Sample x(0.01);
  EXPECT_TRUE(fork_apart_applies(x.row, x.p));
  x.row.buildings[0].hysteresis = "elastic";
  EXPECT_FALSE(fork_apart_applies(x.row, x.p));
  EXPECT_FALSE(fork_apart_applies(test::yielding_and_elastic_pair(0.01), x.free()));  // no laws
}

// A gap just under the free run's peak approach: the buildings touch once. The fork's first
// contact is the row run's (solve: the row together, with contacts) within the event
// location's tolerance, and the state it forked from is the row's free run at that time
// within the integration tolerance (rtol 1e-8 of the motion).
TEST(RowStepper, ContactFoundOnDifferentGrids) {
  const IntegratorSettings s;
  int retaken = 0;
  for (const double scale : {0.8, 0.9, 1.0, 1.1, 1.2}) {
    const Sample probe(0.0, false, scale);
    const RowResult fa = solve_apart(probe.row, probe.free(), s);
    const int top = nearest_site(fa);
    const double peak = fa.sites[top].peak_approach;
    ASSERT_GT(peak, 0.01);
    const Sample x(peak * (1.0 - 1e-5), false, scale);
    ForkStats st;
    const RunPair runs = solve_free_and_pounding_apart(x.row, x.p, s, &st);
    ASSERT_FALSE(st.own_pounding_run) << scale;
    ASSERT_GT(st.t_fork, 0.0) << scale;
    retaken += st.retaken > 0.0;
    const RowResult row = solve(x.p, s);
    ASSERT_EQ(row.sites[top].impacts, 1) << scale;
    int touched = 0;
    for (const SiteResult& r : runs.pounding.sites) touched += r.impacts;
    EXPECT_EQ(touched, 1) << scale;
    EXPECT_EQ(runs.pounding.sites[top].impacts, 1) << scale;
    EXPECT_LT(runs.pounding.sites[top].first_contact - st.t_fork, 0.011) << scale;
    EXPECT_NEAR(runs.pounding.sites[top].first_contact, row.sites[top].first_contact, 1e-7);
    // The pounding run's peaks (those before t_fork from the buildings' runs) are the row's.
    for (int k = 0; k < x.a.dofs(); ++k) {
      EXPECT_LT(rel(runs.pounding.peak_disp(k), row.peak_disp(k)), 1e-6) << scale << " " << k;
      EXPECT_LT(rel(runs.pounding.peak_drift(k), row.peak_drift(k)), 1e-6) << scale << " " << k;
    }
    // The re-taken state at t_fork against the row's free run stopped there.
    RowProblem f = x.free();
    f.t_end = st.t_fork;
    const RowResult at = solve(f, s);
    ASSERT_EQ(at.t_end, st.t_fork);
    const double scale_u = fa.peak_disp.maxCoeff();
    EXPECT_LT((st.u - at.u_end).cwiseAbs().maxCoeff(), 1e-6 * scale_u) << scale;
    EXPECT_LT((st.v - at.v_end).cwiseAbs().maxCoeff(), 1e-5 * scale_u) << scale;
    // The free run is solve_apart's.
    const RowResult ap = solve_apart(x.row, x.free(), s);
    for (int k = 0; k < x.a.dofs(); ++k) EXPECT_EQ(runs.free.peak_disp(k), ap.peak_disp(k));
    EXPECT_EQ(runs.free.sites[top].peak_approach, ap.sites[top].peak_approach);
    // Stopped 20 ms after the touch, the pounding run's peaks are mostly the buildings' before
    // t_fork (RunRecorder::merge_from): still the row's.
    Sample y(x.row.gaps[0][0], false, scale);
    y.p.t_end = row.sites[top].first_contact + 0.02;
    const RunPair short_runs = solve_free_and_pounding_apart(y.row, y.p, s);
    const RowResult short_row = solve(y.p, s);
    for (int k = 0; k < x.a.dofs(); ++k)
      EXPECT_LT(rel(short_runs.pounding.peak_disp(k), short_row.peak_disp(k)), 1e-6) << scale;
    // A gap half the margin above the peak approach: no touch, but the fork is taken where the
    // approach's cubic comes within the margin inside the overlapping steps.
    const Sample z(peak + 0.5 * 1e-6, false, scale);
    ForkStats sz;
    const RunPair near = solve_free_and_pounding_apart(z.row, z.p, s, &sz);
    EXPECT_GT(sz.t_fork, 0.0) << scale;
    EXPECT_EQ(near.pounding.sites[top].impacts, 0) << scale;
  }
  EXPECT_GT(retaken, 0);  // some forks fell inside the neighbour's last step
}

// With several contacts: the pounding run forked at a common time against today's fork of the
// row run (solve_free_and_pounding), peaks within 1e-6.
TEST(RowStepper, PoundingRunIsTheForkedOnes) {
  for (const double gap : {0.005, 0.01}) {
    const Sample x(gap);
    const IntegratorSettings s;
    ForkStats st;
    const RunPair now = solve_free_and_pounding_apart(x.row, x.p, s, &st);
    const RunPair was = solve_free_and_pounding(x.p, s);
    ASSERT_FALSE(st.own_pounding_run) << gap;
    ASSERT_GT(st.t_fork, 0.0) << gap;
    const RowResult &a = now.pounding, &b = was.pounding;
    int impacts = 0;
    for (std::size_t i = 0; i < a.sites.size(); ++i) {
      EXPECT_EQ(a.sites[i].impacts, b.sites[i].impacts) << gap << " " << i;
      impacts += a.sites[i].impacts;
      if (b.sites[i].impacts == 0) continue;
      EXPECT_LT(rel(a.sites[i].peak_force, b.sites[i].peak_force), 1e-6) << gap << " " << i;
      EXPECT_LT(std::fabs(a.sites[i].first_contact - b.sites[i].first_contact), 1e-7);
    }
    EXPECT_GT(impacts, 1) << gap;
    for (int k = 0; k < x.a.dofs(); ++k) {
      EXPECT_LT(rel(a.peak_disp(k), b.peak_disp(k)), 1e-6) << gap << " " << k;
      EXPECT_LT(rel(a.peak_drift(k), b.peak_drift(k)), 1e-6) << gap << " " << k;
      EXPECT_LT(rel(a.hysteretic_energy(k), b.hysteretic_energy(k)), 1e-6) << gap << " " << k;
    }
    // The elastic building takes exact steps in the free run.
    EXPECT_GT(now.free.exact_steps, was.free.exact_steps + 500);
  }
}

// The energy balance (physics.md section 6): the free run's closes per building (it is
// solve_apart's, each building's its own), the pounding run's, resumed at t_fork from the
// buildings' summed input and damping, closes as today's fork does.
TEST(RowStepper, EnergyBalanceClosesPerBuilding) {
  const Sample x(0.01, true);
  const IntegratorSettings s;
  ForkStats st;
  const RunPair now = solve_free_and_pounding_apart(x.row, x.p, s, &st);
  const RunPair was = solve_free_and_pounding(x.p, s);
  ASSERT_GT(st.t_fork, 0.0);
  const RowResult ap = solve_apart(x.row, x.free(), s);
  EXPECT_EQ(now.free.energy.input, ap.energy.input);
  EXPECT_EQ(now.free.energy.residual(), ap.energy.residual());
  EXPECT_LT(std::fabs(now.free.energy.residual()), 1e-6 * now.free.energy.input);
  const EnergyBalance &e = now.pounding.energy, &e0 = was.pounding.energy;
  EXPECT_GT(e.contact, 0.0);
  EXPECT_LT(std::fabs(e.residual()), 1e-6 * e.input);
  EXPECT_LT(rel(e.input, e0.input), 1e-6);
  EXPECT_LT(rel(e.hysteretic, e0.hysteretic), 1e-6);
  EXPECT_LT(rel(e.contact, e0.contact), 1e-5);
}

}  // namespace
}  // namespace pound

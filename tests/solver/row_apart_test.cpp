// A row's run without contacts stepped building by building (solver/row_apart.hpp, issue 38):
// each building's block is that building simulated alone; the row's result agrees with the
// row stepped together (solve) to the integration tolerance; the sites' peak approach, taken
// across two step grids, tells a pounding run's first touch; the energy balance closes per
// building; ground channels, column sites, collapse and a flexible foundation.
#include "solver/row_apart.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../support/buildings.hpp"
#include "../support/ground_motions.hpp"
#include "../support/reference_inputs.hpp"
#include "simulation/contact_spec.hpp"
#include "solver/row_solver.hpp"
#include "structure/building_row.hpp"

namespace pound {
namespace {

RowProblem free_problem(const AssembledRow& a, const RowGround& g, double extra = 1.0) {
  RowProblem p;
  p.row = &a;
  p.ground = &g;
  p.t_end = g.duration() + extra;
  return p;
}

double rel(double a, double b) {
  return std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), 1e-300});
}

// Each building alone: its own row (assemble of that building), on its own channel.
RowResult alone(const BuildingRow& row, int b, const RowGround& g, const RowProblem& like,
                const IntegratorSettings& s) {
  BuildingRow one;
  one.buildings = {row.buildings[static_cast<std::size_t>(b)]};
  const AssembledRow a = assemble(one);
  const RowGround gb = RowGround::uniform(g.under(b).motion(), 1);
  RowProblem p = free_problem(a, gb, like.t_end - g.duration());
  p.track_energy = like.track_energy;
  p.collapse_drift_ratio = like.collapse_drift_ratio;
  return solve(p, s);
}

TEST(RowApart, EachBuildingIsItselfAlone) {
  const BuildingRow row = test::yielding_and_elastic_pair(0.01);
  const AssembledRow a = assemble(row);
  const RowGround g = RowGround::uniform(test::elcentro_first(301), 2);
  const RowProblem p = free_problem(a, g);
  const IntegratorSettings s;
  const RowResult r = solve_apart(row, p, s);
  long steps = 0;
  for (int b = 0; b < 2; ++b) {
    const RowResult one = alone(row, b, g, p, s);
    steps += one.steps;
    const int off = a.offset[static_cast<std::size_t>(b)];
    const int nf = static_cast<int>(row.buildings[static_cast<std::size_t>(b)].masses.size());
    // The block of the row's matrices is the building's own.
    BuildingRow only;
    only.buildings = {row.buildings[static_cast<std::size_t>(b)]};
    const AssembledRow ab = assemble(only);
    EXPECT_EQ((a.K.block(off, off, nf, nf) - ab.K).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ((a.C.block(off, off, nf, nf) - ab.C).cwiseAbs().maxCoeff(), 0.0);
    for (int k = 0; k < nf; ++k) {
      EXPECT_NEAR(r.peak_disp(off + k), one.peak_disp(k), 1e-10 * one.peak_disp(k));
      EXPECT_NEAR(r.peak_drift(off + k), one.peak_drift(k), 1e-10 * one.peak_drift(k));
      EXPECT_NEAR(r.peak_abs_accel(off + k), one.peak_abs_accel(k), 1e-10 * one.peak_abs_accel(k));
      EXPECT_NEAR(r.u_end(off + k), one.u_end(k), 1e-10 * one.peak_disp(k));
      EXPECT_NEAR(r.v_end(off + k), one.v_end(k), 1e-10 * one.peak_disp(k));
      EXPECT_NEAR(r.hysteretic_energy(off + k), one.hysteretic_energy(k),
                  1e-10 * std::max(1.0, one.hysteretic_energy(k)));
    }
  }
  EXPECT_EQ(r.steps, steps);
  EXPECT_GT(r.hysteretic_energy.head(5).sum(), 1e3);  // building 1 yields [J]
  EXPECT_EQ(r.hysteretic_energy.tail(3).sum(), 0.0);  // building 2 does not
}

TEST(RowApart, AgreesWithTheRowSteppedTogether) {
  const BuildingRow row = test::yielding_and_elastic_pair(0.01);
  const AssembledRow a = assemble(row);
  const RowGround g = RowGround::uniform(test::elcentro_first(301), 2);
  const RowProblem p = free_problem(a, g);
  const IntegratorSettings s;
  const RowResult ra = solve_apart(row, p, s), rt = solve(p, s);
  for (int k = 0; k < a.dofs(); ++k) {
    EXPECT_LT(rel(ra.peak_disp(k), rt.peak_disp(k)), 1e-6) << k;
    EXPECT_LT(rel(ra.peak_drift(k), rt.peak_drift(k)), 1e-6) << k;
    // Sampled at the steps' ends (docs/integration.md, "Peaks"): other steps, other samples.
    EXPECT_LT(rel(ra.peak_abs_accel(k), rt.peak_abs_accel(k)), 5e-3) << k;
    EXPECT_LT(rel(ra.hysteretic_energy(k), rt.hysteretic_energy(k)), 1e-5) << k;
  }
  for (std::size_t i = 0; i < ra.sites.size(); ++i)
    EXPECT_LT(rel(ra.sites[i].peak_approach, rt.sites[i].peak_approach), 1e-6) << i;
  // The elastic building alone takes exact steps where in the row it followed the yielding
  // one's Dormand-Prince steps.
  EXPECT_GT(ra.exact_steps, rt.exact_steps + 500);
  EXPECT_EQ(ra.t_end, rt.t_end);
}

// The peak approach taken across the two buildings' grids is the smallest gap the motion does
// not close: a pounding run (the row together, with contacts) touches at a gap a little below
// it and not at one a little above it (the contact is found where the two-grid approach says).
TEST(RowApart, PeakApproachOnTwoGridsTellsTheFirstTouch) {
  const BuildingRow row0 = test::yielding_and_elastic_pair(0.0);
  const AssembledRow a0 = assemble(row0);
  const RowGround g = RowGround::uniform(test::elcentro_first(301), 2);
  const IntegratorSettings s;
  const RowResult ra = solve_apart(row0, free_problem(a0, g), s);
  ASSERT_EQ(ra.sites.size(), 3u);
  int top = 0;  // the site that comes nearest
  for (int i = 1; i < 3; ++i)
    if (ra.sites[i].peak_approach > ra.sites[top].peak_approach) top = i;
  const double peak = ra.sites[top].peak_approach;
  ASSERT_GT(peak, 0.01);
  ContactSpec c;
  c.model = "hc-linear";
  c.params.k = 50 * 8.4e7;
  c.params.e = 0.6;
  for (const double f : {1.0 - 1e-5, 1.0 + 1e-5}) {
    const BuildingRow row = test::yielding_and_elastic_pair(f * peak);
    const AssembledRow a = assemble(row);
    const auto laws = make_site_laws(c, a);
    RowProblem p = free_problem(a, g);
    for (const auto& l : laws) p.laws.push_back(l.get());
    const RowResult r = solve(p, s);
    EXPECT_EQ(r.sites[top].impacts > 0, f < 1.0) << f;
  }
}

TEST(RowApart, EnergyBalanceClosesPerBuilding) {
  const BuildingRow row = test::yielding_and_elastic_pair(0.01);
  const AssembledRow a = assemble(row);
  const RowGround g = RowGround::uniform(test::elcentro_first(301), 2);
  RowProblem p = free_problem(a, g);
  p.track_energy = true;
  const IntegratorSettings s;
  const RowResult r = solve_apart(row, p, s), rt = solve(p, s);
  double input = 0.0;
  for (int b = 0; b < 2; ++b) {
    const RowResult one = alone(row, b, g, p, s);
    EXPECT_GT(one.energy.input, 0.0);
    EXPECT_LT(std::fabs(one.energy.residual()), 1e-6 * one.energy.input) << b;
    input += one.energy.input;
  }
  EXPECT_EQ(r.energy.input, input);
  EXPECT_LT(std::fabs(r.energy.residual()), 1e-6 * r.energy.input);
  EXPECT_LT(rel(r.energy.input, rt.energy.input), 1e-6);
  EXPECT_LT(rel(r.energy.hysteretic, rt.energy.hysteretic), 1e-5);
}

// Each building on its own channel (spatially varying ground): the approach takes the grounds'
// difference (physics.md section 5a) as the row does.
TEST(RowApart, BuildingsOnTheirOwnGround) {
  const BuildingRow row = test::yielding_and_elastic_pair(0.01);
  const AssembledRow a = assemble(row);
  GroundMotion m1 = test::elcentro_first(301), m2 = m1;
  for (double& x : m2.accel) x *= 0.7;
  const RowGround g = RowGround::per_building({m1, m2});
  ASSERT_EQ(g.channels(), 2);
  const RowProblem p = free_problem(a, g);
  const IntegratorSettings s;
  const RowResult ra = solve_apart(row, p, s), rt = solve(p, s);
  for (std::size_t i = 0; i < ra.sites.size(); ++i)
    EXPECT_LT(rel(ra.sites[i].peak_approach, rt.sites[i].peak_approach), 1e-6) << i;
  for (int k = 0; k < a.dofs(); ++k) EXPECT_LT(rel(ra.peak_disp(k), rt.peak_disp(k)), 1e-6);
  // Building 2 alone on its own channel is building 2 of the split run.
  const RowResult two = alone(row, 1, g, p, s);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(ra.peak_disp(5 + k), two.peak_disp(k));
}

// Column sites (issue 36): the free run's peak sway shear on the struck columns.
TEST(RowApart, ColumnSitesKeepTheSwayShear) {
  const BuildingRow row = test::offset_pair(0.01, 0.05);
  const AssembledRow a = assemble(row);
  const RowGround g = RowGround::uniform(test::sine_pulse(), 2);
  const RowProblem p = free_problem(a, g);
  const IntegratorSettings s;
  const RowResult ra = solve_apart(row, p, s), rt = solve(p, s);
  int columns = 0;
  for (std::size_t i = 0; i < ra.sites.size(); ++i) {
    EXPECT_LT(rel(ra.sites[i].peak_approach, rt.sites[i].peak_approach), 1e-6) << i;
    if (!a.sites[i].column()) continue;
    ++columns;
    EXPECT_GT(ra.sites[i].peak_column_shear, 0.0);
    EXPECT_LT(rel(ra.sites[i].peak_column_shear, rt.sites[i].peak_column_shear), 1e-5) << i;
  }
  EXPECT_EQ(columns, 3);
}

// A building that collapses is held still while the other goes on, as in the row; with an
// energy balance the run is the row's (whose balance is the one at the first collapse).
TEST(RowApart, CollapseHoldsTheBuildingAsTheRowDoes) {
  const BuildingRow row = test::yielding_and_elastic_pair(0.01);
  const AssembledRow a = assemble(row);
  const RowGround g = RowGround::uniform(test::elcentro_first(301), 2);
  RowProblem p = free_problem(a, g);
  p.collapse_drift_ratio = 0.004;
  const IntegratorSettings s;
  const RowResult ra = solve_apart(row, p, s), rt = solve(p, s);
  ASSERT_EQ(ra.collapse.size(), 2u);
  EXPECT_TRUE(ra.collapse[0].collapsed);
  EXPECT_FALSE(ra.collapse[1].collapsed);
  EXPECT_TRUE(rt.collapse[0].collapsed);
  EXPECT_NEAR(ra.collapse[0].time, rt.collapse[0].time, 1e-6);
  EXPECT_EQ(ra.collapse[0].storey, rt.collapse[0].storey);
  EXPECT_FALSE(ra.stopped);
  EXPECT_NEAR(ra.t_end, rt.t_end, 1e-12);
  // The standing building as in the row, to the integration tolerance. The collapsed one is
  // held at the end of the step in which its drift passed the limit (RowRun::on_collapse at
  // the next iteration): its own step alone, the row's step in the row, so its held state and
  // peaks differ by what it moves in part of a step (|v| h ~ 0.3 m/s x 3 ms ~ 1e-3 m here).
  for (int k = 0; k < a.dofs(); ++k) {
    const bool standing = a.building_of[k] == 1;
    EXPECT_LT(rel(ra.peak_disp(k), rt.peak_disp(k)), standing ? 1e-6 : 2e-3) << k;
    EXPECT_NEAR(ra.u_end(k), rt.u_end(k), (standing ? 1e-5 : 2e-3) * rt.peak_disp(k)) << k;
  }
  for (std::size_t i = 0; i < ra.sites.size(); ++i)
    EXPECT_LT(rel(ra.sites[i].peak_approach, rt.sites[i].peak_approach), 2e-3) << i;
  p.track_energy = true;
  const RowResult re = solve_apart(row, p, s), rte = solve(p, s);
  EXPECT_EQ(re.energy.input, rte.energy.input);
  EXPECT_EQ(re.steps, rte.steps);
}

// On a flexible foundation (its base's sway and rotation after all floors in the row's
// numbering, first after its own floors alone).
TEST(RowApart, FlexibleFoundationsMapTheBaseDofs) {
  BuildingRow row = test::yielding_and_elastic_pair(0.01);
  row.buildings[0].foundation = test::cone_foundation(7.1, 150, 1800, 0.4, 48e3, 1.6e6);
  row.buildings[1].foundation = test::cone_foundation(5.5, 150, 1800, 0.4, 29e3, 3.48e5);
  const AssembledRow a = assemble(row);
  ASSERT_EQ(a.dofs(), 12);
  const RowGround g = RowGround::uniform(test::elcentro_first(301), 2);
  const RowProblem p = free_problem(a, g);
  const IntegratorSettings s;
  const RowResult ra = solve_apart(row, p, s), rt = solve(p, s);
  for (int k = 0; k < a.dofs(); ++k) {
    EXPECT_LT(rel(ra.peak_disp(k), rt.peak_disp(k)), 1e-5) << k;
    EXPECT_NEAR(ra.u_end(k), rt.u_end(k), 1e-5 * rt.peak_disp(k)) << k;
  }
  for (std::size_t i = 0; i < ra.sites.size(); ++i)
    EXPECT_LT(rel(ra.sites[i].peak_approach, rt.sites[i].peak_approach), 1e-6) << i;
  const RowResult two = alone(row, 1, g, p, s);
  EXPECT_EQ(ra.peak_disp(a.sway[1]), two.peak_disp(3));
  EXPECT_EQ(ra.peak_disp(a.rot[1]), two.peak_disp(4));
}

}  // namespace
}  // namespace pound

// Issue 23 in both solvers: P-Delta (the elastic period T / sqrt(1 - P / (k0 h)) and the energy
// balance with deteriorating storeys and pounding), tangent-stiffness damping, and collapse as a
// limit state (a run that collapses stops and says so; one that does not is unchanged by the
// key).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "../support/studies.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"
#include "sears/sears_simulation.hpp"
#include "simulation/simulate_row.hpp"
#include "solver/row_solver.hpp"

namespace pound {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// One storey, m = 1e4 kg, k0 = 4e6 N/m, h = 3 m, with its gravity load P given.
Building sdof(double P, bool p_delta) {
  Building b;
  b.name = "sdof";
  b.masses = {1e4};
  b.stiffnesses = {4e6};
  b.storey_heights = {3.0};
  b.damping_ratio = 0.0;
  b.p_delta = p_delta;
  b.gravity_loads = {P};
  return b;
}

// The mean period of the up-crossings of zero of floor 0 in a history [s].
double period_of(const History& h) {
  std::vector<double> up;
  for (std::size_t k = 1; k < h.t.size(); ++k) {
    const double a = h.u[k - 1](0), b = h.u[k](0);
    if (a < 0.0 && b >= 0.0) up.push_back(h.t[k - 1] + (h.t[k] - h.t[k - 1]) * (-a) / (b - a));
  }
  EXPECT_GE(up.size(), 5u);
  return (up.back() - up.front()) / double(up.size() - 1);
}

TEST(PDelta, AnElasticStoreysPeriodIsTOverSqrtOfOneMinusPOverK0H) {
  for (double ratio : {0.2, 0.5, 0.8}) {  // P / (k0 h)
    const double P = ratio * 4e6 * 3.0;
    BuildingRow row;
    row.buildings = {sdof(P, true)};
    const AssembledRow a = assemble(row);
    const double T0 = 2.0 * M_PI * std::sqrt(1e4 / 4e6), T = T0 / std::sqrt(1.0 - ratio);
    RowProblem p;
    p.row = &a;
    p.u0 = Eigen::VectorXd::Constant(1, 0.01);
    p.t_end = 10.0 * T;
    p.record_history = true;
    IntegratorSettings s;
    s.h_max = T0 / 200.0;  // a fine sampling of the history for the zero crossings
    const RowResult r = solve(p, s);
    EXPECT_NEAR(period_of(r.history), T, 1e-6 * T) << ratio;
    // The damped Sears path's Newmark steps: period error (w h)^2 / 12 at h = T0 / 200.
    sears::SearsRowProblem q;
    q.row = &row;
    q.u0 = p.u0;
    q.v0 = Eigen::VectorXd::Zero(1);
    q.t_end = p.t_end;
    q.record_history = true;
    sears::SearsRowModel model;
    model.slabs.assign(1, sears::FloorSlabProperties{1.0, 2e11, 7850, 0.3});
    model.dt_s = T0 / 400.0;
    const sears::SearsRowResult rs = sears::solve_sears_row(q, model);
    EXPECT_NEAR(period_of(rs.row.history), T, 2e-4 * T) << ratio;
  }
}

TEST(PDelta, AStoreyThatCannotCarryItsGravityLoadIsRefusedNamingIt) {
  Building b = sdof(4e6 * 3.0 * 1.01, true);  // P / h > k0
  try {
    validate(b, "study.ini:[building1]");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("study.ini:[building1]: storey 1 cannot carry its gravity load with P-Delta"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("must exceed P / h = 4.04e+06 N/m"), std::string::npos) << m;
  }
  b.p_delta = false;  // without P-Delta the same load is no problem
  EXPECT_NO_THROW(validate(b, "x"));
  Building t = sdof(1e5, false);
  t.damping_stiffness = DampingStiffness::tangent;
  t.hysteresis = "bouc-wen";
  t.yield_shears = {1e5};
  EXPECT_THROW(validate(t, "x"), InputError);  // tangent damping needs a piecewise-linear law
  t.hysteresis = "bilinear";
  t.damping = DampingKind::modal;
  EXPECT_THROW(validate(t, "x"), InputError);  // and Rayleigh damping
}

// The chapter 8 pair with imk storeys and P-Delta under El Centro x `scale`, lumped (hc-linear)
// and damped Sears.
struct Pair {
  RowSimulation lumped;
  sears::SearsRowSimulation sears;
};
Pair run_pair(double scale, double collapse, std::vector<std::string> extra = {}) {
  // The base keys, each replaced by a later one of `extra`.
  std::vector<std::string> base = {"--building1.hysteresis",  "imk",
                                   "--building2.hysteresis",  "imk",
                                   "--building1.p_delta",     "true",
                                   "--building2.p_delta",     "true",
                                   "--motion.duration",       "8",
                                   "--simulation.extra_time", "1"},
                           args;
  for (std::size_t k = 0; k < base.size(); k += 2) {
    bool replaced = false;
    for (std::size_t j = 0; j < extra.size(); j += 2) replaced = replaced || extra[j] == base[k];
    if (!replaced) args.insert(args.end(), {base[k], base[k + 1]});
  }
  args.insert(args.end(), extra.begin(), extra.end());
  args.insert(args.end(), {"--motion.scale", std::to_string(scale)});
  const test::StudyRun s = test::read_study("ch8-yielding.ini", args);
  RowSimulationOptions o;
  o.extra_time = 1.0;
  o.track_energy = true;
  o.collapse_drift_ratio = collapse;
  ContactSpec contact;
  contact.model = "hc-linear";
  contact.params.e = 0.65;
  contact.params.k = 30 * 8.4e7;
  return {simulate_row(s.row, s.motion, contact, IntegratorSettings{}, o),
          sears::simulate_sears_row(s.row, s.motion, s.model, o)};
}

TEST(PDelta, TheEnergyBalanceClosesWithDeterioratingStoreysAndPoundingInBothSolvers) {
  const Pair p = run_pair(1.5, kInf);
  for (const RowResult* r : {&p.lumped.pounding, &p.lumped.free}) {
    EXPECT_LT(std::fabs(r->energy.residual()), 1e-7 * r->energy.input);
    EXPECT_LT(r->energy.strain, r->energy.strain + 1.0);  // finite
  }
  for (const RowResult* r : {&p.sears.base.pounding, &p.sears.base.free})
    EXPECT_LT(std::fabs(r->energy.residual()), 1e-5 * r->energy.input);
  EXPECT_GT(p.lumped.sites[0].impacts, 0);
  EXPECT_GT(p.sears.base.sites[0].impacts, 0);
  // P-Delta draws the buildings further than without it (the same record and storeys).
  const Pair q =
      run_pair(1.5, kInf, {"--building1.p_delta", "false", "--building2.p_delta", "false"});
  EXPECT_GT(p.lumped.floors[0].peak_drift_ratio_free, q.lumped.floors[0].peak_drift_ratio_free);
  EXPECT_GT(p.sears.base.floors[0].peak_drift_ratio_free,
            q.sears.base.floors[0].peak_drift_ratio_free);
}

void expect_same(const RowResult& a, const RowResult& b) {
  EXPECT_EQ(a.peak_disp, b.peak_disp);
  EXPECT_EQ(a.peak_drift, b.peak_drift);
  EXPECT_EQ(a.peak_abs_accel, b.peak_abs_accel);
  EXPECT_EQ(a.u_end, b.u_end);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.energy.residual(), b.energy.residual());
}

TEST(Collapse, ARunThatDoesNotCollapseIsUnchangedByTheKey) {
  const Pair a = run_pair(1.5, kInf), b = run_pair(1.5, 0.1);
  for (const auto* c : {&b.lumped.collapse_pounding, &b.lumped.collapse_free,
                        &b.sears.base.collapse_pounding, &b.sears.base.collapse_free}) {
    ASSERT_EQ(c->size(), 2u);
    for (const auto& x : *c) EXPECT_FALSE(x.collapsed);
  }
  expect_same(a.lumped.pounding, b.lumped.pounding);
  expect_same(a.lumped.free, b.lumped.free);
  expect_same(a.sears.base.pounding, b.sears.base.pounding);
  expect_same(a.sears.base.free, b.sears.base.free);
}

// The drift of floor DOF i's storey in history entry k [m].
double drift(const History& h, std::size_t k, int i, int below) {
  return h.u[k](i) - (below >= 0 ? h.u[k](below) : 0.0);
}

TEST(Collapse, ARunThatCollapsesStopsThereAndSaysWhichBuildingWhenAndWhere) {
  const double limit = 0.025;  // a 2.5 % drift ratio: El Centro x 3 reaches 3.4 %
  const test::StudyRun s = test::read_study(
      "ch8-yielding.ini", {"--building1.hysteresis", "imk", "--building2.hysteresis", "imk",
                           "--motion.scale", "3", "--motion.duration", "8"});
  const AssembledRow a = assemble(s.row);
  ContactSpec contact;
  contact.model = "hc-linear";
  contact.params.e = 0.65;
  contact.params.k = 30 * 8.4e7;
  RowSimulationOptions o;
  o.record_history = true;
  o.track_energy = true;
  o.collapse_drift_ratio = limit;
  const RowSimulation lumped = simulate_row(s.row, s.motion, contact, IntegratorSettings{}, o);
  const sears::SearsRowSimulation sears = sears::simulate_sears_row(s.row, s.motion, s.model, o);
  for (const RowSimulation* r : {&lumped, &sears.base}) {
    const RowResult& pr = r->pounding;
    ASSERT_TRUE(pr.stopped);
    ASSERT_EQ(r->collapse_pounding.size(), 2u);
    int collapsed = -1;
    for (int b = 0; b < 2; ++b)
      if (r->collapse_pounding[b].collapsed) collapsed = b;
    ASSERT_GE(collapsed, 0);
    const BuildingCollapse& c = r->collapse_pounding[collapsed];
    EXPECT_EQ(c.cause, CollapseCause::drift);
    // The run stops in the step where the drift passed the limit, at that step's end.
    EXPECT_LT(pr.t_end, s.motion.duration());
    EXPECT_LE(c.time, pr.t_end);
    const int i = a.offset[collapsed] + c.storey - 1;
    const int below = c.storey > 1 ? i - 1 : -1;
    const double h = s.row.buildings[collapsed].storey_heights[c.storey - 1];
    const History& hist = pr.history;
    const std::size_t last = hist.t.size() - 1;
    EXPECT_EQ(hist.t[last], pr.t_end);
    EXPECT_GT(std::fabs(drift(hist, last, i, below)), limit * h);
    EXPECT_GT(c.time, hist.t[last - 1]);
    EXPECT_LT(std::fabs(drift(hist, last - 1, i, below)), limit * h);
    EXPECT_GE(pr.peak_drift(i), limit * h);
    // Every building's residual drift is unknown after a stop.
    for (const FloorResponse& f : r->floors)
      EXPECT_TRUE(std::isnan(f.residual_drift_ratio_pounding));
    // The energy balance holds up to the stop.
    EXPECT_LT(std::fabs(pr.energy.residual()), 1e-5 * pr.energy.input);
  }
  // The free run holds a collapsed building still and goes on with the other to the end; the
  // two solvers agree on when and where the free buildings collapse.
  for (int b = 0; b < 2; ++b) {
    const BuildingCollapse &x = lumped.collapse_free[b], &y = sears.base.collapse_free[b];
    EXPECT_EQ(x.collapsed, y.collapsed) << b;
    if (!x.collapsed) continue;
    EXPECT_EQ(x.storey, y.storey) << b;
    EXPECT_NEAR(x.time, y.time, 0.02) << b;
  }
  if (!(lumped.collapse_free[0].collapsed && lumped.collapse_free[1].collapsed)) {
    EXPECT_DOUBLE_EQ(lumped.free.t_end, s.motion.duration());
  }
}

TEST(Collapse, AStoreyThatFailsUnderItsPDeltaLoadCollapsesItsBuilding) {
  // A short post-capping branch and no residual strength: the first storeys fail before they
  // pass the drift limit.
  const std::vector<std::string> fail = {
      "--building1.post_cap_drift_ratio", "0.02", "--building2.post_cap_drift_ratio", "0.02",
      "--building1.plastic_drift_ratio",  "0.01", "--building2.plastic_drift_ratio",  "0.01"};
  const Pair p = run_pair(4.0, 0.5, fail);
  bool failed = false;
  for (const auto* c : {&p.lumped.collapse_free, &p.sears.base.collapse_free})
    for (const auto& x : *c) failed = failed || x.cause == CollapseCause::failed_storey;
  EXPECT_TRUE(failed);
}

TEST(TangentDamping, AnElasticRowIsUnchangedAndAYieldingOneDissipatesLessInDampersInBothSolvers) {
  const std::vector<std::string> tangent = {"--building1.damping_stiffness", "tangent",
                                            "--building2.damping_stiffness", "tangent"};
  const Pair i = run_pair(1.5, kInf), t = run_pair(1.5, kInf, tangent);
  for (const auto* pr : {&t.lumped.pounding, &t.lumped.free})
    EXPECT_LT(std::fabs(pr->energy.residual()), 1e-7 * pr->energy.input);
  for (const auto* pr : {&t.sears.base.pounding, &t.sears.base.free})
    EXPECT_LT(std::fabs(pr->energy.residual()), 1e-5 * pr->energy.input);
  // Yielding storeys (tangent b k0 or less) damp less than with k0.
  EXPECT_LT(t.lumped.free.energy.damping / t.lumped.free.energy.input,
            i.lumped.free.energy.damping / i.lumped.free.energy.input);
  EXPECT_LT(t.sears.base.free.energy.damping / t.sears.base.free.energy.input,
            i.sears.base.free.energy.damping / i.sears.base.free.energy.input);
  // The two solvers integrate the same model: their free runs agree.
  for (std::size_t k = 0; k < t.lumped.floors.size(); ++k)
    EXPECT_NEAR(t.lumped.floors[k].peak_drift_ratio_free,
                t.sears.base.floors[k].peak_drift_ratio_free,
                2e-3 * t.lumped.floors[k].peak_drift_ratio_free)
        << k;
  // Elastic storeys: tangent = initial, bit for bit.
  const std::vector<std::string> elastic = {"--building1.hysteresis", "elastic",
                                            "--building2.hysteresis", "elastic"};
  std::vector<std::string> et = elastic;
  et.insert(et.end(), tangent.begin(), tangent.end());
  const Pair e = run_pair(1.0, kInf, elastic), f = run_pair(1.0, kInf, et);
  expect_same(e.lumped.free, f.lumped.free);
  expect_same(e.sears.base.free, f.sears.base.free);
}

}  // namespace
}  // namespace pound

#include "solver/row_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/allocation_counter.hpp"
#include "../support/buildings.hpp"
#include "contact/registry.hpp"
#include "motion/motion_reader.hpp"

namespace pound {
namespace {

// One SDOF building: m = 10 kg, k = 4000 N/m (w = 20 rad/s), damping ratio xi.
BuildingRow sdof(double xi) {
  Building b;
  b.masses = {10.0};
  b.stiffnesses = {4000.0};
  b.storey_heights = {3.0};
  b.damping_ratio = xi;
  BuildingRow row;
  row.buildings = {b};
  return row;
}

// Free vibration from u0 (Chopra eq. 2.2.4).
double free_vibration(double t, double u0, double w, double xi) {
  const double wd = w * std::sqrt(1 - xi * xi);
  return u0 * std::exp(-xi * w * t) *
         (std::cos(wd * t) + xi / std::sqrt(1 - xi * xi) * std::sin(wd * t));
}

TEST(RowSolver, SdofFreeVibrationMatchesClosedForm) {
  const AssembledRow a = assemble(sdof(0.05));
  RowProblem p;
  p.row = &a;
  p.u0 = Eigen::VectorXd::Constant(1, 0.01);
  p.t_end = 2.0;
  IntegratorSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-13;
  const RowResult r = solve(p, s);
  EXPECT_NEAR(r.u_end(0), free_vibration(2.0, 0.01, 20.0, 0.05), 1e-10);
  // The peak |u| is the initial displacement; damping only lowers later peaks.
  EXPECT_NEAR(r.peak_disp(0), 0.01, 1e-15);
}

TEST(RowSolver, PeakOfUndampedOscillationIsFoundBetweenSteps) {
  // Released from rest at u = 0 with v = 1 m/s: peak |u| = v / w = 0.05 m at t = pi/40 s,
  // between the steps the solver takes; the Hermite refinement finds it.
  const AssembledRow a = assemble(sdof(0.0));
  RowProblem p;
  p.row = &a;
  p.v0 = Eigen::VectorXd::Constant(1, 1.0);
  p.t_end = 0.2;
  IntegratorSettings s;
  s.control = StepControl::fixed;
  s.dt = 0.013;  // ~ T / 24, steps never hit the peak
  const RowResult r = solve(p, s);
  EXPECT_NEAR(r.peak_disp(0), 0.05, 1e-6);
}

TEST(RowSolver, SdofStepGroundAccelerationMatchesClosedForm) {
  // ag = a0 for t >= 0 (piecewise linear, so represented exactly): the response is the
  // step-force response of Chopra eq. 4.3.2 with p0 = -m a0.
  const double a0 = 2.0, w = 20.0, xi = 0.05, wd = w * std::sqrt(1 - xi * xi);
  GroundMotion g;
  g.dt = 0.01;
  g.accel.assign(301, a0);
  const AssembledRow a = assemble(sdof(xi));
  RowProblem p;
  p.row = &a;
  const RowGround p_ground = RowGround::uniform(g, static_cast<int>(p.row->offset.size()));
  p.ground = &p_ground;
  p.t_end = g.duration();
  IntegratorSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-13;
  const RowResult r = solve(p, s);
  const double t = 3.0;
  const double ust = -a0 / (w * w);
  const double exact =
      ust * (1 - std::exp(-xi * w * t) *
                     (std::cos(wd * t) + xi / std::sqrt(1 - xi * xi) * std::sin(wd * t)));
  EXPECT_NEAR(r.u_end(0), exact, 1e-10);
  // The first peak is the overshoot ust (1 + exp(-xi pi / sqrt(1 - xi^2))).
  EXPECT_NEAR(r.peak_disp(0), -ust * (1 + std::exp(-xi * M_PI / std::sqrt(1 - xi * xi))), 1e-9);
}

TEST(RowSolver, FixedStepConvergesAtFifthOrder) {
  const AssembledRow a = assemble(sdof(0.05));
  RowProblem p;
  p.row = &a;
  p.u0 = Eigen::VectorXd::Constant(1, 0.01);
  p.t_end = 1.0;
  const double exact = free_vibration(1.0, 0.01, 20.0, 0.05);
  double err[3];
  const double dts[3] = {0.02, 0.01, 0.005};
  for (int i = 0; i < 3; ++i) {
    IntegratorSettings s;
    s.control = StepControl::fixed;
    s.dt = dts[i];
    err[i] = std::fabs(solve(p, s).u_end(0) - exact);
  }
  const double order1 = std::log2(err[0] / err[1]), order2 = std::log2(err[1] / err[2]);
  std::printf("observed orders %.3f %.3f\n", order1, order2);
  EXPECT_GT(order1, 4.6);
  EXPECT_GT(order2, 4.6);
  EXPECT_LT(order2, 5.6);
}

TEST(RowSolver, ModalDampingDecaysAHigherModeAtItsOwnRatio) {
  // Three storeys with modal damping (C full, not tridiagonal): released in the third mode
  // shape, the response stays in that mode and decays with ratio xi at w3 (Chopra eq. 2.2.4).
  // This needs every entry of C; Rayleigh damping would give mode 3 a larger ratio.
  Building b;
  b.masses = {2e4, 2e4, 1.5e4};
  b.stiffnesses = {3e7, 2.5e7, 2e7};
  b.storey_heights = {3.0, 3.0, 3.0};
  b.damping_ratio = 0.05;
  b.damping = DampingKind::modal;
  BuildingRow row;
  row.buildings = {b};
  const AssembledRow a = assemble(row);
  ASSERT_NE(a.C(0, 2), 0.0);
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(a.K, a.M);
  const double w3 = std::sqrt(eig.eigenvalues()(2));
  const Eigen::VectorXd phi = eig.eigenvectors().col(2);
  RowProblem p;
  p.row = &a;
  p.u0 = 0.01 * phi / phi.cwiseAbs().maxCoeff();  // [m]
  p.t_end = 0.5;
  IntegratorSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-13;
  const RowResult r = solve(p, s);
  const double q = free_vibration(0.5, 1.0, w3, 0.05);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(r.u_end(i), p.u0(i) * q, 1e-10) << i;
}

// Two SDOF buildings side by side with a gap.
BuildingRow pair(double gap, double k2 = 2500.0) {
  BuildingRow row = sdof(0.05);
  Building b2 = row.buildings[0];
  b2.stiffnesses = {k2};
  row.buildings.push_back(b2);
  row.gaps = {{gap}};
  return row;
}

GroundMotion pulse() {
  GroundMotion g;
  g.dt = 0.01;
  for (int i = 0; i <= 300; ++i)
    g.accel.push_back(3.0 * std::sin(2 * M_PI * i * g.dt / 0.4) * (i < 100));
  return g;
}

TEST(RowSolver, WideGapGivesNoImpactsAndIdenticalResponse) {
  const AssembledRow a = assemble(pair(1.0));
  const GroundMotion g = pulse();
  ContactParameters cp;
  cp.k = 1e6;
  cp.e = 0.5;
  cp.m1 = cp.m2 = 10.0;
  const auto law = find_contact_model("hc-linear", "t").make(cp);
  RowProblem p;
  p.row = &a;
  const RowGround p_ground = RowGround::uniform(g, static_cast<int>(p.row->offset.size()));
  p.ground = &p_ground;
  p.t_end = g.duration();
  const RowResult free = solve(p, {});
  p.laws = {law.get()};
  const RowResult pound = solve(p, {});
  EXPECT_EQ(pound.sites[0].impacts, 0);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(pound.peak_disp(i), free.peak_disp(i));  // bit for bit
    EXPECT_EQ(pound.peak_abs_accel(i), free.peak_abs_accel(i));
  }
}

TEST(RowSolver, IdenticalBuildingsNeverCollide) {
  const AssembledRow a = assemble(pair(0.0, 4000.0));
  const GroundMotion g = pulse();
  ContactParameters cp;
  cp.k = 1e6;
  cp.e = 0.5;
  cp.m1 = cp.m2 = 10.0;
  const auto law = find_contact_model("lve", "t").make(cp);
  RowProblem p;
  p.row = &a;
  const RowGround p_ground = RowGround::uniform(g, static_cast<int>(p.row->offset.size()));
  p.ground = &p_ground;
  p.t_end = g.duration();
  p.laws = {law.get()};
  const RowResult r = solve(p, {});
  EXPECT_EQ(r.sites[0].impacts, 0);
  EXPECT_EQ(r.u_end(0), r.u_end(1));
}

TEST(RowSolver, PoundingConservesMomentumWithoutSpringsOrGround) {
  // Row of three free masses (stiffness-free "buildings"), the first moving: momentum after
  // the cascade of impacts equals the initial momentum.
  AssembledRow a;
  a.M = Eigen::Vector3d(1.0, 2.0, 1.5).asDiagonal();
  a.C = a.K = Eigen::MatrixXd::Zero(3, 3);
  a.inv_mass = a.M.diagonal().cwiseInverse();
  a.offset = {0, 1, 2};
  a.sites = {floor_site(a, 0, 0, 0, 1, 0.001), floor_site(a, 1, 0, 1, 2, 0.002)};
  for (const auto& m : contact_models()) {
    ContactParameters cp;
    cp.k = m.stiffness_unit == "N/m^1.5" ? 1e9 : 1e6;
    cp.e = 0.5;
    cp.m1 = cp.m2 = 1.0;
    const auto l1 = m.make(cp), l2 = m.make(cp);
    RowProblem p;
    p.row = &a;
    p.laws = {l1.get(), l2.get()};
    p.v0 = Eigen::Vector3d(1.0, 0.0, 0.0);
    p.t_end = 0.1;
    const RowResult r = solve(p, {});
    EXPECT_NEAR(a.M.diagonal().dot(r.v_end), 1.0, 1e-12) << m.name;
    EXPECT_GE(r.sites[1].impacts, 1) << m.name;
  }
}

TEST(RowSolver, TimeLoopDoesNotAllocate) {
  // Issue 8: the time loop is allocation-free. Two SDOF buildings with a zero gap (k = 2500 and
  // 4000 N/m, different periods: they pound throughout) under 2 s and 20 s of sinusoidal
  // shaking, hc-linear contacts: the longer run makes thousands more steps and contact events
  // and must not allocate more.
  const AssembledRow a = assemble(pair(0.0));
  ContactParameters cp;
  cp.k = 1e6;
  cp.e = 0.5;
  cp.m1 = cp.m2 = 10.0;
  const auto law = find_contact_model("hc-linear", "t").make(cp);
  auto run = [&](double seconds, long& steps, long& events) {
    GroundMotion g;
    g.dt = 0.01;
    for (int i = 0; i * g.dt <= seconds; ++i)
      g.accel.push_back(3.0 * std::sin(2 * M_PI * i * g.dt / 0.4));
    RowProblem p;
    p.row = &a;
    const RowGround p_ground = RowGround::uniform(g, static_cast<int>(p.row->offset.size()));
    p.ground = &p_ground;
    p.t_end = g.duration();
    p.laws = {law.get()};
    test::CountAllocations c;
    const RowResult r = solve(p, {});
    steps = r.steps + r.rejected;
    events = r.events;
    return c.count();
  };
  long steps2 = 0, steps20 = 0, events2 = 0, events20 = 0;
  const long a2 = run(2.0, steps2, events2), a20 = run(20.0, steps20, events20);
  ASSERT_GT(steps20 - steps2, 4000);
  ASSERT_GT(events20 - events2, 50);
  EXPECT_GT(a2, 0);  // the counter works: set-up allocates
  EXPECT_EQ(a20, a2) << steps2 << " and " << steps20 << " steps";
}

// solve_free_and_pounding against the two runs solved apart: the chapter 8 pair (elastic, or
// with bilinear storeys yielding at a base-shear coefficient of about 0.2) under the first 6 s
// of El Centro with `gap` at its three sites, hc-linear contacts, histories recorded.
struct ForkedRuns {
  RunPair pair;
  RowResult free, pounding;  // solve() of each
};
ForkedRuns forked_and_apart(double gap, bool yielding) {
  BuildingRow row = test::chapter8_pair(gap);
  if (yielding) {
    row.buildings[0].hysteresis = row.buildings[1].hysteresis = "bilinear";
    row.buildings[0].yield_shears.assign(5, 4.5e5);
    row.buildings[1].yield_shears.assign(3, 1.7e5);
  }
  const AssembledRow a = assemble(row);
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  GroundMotion g = read_motion(spec);
  g.accel.resize(static_cast<std::size_t>(6.0 / g.dt) + 1);
  ContactParameters cp;
  cp.k = 50 * 8.4e7;
  cp.e = 0.6;
  cp.m1 = 48e3;
  cp.m2 = 29e3;
  const auto law = find_contact_model("hc-linear", "t").make(cp);
  RowProblem p;
  p.row = &a;
  const RowGround p_ground = RowGround::uniform(g, static_cast<int>(p.row->offset.size()));
  p.ground = &p_ground;
  p.t_end = g.duration() + 1.0;
  p.record_history = true;
  p.laws.assign(a.sites.size(), law.get());
  ForkedRuns out;
  out.pair = solve_free_and_pounding(p, {});
  out.pounding = solve(p, {});
  p.laws.clear();
  out.free = solve(p, {});
  return out;
}

void expect_same_run(const RowResult& x, const RowResult& y, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(x.steps, y.steps);
  EXPECT_EQ(x.rejected, y.rejected);
  EXPECT_EQ(x.events, y.events);
  EXPECT_EQ(x.exact_steps, y.exact_steps);
  for (int i = 0; i < x.peak_disp.size(); ++i) {  // bit for bit
    EXPECT_EQ(x.peak_disp(i), y.peak_disp(i)) << i;
    EXPECT_EQ(x.peak_drift(i), y.peak_drift(i)) << i;
    EXPECT_EQ(x.peak_abs_accel(i), y.peak_abs_accel(i)) << i;
    EXPECT_EQ(x.u_end(i), y.u_end(i)) << i;
  }
  ASSERT_EQ(x.sites.size(), y.sites.size());
  for (std::size_t k = 0; k < x.sites.size(); ++k) {
    const SiteResult &a = x.sites[k], &b = y.sites[k];
    EXPECT_EQ(a.impacts, b.impacts) << k;
    EXPECT_EQ(a.peak_force, b.peak_force) << k;
    EXPECT_EQ(a.peak_penetration, b.peak_penetration) << k;
    EXPECT_EQ(a.impulse, b.impulse) << k;
    EXPECT_EQ(a.first_contact, b.first_contact) << k;
    EXPECT_EQ(a.last_separation, b.last_separation) << k;
    EXPECT_EQ(std::isnan(a.peak_approach), std::isnan(b.peak_approach)) << k;
    if (!std::isnan(a.peak_approach)) {
      EXPECT_EQ(a.peak_approach, b.peak_approach) << k;
    }
  }
  ASSERT_EQ(x.history.t.size(), y.history.t.size());
  for (std::size_t j = 0; j < x.history.t.size(); ++j) {
    ASSERT_EQ(x.history.t[j], y.history.t[j]) << j;
    ASSERT_EQ(x.history.u[j], y.history.u[j]) << j;
    ASSERT_EQ(x.history.force[j], y.history.force[j]) << j;
  }
}

TEST(RowSolver, PoundingRunForkedFromTheFreeRunIsItsOwnSolveBitForBit) {
  // Contacts from about 2 s on (elastic and yielding storeys): the pounding run continues from
  // the free run's state shortly before the first contact, and both runs are those solved apart.
  for (const bool yielding : {false, true}) {
    SCOPED_TRACE(yielding ? "bilinear storeys" : "elastic storeys");
    const ForkedRuns r = forked_and_apart(0.01, yielding);
    double first = 1e9;
    for (const auto& s : r.pounding.sites)
      if (s.first_contact >= 0) first = std::min(first, s.first_contact);
    ASSERT_GT(first, 1.0);
    ASSERT_LT(first, 5.0);
    expect_same_run(r.pair.free, r.free, "free");
    expect_same_run(r.pair.pounding, r.pounding, "pounding");
    // The shared part: the free run's steps up to shortly before the first contact.
    EXPECT_EQ(r.pounding.steps_from_free, 0);
    EXPECT_GT(r.pair.pounding.steps_from_free, 0.9 * first / 3.34e-3);
    long before = 0;
    for (double t : r.pounding.history.t) before += t < first;
    EXPECT_LT(r.pair.pounding.steps_from_free, before);
  }
}

TEST(RowSolver, ForkedPoundingRunWithoutContactIsTheFreeRun) {
  // A gap no motion closes: one run serves both; a zero gap touches at t = 0: no fork, the
  // pounding run is solved from the start.
  const ForkedRuns wide = forked_and_apart(0.5, true);
  expect_same_run(wide.pair.free, wide.free, "wide, free");
  expect_same_run(wide.pair.pounding, wide.pounding, "wide, pounding");
  EXPECT_EQ(wide.pair.pounding.steps_from_free, wide.pair.pounding.steps);
  for (const auto& s : wide.pair.pounding.sites) EXPECT_EQ(s.impacts, 0);
  const ForkedRuns zero = forked_and_apart(0.0, false);
  expect_same_run(zero.pair.free, zero.free, "zero, free");
  expect_same_run(zero.pair.pounding, zero.pounding, "zero, pounding");
  EXPECT_EQ(zero.pair.pounding.steps_from_free, 0);
  EXPECT_GT(zero.pair.pounding.sites[0].impacts, 10);
}

}  // namespace
}  // namespace pound

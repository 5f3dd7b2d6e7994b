#include "solver/row_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "../support/allocation_counter.hpp"
#include "contact/registry.hpp"

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
  p.motion = &g;
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
  p.motion = &g;
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
  p.motion = &g;
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
  a.sites = {ContactSite{0, 0, 0, 1, 0.001}, ContactSite{1, 0, 1, 2, 0.002}};
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
    p.motion = &g;
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

}  // namespace
}  // namespace pound

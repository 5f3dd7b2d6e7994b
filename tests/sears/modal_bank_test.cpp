// The exact piecewise-linear recurrence of the internal modes (Chopra, Dynamics of Structures,
// sec. 5.2) and the modal bank built on it.
#include "sears/modal_bank.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pound::sears {
namespace {

// Chopra Table 5.2.1, closed forms for a unit-mass oscillator (k = w^2), xi < 1.
RecurrenceCoefficients chopra_table_5_2_1(double w, double xi, double dt) {
  const double wd = w * std::sqrt(1.0 - xi * xi), r = xi / std::sqrt(1.0 - xi * xi);
  const double e = std::exp(-xi * w * dt), s = std::sin(wd * dt), c = std::cos(wd * dt);
  const double k = w * w;
  RecurrenceCoefficients o;
  o.A = e * (r * s + c);
  o.B = e * s / wd;
  o.C = (2 * xi / (w * dt) +
         e * (((1 - 2 * xi * xi) / (wd * dt) - r) * s - (1 + 2 * xi / (w * dt)) * c)) /
        k;
  o.D =
      (1 - 2 * xi / (w * dt) + e * ((2 * xi * xi - 1) / (wd * dt) * s + 2 * xi / (w * dt) * c)) / k;
  o.Av = -e * w / std::sqrt(1.0 - xi * xi) * s;
  o.Bv = e * (c - r * s);
  o.Cv = (-1 / dt + e * ((w / std::sqrt(1 - xi * xi) + r / dt) * s + c / dt)) / k;
  o.Dv = (1 - e * (r * s + c)) / (k * dt);
  return o;
}

TEST(SearsRecurrence, CoefficientsEqualChoprasClosedForms) {
  for (double xi : {0.0, 0.05, 0.3})
    for (double wdt : {0.05, 0.3, 1.0, 3.0}) {
      const double w = 2000.0, dt = wdt / w;
      const auto a = recurrence_coefficients(w, xi, dt), b = chopra_table_5_2_1(w, xi, dt);
      const double tol = 1e-9;
      EXPECT_NEAR(a.A, b.A, tol * std::fabs(b.A) + 1e-14);
      EXPECT_NEAR(a.B, b.B, tol * std::fabs(b.B));
      EXPECT_NEAR(a.C, b.C, tol * std::fabs(b.C));
      EXPECT_NEAR(a.D, b.D, tol * std::fabs(b.D));
      EXPECT_NEAR(a.Av, b.Av, tol * std::fabs(b.Av));
      EXPECT_NEAR(a.Bv, b.Bv, tol * std::fabs(b.Bv) + 1e-14);
      EXPECT_NEAR(a.Cv, b.Cv, tol * std::fabs(b.Cv));
      EXPECT_NEAR(a.Dv, b.Dv, tol * std::fabs(b.Dv));
    }
}

TEST(SearsRecurrence, SmallStepsKeepTheTaylorLimit) {
  // For w dt -> 0 the load coefficients tend to C = dt^2/3, D = dt^2/6, C' = D' = dt/2; the
  // closed forms lose every digit there (terms of size 2 xi/(w^3 dt) cancel), this must not.
  const double w = 1.0, dt = 1e-6, xi = 0.05;
  const auto c = recurrence_coefficients(w, xi, dt);
  EXPECT_NEAR(c.C / (dt * dt), 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(c.D / (dt * dt), 1.0 / 6.0, 1e-6);
  EXPECT_NEAR(c.Cv / dt, 0.5, 1e-6);
  EXPECT_NEAR(c.Dv / dt, 0.5, 1e-6);
}

TEST(SearsRecurrence, RampLoadIsIntegratedExactlyAtAnyStep) {
  // q'' + w^2 q = r t from rest: q = (r / w^2) (t - sin(w t) / w). Step w dt = 1.3.
  const double w = 500.0, r = 7.0, dt = 1.3 / w, xi = 0.0;
  const auto c = recurrence_coefficients(w, xi, dt);
  double q = 0.0, v = 0.0;
  for (int i = 0; i < 50; ++i) {
    const double f0 = r * i * dt, f1 = r * (i + 1) * dt;
    const double qn = c.A * q + c.B * v + c.C * f0 + c.D * f1;
    v = c.Av * q + c.Bv * v + c.Cv * f0 + c.Dv * f1;
    q = qn;
  }
  const double t = 50 * dt;
  const double exact_q = r / (w * w) * (t - std::sin(w * t) / w);
  const double exact_v = r / (w * w) * (1.0 - std::cos(w * t));
  EXPECT_NEAR(q, exact_q, 1e-12 * std::fabs(exact_q));
  EXPECT_NEAR(v, exact_v, 1e-10 * r / (w * w));
}

Slab test_bar() {
  return Slab{1.0, 200e9, 7850.0, 0.3, 7850.0 * 1.0 * 0.01, 1.0};
}

TEST(SearsModalBank, FlexibilityIsTheFaceResponseToAUnitEndOfStepLoad) {
  ModalBank bank(test_bar(), 50, 0.05, 1e-6);
  const auto pred = bank.predict(EndLoads{0.0, 0.0});
  bank.step(EndLoads{0.0, 0.0}, EndLoads{1.0, 0.0});  // 1 N at x = 0 at the end of the step
  const auto u = bank.displacement();
  EXPECT_DOUBLE_EQ(pred.left, 0.0);
  EXPECT_NEAR(u.left, bank.flexibility().same, 1e-12 * bank.flexibility().same);
  EXPECT_NEAR(u.right, bank.flexibility().cross, 1e-12 * std::fabs(bank.flexibility().same));
  // Prediction with a load at the start is the same update with a zero end load.
  const auto p2 = bank.predict(EndLoads{0.0, -3.0});
  ModalBank copy = bank;
  copy.step(EndLoads{0.0, -3.0}, EndLoads{0.0, 0.0});
  EXPECT_NEAR(copy.displacement().right, p2.right, 1e-15);
  EXPECT_NEAR(copy.displacement().left, p2.left, 1e-15);
}

TEST(SearsModalBank, ALongerStepIsTheFineStepsItSpansWhenTheLoadIsLinearOverIt) {
  // The recurrence is exact for a load linear over the step (Chopra sec. 5.2), so one step of
  // 3 dt (add_step) and three steps of dt give the same state when the end loads are linear
  // over the 3 dt, from any state; and a step may predict for a following step of another
  // length (next_pred by that length's recurrence).
  const double dt = 2e-6;
  ModalBank fine(test_bar(), 50, 0.05, dt);
  EXPECT_EQ(fine.add_step(3 * dt), 1);
  EXPECT_DOUBLE_EQ(fine.step_size(1), 3 * dt);
  EXPECT_GT(fine.flexibility(1).same, fine.flexibility(0).same);  // more time to deform
  ModalBank::StepResult r;
  fine.step(EndLoads{0.0, 0.0}, EndLoads{2e3, -1e3}, r);  // some internal vibration
  fine.step(EndLoads{2e3, -1e3}, EndLoads{-5e2, 0.0}, r);
  ModalBank coarse = fine;
  const EndLoads b{-5e2, 0.0}, e{4e3, 3e3};
  auto at = [&](double f) {
    return EndLoads{b.left_N + f * (e.left_N - b.left_N), b.right_N + f * (e.right_N - b.right_N)};
  };
  for (int j = 0; j < 3; ++j) fine.step(at(j / 3.0), at((j + 1) / 3.0), r, 0, j == 2 ? 1 : 0);
  ModalBank::StepResult rc;
  coarse.step(b, e, rc, 1);
  const SectionValues uf = fine.displacement(), uc = coarse.displacement();
  const SectionValues vf = fine.velocity(), vc = coarse.velocity();
  const double su = std::fabs(uc.left) + std::fabs(uc.right), sv = std::fabs(vc.left);
  ASSERT_GT(su, 0.0);
  EXPECT_NEAR(uf.left, uc.left, 1e-9 * su);
  EXPECT_NEAR(uf.right, uc.right, 1e-9 * su);
  EXPECT_NEAR(uf.centre, uc.centre, 1e-9 * su);
  EXPECT_NEAR(vf.left, vc.left, 1e-9 * sv);
  EXPECT_NEAR(vf.right, vc.right, 1e-9 * sv);
  // The last fine step predicted for a 3 dt step: predict(e, 1) of the state it reached.
  const SectionValues p = fine.predict(e, 1);
  EXPECT_NEAR(r.next_pred.left, p.left, 1e-12 * su);
  EXPECT_NEAR(r.next_pred.right, p.right, 1e-12 * su);
  EXPECT_GT(std::fabs(p.left - fine.predict(e, 0).left), 1e-3 * su);  // the lengths differ
}

TEST(SearsModalBank, StaticEndLoadGivesTheQuasiStaticStrainField) {
  // A constant force P pulling at x = l on a free bar with damping settles (relative to the
  // rigid body) to the quasi-static field of a uniformly accelerated bar,
  // w(x) = (P l / (E A)) [ (x/l)^2 / 2 - 1/6 ] measured from the mean; at the ends
  // w(l) - w(0) = P l / (2 E A).
  const Slab bar = test_bar();
  const double EA = bar.E_Pa * bar.area_m2(), P = 1e5;
  ModalBank bank(bar, 400, 0.5, bar.first_mode_period() / 50.0);
  for (int i = 0; i < 20000; ++i) bank.step(EndLoads{0.0, P}, EndLoads{0.0, P});
  const auto u = bank.displacement();
  EXPECT_NEAR(u.right - u.left, P * bar.length_m / (2.0 * EA), 2e-3 * P * bar.length_m / EA);
  EXPECT_NEAR(u.right, P * bar.length_m / EA / 3.0, 2e-3 * P * bar.length_m / EA);
}

TEST(SearsModalBank, FreeVibrationEnergyDecaysAtTheModalDampingRate) {
  // A single mode in free vibration: its energy envelope decays as exp(-2 xi w t).
  const Slab bar = test_bar();
  const double xi = 0.02, T = bar.first_mode_period();
  ModalBank bank(bar, 1, xi, T / 7.3);        // an arbitrary, coarse step: exact for free vibration
  bank.step(EndLoads{}, EndLoads{1e6, 0.0});  // kick
  const double e0 = bank.energy();
  // Sample at whole periods (T/7.3 * 73 = 10 T): energy ratio = exp(-2 xi w 10 T) exactly for
  // the same phase.
  for (int i = 0; i < 73; ++i) bank.step(EndLoads{}, EndLoads{});
  EXPECT_NEAR(bank.energy() / e0, std::exp(-2.0 * xi * bar.omega(1) * 10.0 * T), 1e-3);
  EXPECT_GT(bank.free_face_bound(), std::fabs(bank.displacement().left));
}

}  // namespace
}  // namespace pound::sears

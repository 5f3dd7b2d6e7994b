// The row solver with yielding storeys: elastic-perfectly-plastic closed forms, the observed
// order of the integration with located yield kinks, the energy balance with pounding for every
// storey law, and the elastic limit of a very large yield shear.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../support/buildings.hpp"
#include "../support/same_run.hpp"
#include "hysteresis/registry.hpp"
#include "motion/motion_reader.hpp"
#include "simulation/simulate_row.hpp"
#include "solver/row_solver.hpp"

namespace pound {
namespace {

// An undamped elastic-perfectly-plastic SDOF: m = 1000 kg, k = 1e6 N/m (w = 31.62 rad/s),
// Fy = 1e4 N (uy = 0.01 m).
constexpr double kM = 1000.0, kK = 1e6, kFy = 1e4;
BuildingRow epp_sdof() {
  Building b = test::uniform_building(1, kM, kK, 0.0);
  b.hysteresis = "bilinear";
  b.yield_shears = {kFy};
  b.hardening = {0.0};
  BuildingRow row;
  row.buildings = {b};
  return row;
}

// A force P(t) on the floor as the ground acceleration -P/m: constant P0 up to t_off, then
// falling linearly to zero over one record step `dt` (a record is piecewise linear).
GroundMotion force_record(double P0, double t_off, double dt, double duration) {
  GroundMotion g;
  g.dt = dt;
  const long off = std::lround(t_off / dt);
  for (long i = 0; i <= std::lround(duration / dt); ++i)
    g.accel.push_back(i <= off ? -P0 / kM : 0.0);
  return g;
}

RowResult solve_tight(const AssembledRow& a, const GroundMotion& g) {
  RowProblem p;
  p.row = &a;
  const RowGround p_ground = RowGround::uniform(g, static_cast<int>(p.row->offset.size()));
  p.ground = &p_ground;
  p.t_end = g.duration();
  IntegratorSettings s;
  s.rtol = 1e-11;
  s.atol = 1e-14;
  return solve(p, s);
}

// Step force P0 = 0.8 Fy from rest (Chopra, Dynamics of Structures, sec. 7.5 for the EPP
// system): elastic u = P0/k (1 - cos wt) to u = uy at w t1 = acos(1 - Fy/P0), then constant
// resisting force Fy: deceleration (Fy - P0)/m to the peak um = uy / (2 (1 - P0/Fy)) (work:
// P0 um = Fy uy / 2 + Fy (um - uy)) at t2 = t1 + v1 m / (Fy - P0); then elastic oscillation
// about up + P0/k, up = um - uy, with amplitude (Fy - P0)/k. Dissipated: Fy (um - uy).
struct StepForceSolution {
  double w, uy, t1, v1, t2, um, up, amp;
  explicit StepForceSolution(double P0) {
    w = std::sqrt(kK / kM);
    uy = kFy / kK;
    t1 = std::acos(1 - kFy / P0) / w;
    v1 = P0 / kK * w * std::sin(w * t1);
    t2 = t1 + v1 * kM / (kFy - P0);
    um = uy / (2 * (1 - P0 / kFy));
    up = um - uy;
    amp = (kFy - P0) / kK;
  }
  // Displacement for t >= t2 while the force stays on [m].
  double after_peak(double t) const { return up + 0.8 * kFy / kK + amp * std::cos(w * (t - t2)); }
};

TEST(Yielding, ElasticPerfectlyPlasticSdofUnderAStepForce) {
  const double P0 = 0.8 * kFy;
  const StepForceSolution x(P0);
  ASSERT_NEAR(x.um, 0.025, 1e-15);
  const AssembledRow a = assemble(epp_sdof());
  const GroundMotion g = force_record(P0, 10.0, 0.01, 1.0);
  const RowResult r = solve_tight(a, g);
  EXPECT_NEAR(r.peak_disp(0), x.um, 1e-9);
  EXPECT_NEAR(r.hysteretic_energy(0), kFy * x.up, 1e-6);  // 150 J
  EXPECT_NEAR(r.u_end(0), x.after_peak(1.0), 1e-9);
}

TEST(Yielding, ElasticPerfectlyPlasticSdofUnderARectangularPulse) {
  // The pulse of the step above, switched off at td = 0.3 s > t2 (the peak comes during the
  // pulse), falling to zero over one record step delta = 1 ms. Then free vibration about the
  // residual displacement up = um - uy = 0.015 m; no further yielding (amplitude < uy).
  const double P0 = 0.8 * kFy, td = 0.3, delta = 1e-3;
  const StepForceSolution x(P0);
  ASSERT_LT(x.t2, td);
  // State at td, then the exact response to the linear ramp P0 (1 - (t - td)/delta) of the
  // elastic system w'' + w^2 (u - up) = P/m over [td, td + delta].
  const double w0 = x.after_peak(td) - x.up;
  const double v0 = -x.amp * x.w * std::sin(x.w * (td - x.t2));
  const double C1 = w0 - P0 / kK, C2 = (v0 + P0 / (kK * delta)) / x.w;
  const double w1 = C1 * std::cos(x.w * delta) + C2 * std::sin(x.w * delta);
  const double v1 =
      -P0 / (kK * delta) + x.w * (-C1 * std::sin(x.w * delta) + C2 * std::cos(x.w * delta));
  const double amplitude = std::hypot(w1, v1 / x.w);
  ASSERT_LT(amplitude, x.uy);
  const double t_end = 1.0;
  const double tau = t_end - (td + delta);
  const double u_end = x.up + w1 * std::cos(x.w * tau) + v1 / x.w * std::sin(x.w * tau);

  const AssembledRow a = assemble(epp_sdof());
  const RowResult r = solve_tight(a, force_record(P0, td, delta, t_end));
  EXPECT_NEAR(r.peak_disp(0), x.um, 1e-9);
  EXPECT_NEAR(r.u_end(0), u_end, 1e-9);
  EXPECT_NEAR(r.hysteretic_energy(0) / kFy, x.up, 1e-10);  // the residual displacement
  // The residual the simulation reports (drift at the end, over the storey height) equals the
  // closed form's u(t_end).
  RowResult free = r;
  const RowSimulation sim = summarize_runs(epp_sdof(), RowGround(), t_end, free, r);
  EXPECT_NEAR(sim.floors[0].residual_drift_ratio_free, u_end / 3.0, 1e-9);
  EXPECT_NEAR(sim.floors[0].ductility_free, x.um / x.uy, 1e-7);
}

TEST(Yielding, LocatedYieldKinksKeepTheFifthOrderOfDormandPrince) {
  // A bilinear SDOF (T = 0.2 s, 2 % damping) shaken hard enough to yield in both directions
  // (13 kinks), integrated with fixed steps h = T/80, T/160, T/320 (the kinks located as
  // events) against T/5120: the error of the end state falls like h^5, as for the elastic
  // frame. Coarser steps are pre-asymptotic for the elastic frame as well (orders 1.7 and 3.4
  // from T/10 to T/40); a kink left inside a step would cost the order (h^2 per kink).
  for (double b : {0.05, 0.0}) {
    BuildingRow row = epp_sdof();
    row.buildings[0].hardening = {b};
    row.buildings[0].damping_ratio = 0.02;
    const AssembledRow a = assemble(row);
    GroundMotion g;
    g.dt = 0.01;
    for (int i = 0; i * g.dt <= 1.2; ++i)
      g.accel.push_back(25.0 * std::sin(2 * M_PI * i * g.dt / 0.35));
    RowProblem p;
    p.row = &a;
    const RowGround p_ground = RowGround::uniform(g, static_cast<int>(p.row->offset.size()));
    p.ground = &p_ground;
    p.t_end = g.duration();
    auto run = [&](double h) {
      IntegratorSettings s;
      s.control = StepControl::fixed;
      s.dt = h;
      return solve(p, s);
    };
    const double w = std::sqrt(kK / kM), T = 2 * M_PI / w;
    const RowResult ref = run(T / 5120);
    ASSERT_GT(ref.hysteretic_energy(0), 10 * kFy * kFy / kK);  // several yield excursions
    ASSERT_GE(ref.events, 10);
    std::vector<double> err;
    for (int div : {80, 160, 320}) {
      const RowResult r = run(T / div);
      EXPECT_EQ(r.events, ref.events);
      err.push_back(std::fabs(r.u_end(0) - ref.u_end(0)) +
                    std::fabs(r.v_end(0) - ref.v_end(0)) / w);
    }
    EXPECT_GT(std::log2(err[0] / err[1]), 4.0) << "b = " << b;
    EXPECT_GT(std::log2(err[1] / err[2]), 4.0) << "b = " << b;
    EXPECT_GT(std::log2(err[0] / err[2]) / 2, 4.5)
        << "b = " << b << ": errors " << err[0] << ", " << err[1] << ", " << err[2];
  }
}

// The chapter 8 pair under the first 8 s of El Centro and 2 s of free vibration, with
// pounding through `model`; yield shears for a base-shear coefficient of about 0.2.
RowSimulation chapter8(const std::string& law, const std::string& model, double gap,
                       double Fy_scale = 1.0, IntegratorSettings integ = {}, bool energy = true) {
  BuildingRow row = test::chapter8_pair(gap);
  row.buildings[0].hysteresis = row.buildings[1].hysteresis = law;
  row.buildings[0].yield_shears.assign(5, 4.5e5 * Fy_scale);
  row.buildings[1].yield_shears.assign(3, 1.7e5 * Fy_scale);
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  const GroundMotion g = read_motion(spec);
  GroundMotion g8 = g;
  g8.accel.resize(static_cast<std::size_t>(8.0 / g.dt) + 1);
  ContactSpec c;
  c.model = model;
  c.params.k = 50 * 8.4e7;
  c.params.e = 0.6;
  RowSimulationOptions o;
  o.extra_time = 2.0;
  o.track_energy = energy;
  return simulate_row(row, g8, c, integ, o);
}

TEST(Yielding, EnergyBalanceClosesWithPoundingForEveryLaw) {
  for (const auto& info : storey_laws()) {
    for (const char* model : {"hc-linear", "nlve"}) {
      const RowSimulation s = chapter8(info.name, model, 0.01);
      for (const RowResult* r : {&s.pounding, &s.free}) {
        const EnergyBalance& e = r->energy;
        EXPECT_GT(e.input, 1e4);
        EXPECT_LT(std::fabs(e.residual()), 1e-5 * e.input)
            << info.name << " " << model << ": input " << e.input << " J, residual " << e.residual()
            << " J";
        if (!info.law->linear()) {
          EXPECT_GT(e.hysteretic, 0.1 * e.input) << info.name;
        }
        if (info.law->linear()) {
          EXPECT_EQ(e.hysteretic, 0.0);
        }
      }
      int impacts = 0;
      for (const auto& site : s.sites) impacts += site.impacts;
      EXPECT_GT(impacts, 0) << info.name << " " << model;
      EXPECT_GT(s.pounding.energy.contact, 0.0) << info.name << " " << model;
      EXPECT_EQ(s.free.energy.contact, 0.0);
    }
  }
}

TEST(Yielding, VeryLargeYieldShearGivesTheElasticResponse) {
  // Fixed steps, so that both runs take the same steps (peak accelerations and forces are
  // sampled at the steps, and adaptive steps differ with the last bits of the force).
  IntegratorSettings fixed;
  fixed.control = StepControl::fixed;
  fixed.dt = 2e-4;
  const RowSimulation elastic = chapter8("elastic", "hc-linear", 0.005, 1.0, fixed);
  for (const char* law : {"bilinear", "bouc-wen"}) {
    const RowSimulation s = chapter8(law, "hc-linear", 0.005, 1e7, fixed);
    auto near = [&](double x, double y, const char* what) {
      EXPECT_NEAR(x, y, 1e-8 * std::fabs(y)) << law << " " << what;
    };
    for (std::size_t i = 0; i < s.floors.size(); ++i) {
      near(s.floors[i].disp_pounding, elastic.floors[i].disp_pounding, "disp");
      near(s.floors[i].peak_drift_ratio_free, elastic.floors[i].peak_drift_ratio_free, "drift");
      near(s.floors[i].accel_pounding, elastic.floors[i].accel_pounding, "accel");
      near(s.floors[i].residual_drift_ratio_pounding,
           elastic.floors[i].residual_drift_ratio_pounding, "residual");
      EXPECT_LT(s.floors[i].hysteretic_energy_pounding, 1e-6) << law;  // J
    }
    for (std::size_t k = 0; k < s.sites.size(); ++k) {
      EXPECT_EQ(s.sites[k].impacts, elastic.sites[k].impacts) << law;
      near(s.sites[k].peak_force, elastic.sites[k].peak_force, "force");
    }
  }
}

TEST(Yielding, ExactStepsBetweenEventsAgreeWithDormandPrince) {
  // The default stepping (exact steps of the linear system between contacts and yield events,
  // docs/integration.md) against Dormand-Prince throughout, both at rtol 1e-10, for elastic and
  // bilinear storeys pounding through hc-linear contacts (support/same_run.hpp).
  IntegratorSettings exact, dopri;
  exact.rtol = dopri.rtol = 1e-10;
  dopri.exact_free = false;
  for (const char* law : {"elastic", "bilinear"}) {
    const RowSimulation e = chapter8(law, "hc-linear", 0.01, 1.0, exact, false);
    const RowSimulation d = chapter8(law, "hc-linear", 0.01, 1.0, dopri, false);
    EXPECT_EQ(d.pounding.exact_steps + d.free.exact_steps, 0) << law;
    EXPECT_GT(e.free.exact_steps, 0.75 * e.free.steps) << law;
    EXPECT_GT(e.pounding.exact_steps, 0.5 * e.pounding.steps) << law;
    if (std::string(law) == "bilinear") {
      EXPECT_GT(e.free.events, 20);  // yield and unloading events
    }
    test::expect_same_run(e, d, law);
  }
}

}  // namespace
}  // namespace pound

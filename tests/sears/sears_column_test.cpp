// The damped Sears model where slabs strike the neighbour's columns (issue 36;
// sears/sears_row_layout.hpp, docs/contact-geometry.md): only the striking slab is a bar, the
// struck side is a weighted point of its floors with the columns' k_col in series. Checked here:
// the forces load the floors by the fixed-end reactions (equilibrium at every step, written in
// the test), the energy ledger closes on an offset row, event stepping agrees with the fixed
// step, the approach bound holds at column points, and with stiff short bars the model is the
// lumped solver's column site with an undamped linear law of the same k_eff.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../support/buildings.hpp"
#include "../support/ground_motions.hpp"
#include "../support/studies.hpp"
#include "sears/sears_simulation.hpp"
#include "sears/translation_bound.hpp"
#include "simulation/contact_spec.hpp"
#include "simulation/simulate_row.hpp"

namespace pound::sears {
namespace {

using test::offset_pair;  // support/buildings.hpp

// The sites of offset_pair as the test writes them: each side's (DOF, weight) list, with the
// shear building's sway shape s = 3 xi^2 - 2 xi^3 and k_col = phi k_j / (4 xi^3 (1 - xi)^3)
// at phi = 0.5.
struct TestSite {
  std::vector<std::pair<int, double>> l, r;
  double k_col;
};
std::vector<TestSite> offset_sites() {
  auto sh = [](double xi) { return 3 * xi * xi - 2 * xi * xi * xi; };
  auto kc = [](double k, double xi) { return 0.5 * k / (4.0 * std::pow(xi * (1 - xi), 3)); };
  const double x0 = 3.0 / 3.5, x1 = 0.5 / 3.0, x2 = 2.5 / 3.5;
  return {{{{0, 1.0}}, {{2, sh(x0)}}, kc(8e7, x0)},
          {{{0, 1 - sh(x1)}, {1, sh(x1)}}, {{2, 1.0}}, kc(4e7, x1)},
          {{{1, 1.0}}, {{2, 1 - sh(x2)}, {3, sh(x2)}}, kc(8e7, x2)}};
}

TEST(SearsColumn, TheForcesLoadTheStruckFloorsByTheFixedEndReactions) {
  // Undamped buildings, no ground motion, the left building moving right and the right one
  // left: all three sites close. Newmark's average acceleration keeps M a + K u = P at every
  // step's end, so P, read from the history, must be the sites' forces spread by the weights:
  // -w F on the left point's DOFs, +w F on the right one's. The floors' momentum changes only by
  // the ground's share (1 - s) F of the site on R's first storey.
  const BuildingRow row = offset_pair(0.0, 0.0);
  SearsRowModel model;
  model.slabs.assign(2, FloorSlabProperties{8.0, 21e9, 2500.0, 0.15});
  model.modes = 20;
  SearsRowProblem p;
  p.row = &row;
  p.t_end = 0.06;
  p.v0 = Eigen::Vector4d(0.3, 0.3, -0.2, -0.2);
  p.record_history = true;
  const SearsRowResult r = solve_sears_row(p, model);
  const std::vector<TestSite> sites = offset_sites();
  Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
  K.block<2, 2>(0, 0) << 8e7, -4e7, -4e7, 4e7;
  K.block<2, 2>(2, 2) << 16e7, -8e7, -8e7, 8e7;
  const Eigen::Vector4d m(1e5, 1e5, 0.8e5, 0.8e5);
  const auto& h = r.row.history;
  ASSERT_GT(h.t.size(), 100u);
  double f_max = 0.0;
  for (const auto& f : h.force) f_max = std::max(f_max, f.maxCoeff());
  std::vector<double> peak(3, 0.0);
  for (std::size_t i = 0; i < h.t.size(); ++i) {
    const Eigen::Vector4d P = m.cwiseProduct(h.a_abs[i]) + K * h.u[i];
    Eigen::Vector4d expect = Eigen::Vector4d::Zero();
    for (int s = 0; s < 3; ++s) {
      const double F = h.force[i](s);
      peak[s] = std::max(peak[s], F);
      for (auto [d, w] : sites[s].l) expect(d) -= w * F;
      for (auto [d, w] : sites[s].r) expect(d) += w * F;
    }
    for (int d = 0; d < 4; ++d) ASSERT_NEAR(P(d), expect(d), 1e-9 * f_max) << "t " << h.t[i];
    const double ground_share = (1.0 - sites[0].r[0].second) * h.force[i](0);
    ASSERT_NEAR(P.sum(), -ground_share, 1e-9 * f_max) << "t " << h.t[i];
  }
  for (int s = 0; s < 3; ++s) EXPECT_GT(peak[s], 1e-3 * f_max) << "site " << s;
  EXPECT_EQ(r.slabs.size(), 3u);  // the three striking slabs are bars, no struck side is
}

TEST(SearsColumn, TheEnergyLedgerClosesOnAnOffsetRow) {
  // The chapter 8 pair with the 3-storey's storeys 3.6 m high: six slab-to-column sites. The
  // ledger's contact term is the floors' work on the sites' points; it closes to the tolerance
  // of the aligned rows (SearsYielding.EnergyBalanceClosesWithPoundingForEveryLaw): elastic and
  // yielding storeys on the event and the fixed path with the flat law, and the Hertz law.
  struct Case {
    const char* law;
    std::vector<std::string> args;
  };
  const std::vector<Case> cases = {
      {"elastic", {"--sears.integrator", "event"}},
      {"elastic", {"--sears.integrator", "fixed"}},
      {"bilinear", {"--sears.integrator", "event"}},
      {"bilinear", {"--sears.integrator", "fixed"}},
      {"elastic", {"--sears.contact", "hertz", "--sears.k", "3e9"}},
      {"elastic", {"--sears.integrator", "event", "--sears.force_cap", "2e5"}},  // crushing
      {"bilinear", {"--sears.contact", "hertz", "--sears.k", "3e9", "--sears.force_cap", "5e4"}},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"--building2.storey_heights", "3.6", "--sears.modes", "40"};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const std::string what = std::string(c.law) + " " + c.args[0] + " " + c.args[1];
    test::StudyRun s = test::read_study("ch8-five-three.ini", args);
    for (auto& b : s.row.buildings) b.hysteresis = c.law;
    s.row.buildings[0].yield_shears.assign(5, 4.5e5);
    s.row.buildings[1].yield_shears.assign(3, 1.7e5);
    const AssembledRow a = assemble(s.row);
    ASSERT_EQ(a.sites.size(), 6u);
    for (const auto& site : a.sites) ASSERT_TRUE(site.column());
    RowSimulationOptions o;
    o.track_energy = true;
    o.extra_time = 2.0;
    const SearsRowSimulation r = simulate_sears_row(s.row, s.motion, s.model, o);
    const EnergyBalance& e = r.base.pounding.energy;
    EXPECT_GT(e.input, 1e4);
    EXPECT_LT(std::fabs(e.residual()), 1e-5 * e.input)
        << what << ": input " << e.input << " J, residual " << e.residual();
    EXPECT_GT(e.contact, 1e-3 * e.input) << what;
    EXPECT_EQ(r.counts_pounding.bound_violations, 0) << what;
    for (const auto& site : r.base.sites) EXPECT_GT(site.impacts, 0) << what;
    // Crushing faces (issue 36): the work PF_max x c of every site, and none without a cap.
    double crush_work = 0.0;
    for (const auto& site : r.base.sites) crush_work += s.model.force_cap_N * site.crush;
    if (std::isinf(s.model.force_cap_N)) {
      EXPECT_EQ(e.crushing, 0.0) << what;
    } else {
      EXPECT_GT(e.crushing, 1e-3 * e.input) << what;
      EXPECT_NEAR(e.crushing, crush_work, 1e-12 * e.crushing) << what;
      for (const auto& site : r.base.sites) EXPECT_LE(site.peak_force, s.model.force_cap_N);
    }
  }
}

TEST(SearsColumn, EventSteppingAgreesWithTheFixedStepOnAnOffsetRow) {
  // The accuracy targets of the aligned rows (SearsEvent.AgreesWithTheFixedStepOnTheChapter8
  // Example): 0.5 % in displacement and drift, 2 % in peak force, the same impacts.
  test::StudyRun s = test::read_study("ch8-five-three.ini", {"--building2.storey_heights", "3.6"});
  const SearsRowSimulation ev = simulate_sears_row(s.row, s.motion, s.model);
  s.model.stepping = SearsStepping::fixed;
  const SearsRowSimulation fx = simulate_sears_row(s.row, s.motion, s.model);
  EXPECT_GT(ev.counts_pounding.coarse, 0);
  EXPECT_EQ(ev.counts_pounding.bound_violations, 0);
  for (std::size_t i = 0; i < fx.base.floors.size(); ++i) {
    const auto &x = ev.base.floors[i], &y = fx.base.floors[i];
    EXPECT_NEAR(x.disp_pounding, y.disp_pounding, 5e-3 * y.disp_pounding) << i;
    EXPECT_NEAR(x.peak_drift_ratio_pounding, y.peak_drift_ratio_pounding,
                5e-3 * y.peak_drift_ratio_pounding)
        << i;
  }
  ASSERT_EQ(fx.contacts.size(), 6u);
  for (std::size_t k = 0; k < fx.contacts.size(); ++k) {
    EXPECT_NEAR(ev.base.sites[k].peak_force, fx.base.sites[k].peak_force,
                2e-2 * fx.base.sites[k].peak_force)
        << k;
    EXPECT_EQ(ev.contacts[k].impacts, fx.contacts[k].impacts) << k;
  }
}

TEST(SearsColumn, TheApproachBoundHoldsAtColumnPoints) {
  // offset_pair without contacts, random states, a 2.5 Hz shaking of 3 m/s^2: over one step of
  // 1.5 ms the approach of every site's points (a column point on a fixed base moves s u_1, the
  // ground's share of its acceleration entering the bound) never rises above the bound. A slab
  // site's bound is the one of its two floors, to the bit.
  const BuildingRow row = offset_pair(0.0, 0.05);
  const GroundMotion gm = test::sine_motion(3.0, 2.5, 0.02, 101);
  const RowGround ground = RowGround::uniform(gm, 2);
  SearsRowModel model;
  model.slabs.assign(2, FloorSlabProperties{8.0, 21e9, 2500.0, 0.15});
  model.modes = 10;
  model.stepping = SearsStepping::fixed;
  model.dt_s = 1e-5;
  const AssembledRow a = assemble(row);
  TranslationBound bound(a, gm.pga());
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> ud(-0.05, 0.05), vd(-0.5, 0.5);
  const double h = 1.5e-3;
  double tightest = 0.0;
  for (int trial = 0; trial < 10; ++trial) {
    SearsRowProblem p;
    p.row = &row;
    p.ground = &ground;
    p.t_end = h;
    p.contacts = false;
    p.record_history = true;
    p.u0 = Eigen::VectorXd(4);
    p.v0 = Eigen::VectorXd(4);
    for (int i = 0; i < 4; ++i) p.u0(i) = ud(gen), p.v0(i) = vd(gen);
    const SearsRowResult r = solve_sears_row(p, model);
    bound.set_state(p.u0, p.v0);
    for (const auto& site : a.sites) {
      auto x = [&](const Eigen::VectorXd& u) {
        return site.left.of(u.data()) - site.right.of(u.data());
      };
      double rise = 0.0;
      for (const auto& u : r.row.history.u) rise = std::max(rise, x(u) - x(p.u0));
      const double b = bound.approach(site.left, site.right, p.v0, 0.0, h);
      EXPECT_LE(rise, b) << trial;
      tightest = std::max(tightest, rise / b);
    }
  }
  EXPECT_GT(tightest, 0.3);
  // At rest under a constant ground acceleration of -3 m/s^2: every floor starts with u'' = 3,
  // so the approach of L's floor 1 to R's column point s u_1 accelerates at (1 - s) 3 m/s^2 (the
  // ground carries the point's lower end). The floors' own terms grow only as h^3 from rest; the
  // ground's share (1 - s) |ag|_max h^2 / 2 is what bounds this rise over a short step.
  GroundMotion steady;
  steady.name = "steady";
  steady.dt = 0.02;
  steady.accel.assign(11, -3.0);
  const RowGround steady_ground = RowGround::uniform(steady, 2);
  SearsRowProblem p;
  p.row = &row;
  p.ground = &steady_ground;
  p.t_end = 1e-4;
  p.contacts = false;
  p.record_history = true;
  model.dt_s = 1e-6;
  const SearsRowResult r = solve_sears_row(p, model);
  TranslationBound at_rest(a, 3.0);
  const Eigen::VectorXd zero = Eigen::VectorXd::Zero(4);
  at_rest.set_state(zero, zero);
  for (std::size_t k = 0; k < a.sites.size(); ++k) {
    const auto& site = a.sites[k];
    double rise = 0.0;
    for (const auto& u : r.row.history.u)
      rise = std::max(rise, site.left.of(u.data()) - site.right.of(u.data()));
    EXPECT_LE(rise, at_rest.approach(site.left, site.right, zero, 0.0, p.t_end)) << k;
  }
  const double s0 = 3.0 * std::pow(3.0 / 3.5, 2) - 2.0 * std::pow(3.0 / 3.5, 3);
  const double x = r.row.history.u.back()(0) - s0 * r.row.history.u.back()(2);
  EXPECT_NEAR(x, 0.5 * (1 - s0) * 3.0 * p.t_end * p.t_end, 1e-3 * x);
  const AssembledRow aligned = assemble(test::chapter8_pair(0.0));
  TranslationBound b8(aligned, 3.0);
  Eigen::VectorXd u = Eigen::VectorXd::LinSpaced(8, -0.02, 0.03);
  Eigen::VectorXd v = Eigen::VectorXd::LinSpaced(8, 0.4, -0.3);
  b8.set_state(u, v);
  for (const auto& site : aligned.sites)
    EXPECT_EQ(b8.approach(site.left, site.right, v, 0.1, h),
              b8.approach(site.dof_left, site.dof_right, v, 0.1, h));
}

TEST(SearsColumn, StiffShortBarsGiveTheLumpedColumnSite) {
  // Bars 1 m and sqrt(0.8) m long at the full wave speed (chi = 1), so that both slabs have
  // k_A = E m / (rho l^2) = 1.2e12 N/m, without modal damping. Their axial compliance,
  // l / (3 E A) = 2.8e-13 m/N, is 1e-3 of the sites' 1 / k_eff or less (k_col = 1.2e9 to
  // 5.4e9 N/m) and their first mode (0.58 ms) is 40 times shorter than the contacts: the bars
  // act as rigid bodies, and each site is the lumped solver's with lve at e = 1 (no dashpot) and
  // k = k_A in series with k_col (contact/column_series.hpp). Under one cycle of a 0.5 s sine
  // pulse with 2 mm gaps: the same impacts, peak floor displacements within 2e-4 and peak forces
  // within 5e-3 (measured: 4e-5 and 2.5e-3; the bars' compliance and the two integrators'
  // errors, Newmark at the fine step against the lumped solver's adaptive one).
  const GroundMotion g = test::sine_pulse();
  const BuildingRow row = offset_pair(0.002, 0.0);
  SearsRowModel model;
  model.slabs = {{1.0, 30e9, 2500.0, 0.2}, {std::sqrt(0.8), 30e9, 2500.0, 0.2}};
  model.chi = 1.0;
  model.modes = 10;
  model.xi_s = 0.0;
  RowSimulationOptions o;
  o.track_energy = true;
  const SearsRowSimulation sr = simulate_sears_row(row, g, model, o);
  ContactSpec spec;
  spec.model = "lve";
  spec.params.k = 30e9 * 1e5 / 2500.0;  // k_A of both slabs
  spec.params.e = 1.0;
  const RowSimulation lr = simulate_row(row, g, spec, IntegratorSettings{});
  ASSERT_EQ(sr.base.sites.size(), 3u);
  int total = 0;
  for (int k = 0; k < 3; ++k) {
    const auto &x = sr.base.sites[k], &y = lr.sites[k];
    EXPECT_EQ(x.impacts, y.impacts) << "site " << k;
    EXPECT_NEAR(x.peak_force, y.peak_force, 5e-3 * y.peak_force) << "site " << k;
    total += y.impacts;
  }
  EXPECT_GT(total, 3);  // the row pounds
  for (std::size_t i = 0; i < lr.floors.size(); ++i)
    EXPECT_NEAR(sr.base.floors[i].disp_pounding, lr.floors[i].disp_pounding,
                2e-4 * lr.floors[i].disp_pounding)
        << "floor DOF " << i;
  // The bars keep next to none of the work: an elastic impact without a dashpot.
  const EnergyBalance& e = sr.base.pounding.energy;
  EXPECT_LT(std::fabs(e.contact), 1e-3 * e.input);
}

}  // namespace
}  // namespace pound::sears

// Crushing contact faces in the lumped solver (issue 36; docs/contact-models.md, "Crushing
// faces"): with RowProblem::force_cap the force never passes the cap, a permanent indentation
// grows only while the force is at it, the law then acts on the penetration less the
// indentation (the gap has widened), and the energy balance closes with the crushing work.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "../support/buildings.hpp"
#include "contact/registry.hpp"
#include "motion/motion_reader.hpp"
#include "simulation/contact_spec.hpp"
#include "simulation/simulate_row.hpp"
#include "solver/row_solver.hpp"

namespace pound {
namespace {

// Two free bodies, m1 = 2 kg moving right at v0 = 0.5 m/s onto m2 = 3 kg at rest, touching at
// t = 0, through a linear elastic law (lve with e = 1: no dashpot), k = 1e6 N/m.
constexpr double kM1 = 2.0, kM2 = 3.0, kV0 = 0.5, kK = 1e6;

AssembledRow two_bodies(double k_spring = 0.0, double gap = 0.0) {
  AssembledRow row;
  row.M = Eigen::Vector2d(kM1, kM2).asDiagonal();
  row.C = Eigen::MatrixXd::Zero(2, 2);
  row.K = Eigen::MatrixXd::Zero(2, 2);
  row.K(0, 0) = k_spring;        // each body on a spring to the ground (0: free bodies)
  row.K(1, 1) = 3.0 * k_spring;  // stiffer on the right: the bodies meet again
  row.inv_mass = row.M.diagonal().cwiseInverse();
  row.offset = {0, 1};
  row.sites = {floor_site(row, 0, 0, 0, 1, gap)};
  return row;
}

std::unique_ptr<ContactLaw> law(const std::string& model, double e, double k = kK) {
  ContactParameters p;
  p.k = k;
  p.e = e;
  p.m1 = kM1;
  p.m2 = kM2;
  p.v0_min = 1e-9;
  return find_contact_model(model, "test").make(p);
}

IntegratorSettings tight() {
  IntegratorSettings s;
  s.rtol = 1e-11;
  s.atol = 1e-14;
  s.h_max = 1e-4;
  return s;
}

RowResult free_impact(const ContactLaw& l, double cap, double t_end, bool history = false) {
  static AssembledRow row = two_bodies();
  RowProblem p;
  p.row = &row;
  p.laws = {&l};
  p.force_cap = cap;
  p.u0 = Eigen::Vector2d::Zero();
  p.v0 = Eigen::Vector2d(kV0, 0.0);
  p.t_end = t_end;
  p.track_energy = true;
  p.record_history = history;
  return solve(p, tight());
}

// The hand solution of the elastic two-mass impact at a cap (mu the reduced mass, w =
// sqrt(k / mu)): elastic until F = k delta = cap at t_cap = asin(cap w / (k v0)) / w, where the
// approach rate is v_c = v0 cos(w t_cap); then F = cap decelerates the approach by cap / mu, so
// the indentation grows as c = v_c tau - cap tau^2 / (2 mu) until tau_end = mu v_c / cap; the
// kinetic energy above the cap's elastic energy is the crushing work:
// c_end = (mu v0^2 / 2 - cap^2 / (2 k)) / cap.
struct HandImpact {
  double mu, w, t_cap, v_c, tau_end, c_end;
  explicit HandImpact(double cap) {
    mu = kM1 * kM2 / (kM1 + kM2);
    w = std::sqrt(kK / mu);
    t_cap = std::asin(cap * w / (kK * kV0)) / w;
    v_c = kV0 * std::cos(w * t_cap);
    tau_end = mu * v_c / cap;
    c_end = (0.5 * mu * kV0 * kV0 - cap * cap / (2.0 * kK)) / cap;
  }
  double crush(double t, double cap) const {
    const double tau = std::min(std::max(t - t_cap, 0.0), tau_end);
    return v_c * tau - cap * tau * tau / (2.0 * mu);
  }
};

TEST(Crushing, AFreeElasticImpactCrushesByTheKineticEnergyAboveTheCap) {
  const double cap = 300.0;  // the elastic peak would be v0 sqrt(k mu) = 547.7 N
  const auto lve = law("lve", 1.0);
  const HandImpact hand(cap);
  ASSERT_NEAR(hand.c_end, 3.5e-4, 1e-15);  // (0.15 J - 0.045 J) / 300 N
  const RowResult r = free_impact(*lve, cap, hand.t_cap + 3.0 * hand.tau_end);
  const SiteResult& s = r.sites[0];
  EXPECT_EQ(s.peak_force, cap);
  EXPECT_NEAR(s.crush, hand.c_end, 1e-10 * hand.c_end);
  // The faces went past the gap by the cap's elastic penetration plus the indentation.
  EXPECT_NEAR(s.peak_penetration, cap / kK + hand.c_end, 1e-10 * hand.c_end);
  // The rebound returns the cap's elastic energy only: the approach velocity after is
  // sqrt(cap^2 / (k mu)), so e_eff = cap / (v0 sqrt(k mu)); momentum is kept.
  const double v_rel = r.v_end(1) - r.v_end(0);
  EXPECT_NEAR(v_rel, cap / std::sqrt(kK * hand.mu), 1e-9);
  EXPECT_NEAR(kM1 * r.v_end(0) + kM2 * r.v_end(1), kM1 * kV0, 1e-12);
  // The ledger: no input, so the kinetic energy at the start is what is left plus the contact's
  // and the crushing's work; the crushing work is cap x indentation.
  const EnergyBalance& e = r.energy;
  EXPECT_NEAR(e.crushing, cap * s.crush, 1e-12 * e.crushing);
  EXPECT_NEAR(e.kinetic + e.contact + e.crushing, 0.5 * kM1 * kV0 * kV0, 1e-10);
  EXPECT_NEAR(e.contact, 0.0, 1e-10);  // the elastic law gave back what it stored
}

TEST(Crushing, TheIndentationGrowsOnlyWhileTheForceIsAtTheCap) {
  const double cap = 300.0;
  const auto lve = law("lve", 1.0);
  const HandImpact hand(cap);
  // The run stopped at times before, during and after the crushing phase: the indentation is
  // 0 before it, the hand solution's during it, and stays after it.
  for (double f : {0.5, 0.999, 1.0001, 1.25, 1.5, 1.9, 1.999, 2.2, 3.0}) {
    const double t =
        f <= 1.0 ? f * hand.t_cap : hand.t_cap + (f - 1.0) * hand.tau_end;  // f - 1: of tau_end
    const RowResult r = free_impact(*lve, cap, t);
    EXPECT_NEAR(r.sites[0].crush, hand.crush(t, cap), 1e-9 * hand.c_end) << "t = " << t;
    if (f < 1.0) {
      EXPECT_EQ(r.sites[0].crush, 0.0);
    }
  }
  // The force history: below the cap before and after the phase, at it throughout.
  const RowResult r = free_impact(*lve, cap, hand.t_cap + 3.0 * hand.tau_end, true);
  const double t_end = hand.t_cap + hand.tau_end;
  int at_cap = 0;
  for (std::size_t k = 0; k < r.history.t.size(); ++k) {
    const double t = r.history.t[k], force = r.history.force[k](0);
    if (t < hand.t_cap * (1 - 1e-9) || t > t_end * (1 + 1e-9)) {
      EXPECT_LT(force, cap) << "t = " << t;
    } else if (t > hand.t_cap * (1 + 1e-9) && t < t_end * (1 - 1e-9)) {
      EXPECT_EQ(force, cap) << "t = " << t;
      ++at_cap;
    }
  }
  EXPECT_GT(at_cap, 10);
}

// A damped law at the cap (docs/contact-models.md): its full force, dashpot included, reaches
// the cap; the phase ends when the faces start to part, and the force then falls to the law's
// value at rest, its elastic part. The energy closes.
TEST(Crushing, DampedLawsReachTheCapAndTheLedgerCloses) {
  const double cap = 300.0;
  const HandImpact hand(cap);
  for (const char* model : {"lve", "mlve", "nlve", "kelvin-ye", "hc-linear"}) {
    const auto l = law(model, 0.8, std::string(model) == "nlve" ? 1e9 : kK);
    const RowResult r = free_impact(*l, cap, 0.02);
    const SiteResult& s = r.sites[0];
    EXPECT_EQ(s.peak_force, cap) << model;
    EXPECT_GT(s.crush, 0.0) << model;
    // The crushing takes at most the kinetic energy of the approach, mu v0^2 / 2.
    EXPECT_LT(cap * s.crush, 0.5 * hand.mu * kV0 * kV0) << model;
    const EnergyBalance& e = r.energy;
    EXPECT_NEAR(e.crushing, cap * s.crush, 1e-12 * e.crushing) << model;
    EXPECT_NEAR(e.kinetic + e.contact + e.crushing, 0.5 * kM1 * kV0 * kV0, 1e-10) << model;
    EXPECT_GT(e.contact, 1e-6) << model;  // the dashpot's work
    EXPECT_NEAR(kM1 * r.v_end(0) + kM2 * r.v_end(1), kM1 * kV0, 1e-12) << model;
  }
}

// A dashpot whose force at the contact's start, c_d v0, is above the cap crushes the face at
// once: the law's penetration is held at 0, the whole kinetic energy of the approach goes into
// crushing, c = mu v0^2 / (2 cap), and the bodies leave together (mlve at e = 0.5: xi = 0.59,
// c_d v0 = 2 xi sqrt(k mu) v0 = 650 N).
TEST(Crushing, ADashpotAboveTheCapAtTheStartCrushesAtOnce) {
  const double cap = 300.0;
  const HandImpact hand(cap);
  const auto l = law("mlve", 0.5);
  ASSERT_GT(l->force(0.0, kV0, kV0), cap);
  const RowResult r = free_impact(*l, cap, 0.02);
  EXPECT_NEAR(r.sites[0].crush, 0.5 * hand.mu * kV0 * kV0 / cap, 1e-12);
  EXPECT_NEAR(r.v_end(1) - r.v_end(0), 0.0, 1e-10);
  EXPECT_NEAR(r.energy.contact, 0.0, 1e-12);
}

// Two oscillators that meet twice: after the first impact has crushed the face by c, the law
// acts on the penetration less c: F = k (u_L - u_R - gap - c) at every step of a later contact,
// which starts only where the faces have gone c past the at-rest gap.
TEST(Crushing, ALaterImpactSeesTheWidenedGap) {
  const double gap = 0.01, k_spring = 2e3, cap = 300.0;
  const AssembledRow row = two_bodies(k_spring, gap);
  const auto lve = law("lve", 1.0);
  RowProblem p;
  p.row = &row;
  p.laws = {lve.get()};
  p.force_cap = cap;
  p.u0 = Eigen::Vector2d::Zero();
  p.v0 = Eigen::Vector2d(kV0, 0.0);
  p.t_end = 0.3;  // the second impact (at 0.24 s) stays below the cap; a third would crush
  p.record_history = true;
  IntegratorSettings s = tight();
  s.h_max = 1e-3;
  const RowResult r = solve(p, s);
  const double c = r.sites[0].crush;
  ASSERT_GT(c, 1e-5);
  ASSERT_GE(r.sites[0].impacts, 2);
  // The history after the last step at the cap: the faces part, then meet again.
  const auto& h = r.history;
  std::size_t last_cap = 0;
  for (std::size_t k = 0; k < h.t.size(); ++k)
    if (h.force[k](0) == cap) last_cap = k;
  bool parted = false;
  int later = 0;
  for (std::size_t k = last_cap + 1; k < h.t.size(); ++k) {
    const double f = h.force[k](0), approach = h.u[k](0) - h.u[k](1);
    if (f == 0.0) parted = true;
    if (!parted || f == 0.0) continue;
    ++later;
    EXPECT_NEAR(f / kK, approach - gap - c, 1e-13) << "t = " << h.t[k];
    EXPECT_GE(approach - gap, c - 1e-13) << "t = " << h.t[k];  // no force until c past the gap
  }
  EXPECT_TRUE(parted);
  EXPECT_GT(later, 5);
}

// The chapter 8 pair under El Centro (as tests/solver/yielding_test.cpp's energy check), every
// lumped law with a force history, a cap of 2 MN (the uncapped peaks are 4-9 MN): no force
// above it, faces crushed, and the balance closes with the crushing work cap x sum c.
RowSimulation chapter8(const std::string& model, double cap, double right_storey_height = 3.0) {
  BuildingRow row = test::chapter8_pair(0.01);
  row.buildings[1].storey_heights.assign(3, right_storey_height);
  row.gaps = {std::vector<double>(colliding_levels(row, 0), 0.01)};  // one per site
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  GroundMotion g = read_motion(spec);
  g.accel.resize(static_cast<std::size_t>(8.0 / g.dt) + 1);
  ContactSpec c;
  c.model = model;
  c.params.k = 50 * 8.4e7;  // [N/m] or [N/m^1.5], as tests/solver/yielding_test.cpp
  c.params.e = 0.6;
  c.force_cap = cap;
  RowSimulationOptions o;
  o.extra_time = 2.0;
  o.track_energy = true;
  return simulate_row(row, g, c, IntegratorSettings{}, o);
}

TEST(Crushing, TheChapter8PairCrushesAtTheCapAndItsBalanceCloses) {
  const double cap = 2e6;
  for (const auto& info : contact_models()) {
    if (info.stiffness_unit.empty()) continue;  // stereomechanical: no force to cap
    const RowSimulation s = chapter8(info.name, cap);
    double peak = 0.0, crush = 0.0;
    for (const auto& site : s.sites) {
      EXPECT_LE(site.peak_force, cap) << info.name;
      peak = std::max(peak, site.peak_force);
      EXPECT_GE(site.crush, 0.0);
      crush += site.crush;
    }
    EXPECT_EQ(peak, cap) << info.name;
    EXPECT_GT(crush, 0.0) << info.name;
    const EnergyBalance& e = s.pounding.energy;
    EXPECT_NEAR(e.crushing, cap * crush, 1e-12 * e.crushing) << info.name;
    EXPECT_GT(e.input, 1e4);
    EXPECT_LT(std::fabs(e.residual()), 1e-5 * e.input)
        << info.name << ": input " << e.input << " J, residual " << e.residual() << " J";
  }
}

// Slab-to-column sites (the 3-storey's floors at 3.6 m, 7.2 m, 10.8 m against the 5-storey's
// at 3 m steps: six column sites): the cap bounds the force of the law in series with the
// columns, and the balance closes with the crushing work.
TEST(Crushing, ColumnSitesCrushAtTheCapAndTheirBalanceCloses) {
  const double cap = 1e6;
  for (const char* model : {"lve", "hc-hertz"}) {
    const RowSimulation s = chapter8(model, cap, 3.6);
    double crush = 0.0;
    int columns = 0;
    for (const auto& site : s.sites) {
      columns += site.site.column();
      EXPECT_LE(site.peak_force, cap) << model;
      crush += site.crush;
    }
    EXPECT_EQ(columns, static_cast<int>(s.sites.size())) << model;
    EXPECT_GT(crush, 0.0) << model;
    const EnergyBalance& e = s.pounding.energy;
    EXPECT_NEAR(e.crushing, cap * crush, 1e-12 * e.crushing) << model;
    EXPECT_LT(std::fabs(e.residual()), 1e-5 * e.input) << model;
  }
}

// A crushing switch's crossing that proves a false alarm must not hide a storey's yield later in
// the same step (nlve's force has an infinite slope at delta = 0, so its switch's interpolant
// overshoots at a contact's start): the yield would be applied late, across the kink, and the
// balance would miss its jump (ch8-yielding at 1.5 x El Centro, the 3-storey's storeys 3.6 m,
// nlve, cap 300 kN, gap 1 mm, rtol 1e-7: 36 J, 8.7e-5 of the input, before the fix; the
// uncapped run's residual is 7e-3 J).
TEST(Crushing, AFalseAlarmOfACrushingSwitchHidesNoYield) {
  BuildingRow row = test::chapter8_pair(0.001);
  row.buildings[1].storey_heights.assign(3, 3.6);
  row.gaps = {std::vector<double>(colliding_levels(row, 0), 0.001)};
  for (auto& b : row.buildings) b.hysteresis = "bilinear";
  row.buildings[0].yield_shears = {1106e3, 1032e3, 885e3, 664e3, 369e3};
  row.buildings[1].yield_shears = {401e3, 334e3, 200e3};
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  GroundMotion g = read_motion(spec);
  for (double& a : g.accel) a *= 1.5;
  ContactSpec c;
  c.model = "nlve";
  c.params.k = 50 * 8.4e7;
  c.params.e = 0.65;
  c.force_cap = 3e5;
  RowSimulationOptions o;
  o.extra_time = 5.0;
  o.track_energy = true;
  IntegratorSettings integ;
  integ.rtol = 1e-7;
  const RowSimulation s = simulate_row(row, g, c, integ, o);
  double crush = 0.0;
  for (const auto& site : s.sites) crush += site.crush;
  ASSERT_GT(crush, 0.0);
  const EnergyBalance& e = s.pounding.energy;
  EXPECT_LT(std::fabs(e.residual()), 1e-6 * e.input)
      << "input " << e.input << " J, residual " << e.residual() << " J";
}

// A cap never reached changes nothing: the same steps and numbers as no cap, bit for bit.
TEST(Crushing, ACapNeverReachedIsNoCapBitForBit) {
  for (const char* model : {"lve", "hc-hertz"}) {
    const RowSimulation a = chapter8(model, std::numeric_limits<double>::infinity());
    const RowSimulation b = chapter8(model, 1e12);
    EXPECT_EQ(a.pounding.steps, b.pounding.steps) << model;
    EXPECT_EQ(a.pounding.events, b.pounding.events) << model;
    for (std::size_t k = 0; k < a.sites.size(); ++k) {
      EXPECT_EQ(a.sites[k].peak_force, b.sites[k].peak_force) << model;
      EXPECT_EQ(a.sites[k].peak_penetration, b.sites[k].peak_penetration) << model;
      EXPECT_EQ(b.sites[k].crush, 0.0);
    }
    EXPECT_EQ(a.pounding.peak_disp, b.pounding.peak_disp) << model;
    EXPECT_EQ(a.pounding.energy.contact, b.pounding.energy.contact) << model;
  }
}

}  // namespace
}  // namespace pound

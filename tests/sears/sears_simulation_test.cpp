// Buildings in a row with damped Sears contacts: free-body limits against the free-bar impact
// and St Venant's solution, a floor with contacts at both ends, and the building integrator
// against the lumped-model row solver when no contact happens.
#include "sears/sears_simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../support/buildings.hpp"
#include "../support/ground_motions.hpp"
#include "sears/contact_stiffness.hpp"
#include "sears/sears_impact.hpp"
#include "sears/sears_row_layout.hpp"
#include "solver/row_solver.hpp"

namespace pound::sears {
namespace {

// A single floor without storey spring or damping: a free body in the row.
Building free_floor(double mass) {
  Building b;
  b.masses = {mass};
  b.stiffnesses = {0.0};
  b.storey_heights = {3.0};
  b.damping_ratio = 0.0;
  return b;
}

// Thesis ch. 7 pendulums at c/8 (Hertz, k = 3.21 GN/m^1.5, 0.146 m/s) as a free-bar impact,
// and as two one-floor "buildings" without springs with the same slabs and law.
SearsImpactSpec pendulum_impact() {
  SearsImpactSpec spec;
  spec.bar1 = Slab{0.700, 21e9, 2400.0, 0.15, 109.0, 0.125};
  spec.bar2 = Slab{0.650, 21e9, 2400.0, 0.15, 108.0, 0.125};
  spec.v0_m_s = 0.146;
  spec.contact.kind = ContactKind::hertz;
  spec.contact.stiffness = 3.21e9;
  return spec;
}
BuildingRow pendulum_row() {
  BuildingRow row;
  row.buildings = {free_floor(109.0), free_floor(108.0)};
  row.gaps = {{0.0}};
  return row;
}
SearsRowModel pendulum_model() {
  SearsRowModel model;
  model.slabs = {{0.700, 21e9, 2400.0, 0.15}, {0.650, 21e9, 2400.0, 0.15}};
  model.contact = ContactKind::hertz;
  model.hertz_k = 3.21e9;
  model.hertz_reference_velocity = 0.146;
  model.contact_step_tolerance = 0.0;  // the free bars' step throughout the contact
  return model;
}

TEST(SearsRow, TwoFreeFloorsReproduceTheFreeBarImpact) {
  // Thesis ch. 7 pendulums at c/8 as two one-floor "buildings" without springs: the same
  // model as run_sears_impact except that the rigid bodies are advanced by Newmark's average
  // acceleration instead of exactly; both are second order, so at one step the impulse and
  // the velocities agree to O(dt^2).
  const SearsImpactOutcome ref = run_sears_impact(pendulum_impact());
  const BuildingRow row = pendulum_row();
  const SearsRowModel model = pendulum_model();
  SearsRowProblem p;
  p.row = &row;
  p.t_end = ref.end_time_s;
  p.v0 = Eigen::Vector2d(0.146, 0.0);
  const SearsRowResult r = solve_sears_row(p, model);
  EXPECT_DOUBLE_EQ(r.dt_s, ref.dt_s);
  const double p0 = 109.0 * 0.146;
  EXPECT_NEAR(109.0 * r.row.v_end(0) + 108.0 * r.row.v_end(1), p0, 1e-12 * p0);
  EXPECT_NEAR(r.row.sites[0].impulse, ref.impact.impulse_Ns, 1e-6 * ref.impact.impulse_Ns);
  EXPECT_NEAR(r.row.v_end(0), ref.impact.v1_after, 1e-6 * 0.146);
  EXPECT_NEAR(r.row.v_end(1), ref.impact.v2_after, 1e-6 * 0.146);
  EXPECT_NEAR(r.row.sites[0].peak_force, ref.impact.peak_force_N, 1e-4 * ref.impact.peak_force_N);
  EXPECT_EQ(r.row.sites[0].impacts, ref.impact.contact_phases);
  EXPECT_NEAR(r.row.sites[0].last_separation, ref.impact.contact_duration_s, 2.0 * ref.dt_s);
  ASSERT_EQ(r.slabs.size(), 2u);
  EXPECT_NEAR(r.slabs[0].face_accel, ref.peak_face_accel1, 1e-3 * ref.peak_face_accel1);
  EXPECT_NEAR(r.slabs[1].centre_accel, ref.peak_centre_accel2, 1e-3 * ref.peak_centre_accel2);
}

TEST(SearsRow, TwoFreeFloorsCrushAsTheFreeBarImpact) {
  // [sears] force_cap on the row (issue 36): the crushing faces of run_sears_impact. The
  // pendulums above with the cap at half the free peak: the same indentation to O(dt^2), the
  // force at the cap, the momentum kept, and the row's ledger closing with the crushing work
  // PF_max x c in it.
  SearsImpactSpec spec = pendulum_impact();
  spec.contact.force_cap_N = 0.5 * run_sears_impact(spec).impact.peak_force_N;
  const SearsImpactOutcome ref = run_sears_impact(spec);
  ASSERT_GT(ref.crush_m, 0.0);
  const BuildingRow row = pendulum_row();
  SearsRowModel model = pendulum_model();
  model.force_cap_N = spec.contact.force_cap_N;
  SearsRowProblem p;
  p.row = &row;
  p.t_end = ref.end_time_s;
  p.v0 = Eigen::Vector2d(0.146, 0.0);
  p.track_energy = true;
  const SearsRowResult r = solve_sears_row(p, model);
  const SiteResult& site = r.row.sites[0];
  EXPECT_DOUBLE_EQ(site.peak_force, model.force_cap_N);
  EXPECT_NEAR(site.crush, ref.crush_m, 1e-6 * ref.crush_m);
  EXPECT_NEAR(r.row.v_end(1), ref.impact.v2_after, 1e-6 * 0.146);
  const double p0 = 109.0 * 0.146;
  EXPECT_NEAR(109.0 * r.row.v_end(0) + 108.0 * r.row.v_end(1), p0, 1e-12 * p0);
  const EnergyBalance& e = r.row.energy;
  EXPECT_NEAR(e.crushing, model.force_cap_N * site.crush, 1e-12 * e.crushing);
  const double e0 = 0.5 * 109.0 * 0.146 * 0.146;
  EXPECT_LT(std::fabs(e.residual() + e0), 1e-6 * e0)  // no ground: input 0, initial kinetic e0
      << "kinetic " << e.kinetic << " contact " << e.contact << " crushing " << e.crushing;
}

TEST(SearsRow, NewtonsCradleOfThreeBarsPassesTheWaveThrough) {
  // Three equal steel bars (l = 1 m), the first at v0 = 1 m/s, flat contacts 100 E A / l
  // (D = 200), 400 modes, no damping. St Venant: a pulse of length 2 l runs through bar 2
  // (contacts at both its ends) into bar 3, which leaves at v0 while bars 1 and 2 stop
  // (Goldsmith, Impact, 1960, ch. 2). Tolerances as in the two-bar wave-limit tests (1 %).
  const double A = 1e-3, rho = 7850.0, E = 200e9, m = rho * A * 1.0;
  BuildingRow row;
  row.buildings = {free_floor(m), free_floor(m), free_floor(m)};
  row.gaps = {{0.0}, {0.0}};
  SearsRowModel model;
  model.slabs.assign(3, FloorSlabProperties{1.0, E, rho, 0.3});
  model.chi = 1.0;
  model.modes = 400;
  model.xi_s = 0.0;
  model.D = 200.0;
  SearsRowProblem p;
  p.row = &row;
  const double c = std::sqrt(E / rho);
  p.t_end = 5.0 / c;
  p.v0 = Eigen::Vector3d(1.0, 0.0, 0.0);
  p.record_history = true;
  const SearsRowResult r = solve_sears_row(p, model);
  EXPECT_NEAR(m * r.row.v_end.sum(), m * 1.0, 1e-12 * m);
  EXPECT_NEAR(r.row.v_end(0), 0.0, 0.01);
  EXPECT_NEAR(r.row.v_end(1), 0.0, 0.01);
  EXPECT_NEAR(r.row.v_end(2), 1.0, 0.01);
  EXPECT_NEAR(r.row.sites[0].impulse, m, 0.01 * m);
  EXPECT_NEAR(r.row.sites[1].impulse, m, 0.01 * m);
  EXPECT_NEAR(r.row.sites[0].first_contact, 0.0, 1e-12);
  // The wave force Z v0 / 2 reaches the second interface after l / c and leaves it at 3 l / c.
  // (Modal truncation lets its face creep before the front arrives, so the contact is timed
  // by the force passing half the wave force rather than by the first overlap.) Tolerance:
  // the force reaches half its plateau ln 2 Z/(2k) = 0.0035 l/c after the front, and 400
  // modes smear the front over ~0.005 l/c: 0.015 l/c.
  const double wave_force = rho * A * c * 1.0 / 2.0;
  double rise = -1.0, fall = -1.0;
  const auto& h = r.row.history;
  for (std::size_t i = 1; i < h.t.size(); ++i) {
    if (rise < 0 && h.force[i](1) > 0.5 * wave_force) rise = h.t[i];
    if (rise > 0 && fall < 0 && h.force[i](1) < 0.5 * wave_force) fall = h.t[i];
  }
  EXPECT_NEAR(rise, 1.0 / c, 0.015 / c);
  EXPECT_NEAR(fall, 3.0 / c, 0.015 / c);
}

TEST(SearsRow, SymmetricImpactOnAMiddleFloorKeepsItAtRest) {
  // Outer floors approach the middle one (contacts at both of its ends) at +-0.2 m/s; by
  // symmetry the middle floor's DOF stays at rest and both sites carry the same impulse.
  BuildingRow row;
  row.buildings = {free_floor(50.0), free_floor(80.0), free_floor(50.0)};
  row.gaps = {{0.0}, {0.0}};
  SearsRowModel model;
  model.slabs.assign(3, FloorSlabProperties{2.0, 21e9, 2500.0, 0.15});
  model.modes = 60;
  model.contact = ContactKind::hertz;
  model.hertz_k = 3e9;
  model.hertz_reference_velocity = 0.2;
  SearsRowProblem p;
  p.row = &row;
  p.t_end = 0.05;
  p.v0 = Eigen::Vector3d(0.2, 0.0, -0.2);
  const SearsRowResult r = solve_sears_row(p, model);
  EXPECT_GT(r.row.sites[0].impulse, 0.0);
  EXPECT_NEAR(r.row.sites[0].impulse, r.row.sites[1].impulse, 1e-9 * r.row.sites[0].impulse);
  EXPECT_NEAR(r.row.v_end(1), 0.0, 1e-12);
  EXPECT_NEAR(r.row.v_end(0), -r.row.v_end(2), 1e-12);
  EXPECT_LT(r.row.v_end(0), 0.0);   // the outer floors rebound ...
  EXPECT_GT(r.row.v_end(0), -0.2);  // ... with some energy left in the slabs
}

TEST(SearsRow, WithoutContactsNewmarkMatchesTheRowSolver) {
  // Two shear buildings (Table 8.2 storey stiffnesses and floor masses) far apart under a
  // sine ground motion: the Sears run's buildings (Newmark, small step) must match the
  // adaptive Dormand-Prince solver of the lumped models.
  const BuildingRow row = test::chapter8_pair(1.0);
  const GroundMotion gm = test::sine_motion(2.0, 2.0, 0.01, 151);
  SearsRowModel model;
  model.slabs = {{20.0, 21e9, 2500.0, 0.15}, {12.0, 21e9, 2500.0, 0.15}};
  model.modes = 10;
  model.stepping = SearsStepping::fixed;  // Newmark at the fine step; event stepping below
  SearsRowProblem p;
  p.row = &row;
  const RowGround p_ground = RowGround::uniform(gm, static_cast<int>(p.row->buildings.size()));
  p.ground = &p_ground;
  p.t_end = gm.duration();
  const SearsRowResult r = solve_sears_row(p, model);
  model.stepping = SearsStepping::event;  // coarse steps throughout (no contact possible)
  model.modes = 100;  // a fine step below the coarse one (with 10 modes they coincide)
  const SearsRowResult e = solve_sears_row(p, model);
  EXPECT_EQ(e.counts.fine, 0);
  EXPECT_GT(e.coarse_dt_s, 5.0 * e.dt_s);
  const AssembledRow a = assemble(row);
  RowProblem q;
  q.row = &a;
  const RowGround q_ground = RowGround::uniform(gm, static_cast<int>(q.row->offset.size()));
  q.ground = &q_ground;
  q.t_end = gm.duration();
  IntegratorSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-12;
  const RowResult ref = solve(q, s);
  EXPECT_EQ(r.row.sites[0].impacts, 0);
  for (int i = 0; i < a.dofs(); ++i) {
    EXPECT_NEAR(r.row.u_end(i), ref.u_end(i), 1e-5 * ref.peak_disp(i)) << i;
    EXPECT_NEAR(r.row.peak_disp(i), ref.peak_disp(i), 1e-4 * ref.peak_disp(i)) << i;
    EXPECT_NEAR(r.row.peak_abs_accel(i), ref.peak_abs_accel(i), 1e-3 * ref.peak_abs_accel(i)) << i;
    // Coarse Newmark steps of T_min / 200 (period error (w h)^2 / 12 = 8e-5 for the highest
    // mode): observed up to 8.6e-6 of the peak.
    EXPECT_NEAR(e.row.u_end(i), ref.u_end(i), 5e-5 * ref.peak_disp(i)) << i;
    EXPECT_NEAR(e.row.peak_disp(i), ref.peak_disp(i), 5e-5 * ref.peak_disp(i)) << i;
    EXPECT_NEAR(e.row.peak_abs_accel(i), ref.peak_abs_accel(i), 3e-3 * ref.peak_abs_accel(i)) << i;
  }
}

}  // namespace
}  // namespace pound::sears

namespace pound::sears {
namespace {

TEST(SearsRow, HertzStiffnessFromTheFaceRadiiAndTheSlabMaterials) {
  // Th. 7.2 for a 50 mm concrete hemisphere on a flat concrete face: 3.21 GN/m^1.5 in the
  // thesis; the row computes it per pair from the two buildings' slabs.
  BuildingRow row;
  Building b;
  b.masses = {100.0};
  b.stiffnesses = {1e5};
  b.storey_heights = {3.0};
  row.buildings = {b, b};
  row.gaps = {{0.0}};
  SearsRowModel model;
  model.slabs = {{0.7, 21e9, 2400.0, 0.15}, {0.65, 21e9, 2400.0, 0.15}};
  model.contact = ContactKind::hertz;
  model.hertz_radius_left = 0.05;
  model.hertz_radius_right = kFlatRadius;
  const AssembledRow a = assemble(row);
  const RowContactLayout layout = make_layout(row, a, model);
  ASSERT_EQ(layout.laws.size(), 1u);
  EXPECT_NEAR(layout.laws[0].stiffness / 3.21e9, 1.0, 0.005);
  EXPECT_DOUBLE_EQ(layout.laws[0].stiffness,
                   hertz_stiffness(21e9, 0.15, 0.05, 21e9, 0.15, kFlatRadius));
}

}  // namespace
}  // namespace pound::sears

namespace pound::sears {
namespace {

TEST(SearsRow, SlabPropertiesMayDifferPerFloor) {
  // Flat contact (Th. 8.1-8.2, D = 1): k_A = E A / l with A = m / (rho l), so
  // k_A = E m / (rho l^2); two slabs in series. Floor 2 of the left building has a 10 m slab.
  const Building b = test::uniform_building(2, 48e3, 8.4e7);
  BuildingRow row;
  row.buildings = {b, b};
  row.gaps = {{0.0, 0.0}};
  SearsRowModel model;
  FloorSlabProperties left{20.0, 21e9, 2500.0, 0.15};
  left.length_per_floor_m = {20.0, 10.0};
  model.slabs = {left, {20.0, 21e9, 2500.0, 0.15}};
  const AssembledRow a = assemble(row);
  const RowContactLayout layout = make_layout(row, a, model);
  auto ka = [](double l) { return 21e9 * 48e3 / (2500.0 * l * l); };
  auto series = [](double x, double y) { return 1.0 / (1.0 / x + 1.0 / y); };
  ASSERT_EQ(layout.laws.size(), 2u);
  EXPECT_NEAR(layout.laws[0].stiffness / series(ka(20.0), ka(20.0)), 1.0, 1e-12);
  EXPECT_NEAR(layout.laws[1].stiffness / series(ka(10.0), ka(20.0)), 1.0, 1e-12);
}

}  // namespace
}  // namespace pound::sears

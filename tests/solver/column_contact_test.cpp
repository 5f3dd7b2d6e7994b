// Slab-to-column contact in the lumped solver (issue 36): the forces of a site keep the
// momentum and load the struck floors by the fixed-end reactions, and a row whose slabs strike
// the neighbour's columns agrees with an independent integration written here.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <vector>

#include "../support/buildings.hpp"
#include "../support/ground_motions.hpp"
#include "contact/registry.hpp"
#include "simulation/contact_spec.hpp"
#include "simulation/simulate_row.hpp"
#include "solver/row_dynamics.hpp"
#include "structure/building_row.hpp"

namespace pound {
namespace {

using test::offset_pair;  // support/buildings.hpp

TEST(ColumnContact, ASiteKeepsTheMomentumAndLoadsTheFloorsByTheReactions) {
  const BuildingRow row = offset_pair(0.0, 0.05);
  const AssembledRow a = assemble(row);
  ASSERT_EQ(a.sites.size(), 3u);
  ContactSpec spec;
  spec.model = "lve";
  spec.params.k = 1e9;
  spec.params.e = 1.0;  // no dashpot: F = k_eff delta
  const auto owned = make_site_laws(spec, a);
  std::vector<const ContactLaw*> laws;
  for (const auto& l : owned) laws.push_back(l.get());
  RowDynamics dyn(a, a.storeys, false, nullptr);
  dyn.set_contacts(&laws);
  Eigen::VectorXd y = Eigen::VectorXd::Zero(dyn.layout().size), free, loaded;
  y(0) = 0.004, y(1) = 0.007, y(2) = -0.001, y(3) = 0.002;  // every site closed
  dyn.rhs(0.0, y, free);
  // Site 1: R's slab against L's storey 2 (floors 0 and 1): the one site whose two sides both
  // stand on floors, so that the floors' momentum change is zero.
  dyn.active[1] = true;
  dyn.rhs(0.0, y, loaded);
  const double F = dyn.contact_force()(1);
  const double s = column_shape(0.5 / 3.0);
  const double kc = 0.5 * 4.0e7 / (4.0 * std::pow(0.5 / 3.0 * (2.5 / 3.0), 3));
  const double delta = (1 - s) * y(0) + s * y(1) - y(2);
  EXPECT_NEAR(F, 1e9 * kc / (1e9 + kc) * delta, 1e-9 * std::fabs(F));
  Eigen::VectorXd force(4);  // M (a_loaded - a_free) = the contact forces on the floors
  for (int i = 0; i < 4; ++i) force(i) = (loaded(4 + i) - free(4 + i)) / a.inv_mass(i);
  EXPECT_NEAR(force.sum(), 0.0, 1e-9 * F);
  EXPECT_NEAR(force(0), -(1 - s) * F, 1e-9 * F);  // the struck storey's floors: F (1 - s), F s
  EXPECT_NEAR(force(1), -s * F, 1e-9 * F);
  EXPECT_NEAR(force(2), F, 1e-9 * F);  // the slab
  EXPECT_NEAR(force(3), 0.0, 1e-9 * F);
}

// The row of offset_pair, undamped, integrated here by classical Runge-Kutta with a fixed step:
// M u'' + K u = -M ag + P, P from k_eff delta at each closed site (lve with e = 1).
struct Reference {
  Eigen::VectorXd peak = Eigen::VectorXd::Zero(4);
  int impacts[3] = {0, 0, 0};
};

Reference integrate(const GroundMotion& g, double gap, double k, double t_end, double h) {
  const double m[4] = {1.0e5, 1.0e5, 0.8e5, 0.8e5};
  Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
  K.block<2, 2>(0, 0) << 8e7, -4e7, -4e7, 4e7;
  K.block<2, 2>(2, 2) << 16e7, -8e7, -8e7, 8e7;
  // Sites: (left DOFs, weights), (right DOFs, weights), k_eff with the struck columns.
  struct Site {
    std::vector<std::pair<int, double>> l, r;
    double k;
  };
  auto keff = [&](double ks, double xi) {
    const double kc = 0.5 * ks / (4.0 * std::pow(xi * (1 - xi), 3));
    return k * kc / (k + kc);
  };
  auto sh = [](double xi) { return 3 * xi * xi - 2 * xi * xi * xi; };
  const double x0 = 3.0 / 3.5, x1 = 0.5 / 3.0, x2 = 2.5 / 3.5;
  const std::vector<Site> sites = {
      {{{0, 1.0}}, {{2, sh(x0)}}, keff(8e7, x0)},
      {{{0, 1 - sh(x1)}, {1, sh(x1)}}, {{2, 1.0}}, keff(4e7, x1)},
      {{{1, 1.0}}, {{2, 1 - sh(x2)}, {3, sh(x2)}}, keff(8e7, x2)},
  };
  auto delta = [&](const Site& s, const Eigen::Vector4d& u) {
    double d = -gap;
    for (auto [i, w] : s.l) d += w * u(i);
    for (auto [i, w] : s.r) d -= w * u(i);
    return d;
  };
  auto accel = [&](double t, const Eigen::Vector4d& u) {
    Eigen::Vector4d f = -K * u;
    for (const Site& s : sites) {
      const double d = delta(s, u);
      if (d <= 0.0) continue;
      for (auto [i, w] : s.l) f(i) -= w * s.k * d;
      for (auto [i, w] : s.r) f(i) += w * s.k * d;
    }
    Eigen::Vector4d a;
    for (int i = 0; i < 4; ++i) a(i) = f(i) / m[i] - g.at(t);
    return a;
  };
  Reference out;
  Eigen::Vector4d u = Eigen::Vector4d::Zero(), v = Eigen::Vector4d::Zero();
  bool closed[3] = {false, false, false};
  const long steps = std::lround(t_end / h);
  for (long n = 0; n < steps; ++n) {
    const double t = n * h;
    const Eigen::Vector4d k1u = v, k1v = accel(t, u);
    const Eigen::Vector4d k2u = v + 0.5 * h * k1v, k2v = accel(t + 0.5 * h, u + 0.5 * h * k1u);
    const Eigen::Vector4d k3u = v + 0.5 * h * k2v, k3v = accel(t + 0.5 * h, u + 0.5 * h * k2u);
    const Eigen::Vector4d k4u = v + h * k3v, k4v = accel(t + h, u + h * k3u);
    u += h / 6.0 * (k1u + 2 * k2u + 2 * k3u + k4u);
    v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    out.peak = out.peak.cwiseMax(u.cwiseAbs());
    for (int s = 0; s < 3; ++s) {
      const bool c = delta(sites[s], u) > 0.0;
      if (c && !closed[s]) ++out.impacts[s];
      closed[s] = c;
    }
  }
  return out;
}

TEST(ColumnContact, AnOffsetRowAgreesWithAnIndependentIntegration) {
  const GroundMotion g = test::sine_pulse();  // one cycle of a 0.5 s sine, then rest
  const double gap = 0.002, k = 1e9;
  ContactSpec spec;
  spec.model = "lve";
  spec.params.k = k;
  spec.params.e = 1.0;
  const RowSimulation s = simulate_row(offset_pair(gap, 0.0), g, spec, IntegratorSettings{});
  const Reference ref = integrate(g, gap, k, g.duration(), 1e-5);
  ASSERT_EQ(s.sites.size(), 3u);
  int total = 0;
  for (int k2 = 0; k2 < 3; ++k2) {
    EXPECT_EQ(s.sites[k2].impacts, ref.impacts[k2]) << "site " << k2;
    total += ref.impacts[k2];
  }
  EXPECT_GT(total, 3);  // the row pounds
  for (int i = 0; i < 4; ++i)
    EXPECT_NEAR(s.floors[i].disp_pounding, ref.peak(i), 1e-4 * ref.peak(i)) << "floor DOF " << i;
}

// The slab-only paths (issue 38 part 1; RowDynamics::approach and penetration_rate with
// `slabs` chosen once per run from slab_sites()) take a slab site's floors directly: at every
// slab site their values are the general SitePoint sums' to the bit (1 x u is u), and a row
// with a column site does not take them.
TEST(ColumnContact, SlabSitesApproachAndRateByTheirFloorsAreTheGeneralValuesToTheBit) {
  BuildingRow row;
  row.buildings = {test::uniform_building(3, 1.0e5, 4.0e7),
                   test::uniform_building(2, 0.8e5, 8.0e7)};
  row.gaps = {{0.01, 0.02}};
  const AssembledRow a = assemble(row);
  ASSERT_EQ(a.sites.size(), 2u);
  RowDynamics dyn(a, a.storeys, false, nullptr);
  ASSERT_TRUE(dyn.slab_sites());
  Eigen::VectorXd y(dyn.layout().size);
  for (int k = 0; k < y.size(); ++k) y(k) = 1e-3 * std::sin(1.7 * k + 0.3) / 3.0;  // not round
  for (int i = 0; i < 2; ++i) {
    const ContactSite& s = a.sites[i];
    const double d = y(s.dof_left) - y(s.dof_right);
    const double r = y(a.dofs() + s.dof_left) - y(a.dofs() + s.dof_right);
    EXPECT_EQ(dyn.approach(y, i, true), d);
    EXPECT_EQ(dyn.approach(y, i, false), d);
    EXPECT_EQ(dyn.approach(y, i), d);
    EXPECT_EQ(dyn.penetration_rate(y, i, true), r);
    EXPECT_EQ(dyn.penetration_rate(y, i, false), r);
    EXPECT_EQ(dyn.penetration_rate(y, i), r);
  }
  const AssembledRow offset = assemble(offset_pair(0.0, 0.05));
  RowDynamics column_row(offset, offset.storeys, false, nullptr);
  EXPECT_FALSE(column_row.slab_sites());
}

}  // namespace
}  // namespace pound

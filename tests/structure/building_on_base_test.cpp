// A building on its foundation (issue 29, structure/building_on_base.hpp): the periods with the
// foundation against closed forms and against a model written here independently.
// - An SDOF (m, k, h) on massless springs has the Veletsos & Meek (1974) period
//   T~ = T sqrt(1 + k / K_x + k h^2 / K_theta) (physics.md section 5a; docs/ssi.md).
// - With the base's mass m_0 and rotary inertia I_0 and the floors' own J_j, the periods are
//   those of the classic model in coordinates RELATIVE to the base (the floors' deformations
//   u_j, the base's sway u0 and rotation theta; e.g. Wolf 1985, Dynamic Soil-Structure
//   Interaction, Prentice Hall): each floor's total displacement relative to the free-field
//   ground is u_j + u0 + H_j theta, so that
//       M = [ diag(m)    m         m.H                        ]
//           [ m^T        sum m + m_0   sum m H                ]
//           [ (m.H)^T    sum m H   sum m H^2 + I_0 + sum J    ],
//       K = blockdiag(K_fixed, K_x, K_theta),
//   the coordinates of the library (U_j = u_j + u0 + H_j theta) being a linear change of these.
//   A massless u0 or theta makes this M singular: the periods are 2 pi sqrt(mu) for the non-zero
//   eigenvalues mu of K^-1 M (infinite frequencies dropped), as many as the library's DOFs with
//   mass.
#include "structure/building_on_base.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "../support/buildings.hpp"
#include "structure/building_row.hpp"

namespace pound {
namespace {

using test::uniform_building;

Foundation springs(double kx, double kr, double m0 = 0.0, double i0 = 0.0,
                   std::vector<double> j = {}) {
  // (the dashpots do not enter the undamped periods)
  Foundation f = test::springs_foundation(kx, kr, 1e5, 1e7, m0, i0);
  f.floor_inertias = std::move(j);
  return f;
}

// The relative model above: M, K and, with the fixed-base building's damping on the
// deformations u_j and the foundation's dashpots on u0 and theta, C = blockdiag(C_fixed, C_x,
// C_theta).
struct RelativeModel {
  Eigen::MatrixXd M, K, C;
};
RelativeModel relative_model(const Building& b) {
  const FoundationConstants f = foundation_constants(b.foundation);
  const int n = b.floors(), m = n + 2, sway = n, rot = n + 1;
  RelativeModel r;
  r.M = Eigen::MatrixXd::Zero(m, m), r.K = Eigen::MatrixXd::Zero(m, m);
  r.C = Eigen::MatrixXd::Zero(m, m);
  Eigen::MatrixXd &M = r.M, &K = r.K;
  double H = 0.0, J = 0.0;
  for (int j = 0; j < n; ++j) {
    H += b.storey_heights[j];
    const double mj = b.masses[j];
    M(j, j) = mj;
    M(j, sway) = M(sway, j) = mj;
    M(j, rot) = M(rot, j) = mj * H;
    M(sway, sway) += mj;
    M(sway, rot) += mj * H;
    M(rot, rot) += mj * H * H;
    J += j < static_cast<int>(f.floor_inertias.size()) ? f.floor_inertias[j] : 0.0;
    // The fixed-base shear building's stiffness: storey j between floor j-1 (or the base) and j.
    K(j, j) += b.stiffnesses[j];
    if (j > 0) {
      K(j - 1, j - 1) += b.stiffnesses[j];
      K(j, j - 1) -= b.stiffnesses[j];
      K(j - 1, j) -= b.stiffnesses[j];
    }
  }
  M(rot, sway) = M(sway, rot);
  M(sway, sway) += f.foundation_mass;
  M(rot, rot) += f.foundation_inertia + J;  // (the cone's trapped soil is in foundation_inertia)
  K(sway, sway) = f.sway_stiffness;
  K(rot, rot) = f.rocking_stiffness;
  r.C.topLeftCorner(n, n) = assemble(b).C;
  r.C(sway, sway) = f.sway_damping;
  r.C(rot, rot) = f.rocking_damping;
  return r;
}

// The undamped periods of the relative model, longest first [s].
Eigen::VectorXd relative_model_periods(const Building& b) {
  const RelativeModel r = relative_model(b);
  const Eigen::MatrixXd &M = r.M, &K = r.K;
  const int m = static_cast<int>(M.rows());
  // mu = 1 / omega^2 are the eigenvalues of K^-1/2 M K^-1/2 (K positive definite).
  Eigen::LLT<Eigen::MatrixXd> llt(K);
  const Eigen::MatrixXd L = llt.matrixL();
  const Eigen::MatrixXd Li = L.inverse();
  const Eigen::MatrixXd A = Li * M * Li.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
  const Eigen::VectorXd mu = eig.eigenvalues();  // ascending
  std::vector<double> periods;
  for (int i = m - 1; i >= 0; --i)
    if (mu(i) > 1e-13 * mu(m - 1)) periods.push_back(2 * M_PI * std::sqrt(mu(i)));
  return Eigen::Map<Eigen::VectorXd>(periods.data(), static_cast<int>(periods.size()));
}

std::string sci(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.3g", x);
  return s;
}

double worst_relative(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  double w = 0.0;
  for (int i = 0; i < a.size(); ++i) w = std::max(w, std::fabs(a(i) / b(i) - 1));
  return w;
}

// Veletsos & Meek (1974): an oscillator of mass m = 100 t, stiffness k = 4e7 N/m (T = 0.3142 s)
// and height h = 3 m on massless springs has one period, T sqrt(1 + k / K_x + k h^2 / K_theta),
// for flexibilities k / K_x and k h^2 / K_theta from 1e-3 to 3 (the periods from
// assemble_on_base and from the row's assembly), to 1e-10 (2.2e-16 measured).
TEST(BuildingOnBase, SdofOnMasslessSpringsHasTheVeletsosMeekPeriod) {
  const double m = 1e5, k = 4e7, h = 3.0;
  const double T = 2 * M_PI * std::sqrt(m / k);
  const std::vector<std::pair<double, double>> flex = {{0.1, 0.2}, {1e-3, 1.0}, {1.0, 1e-3},
                                                       {0.5, 0.5}, {3.0, 2.0},  {0.02, 0.05}};
  double worst = 0.0;
  for (const auto& [sway, rocking] : flex) {
    SCOPED_TRACE(std::to_string(sway) + ", " + std::to_string(rocking));
    Building b = uniform_building(1, m, k);
    b.foundation = springs(k / sway, k * h * h / rocking);
    const double expected = T * std::sqrt(1 + sway + rocking);
    const BaseMatrices bm = assemble_on_base(b);
    ASSERT_TRUE(bm.flexible);
    ASSERT_EQ(bm.dofs(), 3);
    ASSERT_EQ(bm.periods.size(), 1);  // the massless sway and rotation have no mode of their own
    EXPECT_NEAR(bm.periods(0), expected, 1e-10 * expected);
    BuildingRow row;
    row.buildings = {uniform_building(2, m, k), b};
    row.gaps = {{0.01}};
    const AssembledRow a = assemble(row);
    ASSERT_EQ(a.periods.size(), 2u);
    EXPECT_EQ(a.periods[1](0), bm.periods(0));
    EXPECT_EQ(a.sway[0], -1);
    EXPECT_EQ(a.sway[1], 3);
    EXPECT_EQ(a.rot[1], 4);
    EXPECT_TRUE(a.massless[3] && a.massless[4]);
    worst = std::max(worst, std::fabs(bm.periods(0) / expected - 1));
  }
  RecordProperty("worst_relative_difference", sci(worst));
}

// With mass: an SDOF with m_0, I_0 and J (three modes), with m_0 only or I_0 only (two: the
// other base DOF is massless), and buildings of 2 and 3 storeys (unequal masses, stiffnesses and
// heights) with every inertia, some of them, or none (n modes), against the relative model, to
// 1e-10 (1.7e-15 measured).
TEST(BuildingOnBase, PeriodsWithMassiveBaseMatchTheRelativeModel) {
  struct Case {
    const char* name;
    std::function<Building()> make;
  };
  const double m = 1e5, k = 4e7;
  auto sdof = [&](Foundation f) {
    Building b = uniform_building(1, m, k);
    b.storey_heights = {3.5};
    b.foundation = std::move(f);
    return b;
  };
  auto three = [&](Foundation f) {
    Building b;
    b.masses = {1.2e5, 1.0e5, 0.7e5};
    b.stiffnesses = {9e7, 7e7, 4e7};
    b.storey_heights = {4.0, 3.2, 3.0};
    b.foundation = std::move(f);
    return b;
  };
  const std::vector<Case> cases = {
      {"sdof m0 I0 J", [&] { return sdof(springs(2e8, 3e10, 4e4, 6e5, {2e5})); }},
      {"sdof m0", [&] { return sdof(springs(2e8, 3e10, 4e4)); }},
      {"sdof I0", [&] { return sdof(springs(2e8, 3e10, 0.0, 6e5)); }},
      {"sdof J", [&] { return sdof(springs(1e8, 1e10, 0.0, 0.0, {5e5})); }},
      {"sdof heavy soft base", [&] { return sdof(springs(3e7, 2e9, 3e5, 5e6, {1e6})); }},
      {"2 storeys m0 I0 J",
       [&] {
         Building b = uniform_building(2, 8e4, 6e7);
         b.foundation = springs(5e8, 8e10, 1.5e5, 2e6, {4e5, 3e5});
         return b;
       }},
      {"3 storeys m0 I0 J",
       [&] {
         return three(springs(6e8, 2e11, 2e5, 3e6, {1e6, 8e5, 6e5}));
       }},
      {"3 storeys m0", [&] { return three(springs(6e8, 2e11, 2e5)); }},
      {"3 storeys massless", [&] { return three(springs(6e8, 2e11)); }},
  };
  double worst = 0.0;
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const Building b = c.make();
    const BaseMatrices bm = assemble_on_base(b);
    const Eigen::VectorXd expected = relative_model_periods(b);
    int with_mass = 0;
    for (int i = 0; i < bm.dofs(); ++i) with_mass += bm.M(i, i) > 0.0;
    ASSERT_EQ(bm.periods.size(), with_mass);
    ASSERT_EQ(expected.size(), with_mass);
    for (int i = 0; i < expected.size(); ++i)
      EXPECT_NEAR(bm.periods(i), expected(i), 1e-10 * expected(i)) << "mode " << i + 1;
    // The foundation lengthens the fixed base's periods (Rayleigh's interlacing).
    const BuildingMatrices fixed = assemble(b);
    EXPECT_GT(bm.periods(0), fixed.periods(0));
    worst = std::max(worst, worst_relative(bm.periods, expected));
  }
  RecordProperty("worst_relative_difference", sci(worst));
}

// A cone above nu = 1/3 rocks the soil trapped under the footing, Delta M_theta =
// 0.3 pi (nu - 1/3) rho r^5 (Wolf 1994; physics.md section 5a), with the base: the periods are
// those of the relative model whose rotary inertia is I_0 + Delta M_theta + sum J, and differ
// from those without the trapped soil. Below 1/3 there is none.
TEST(BuildingOnBase, ConeAboveOneThirdRocksTheTrappedSoil) {
  for (double nu : {0.25, 0.45}) {
    SCOPED_TRACE(nu);
    Building b = uniform_building(3, 3e5, 4e8);
    b.foundation.kind = FoundationKind::cone;
    b.foundation.radius = 5.0;
    b.foundation.soil_shear_velocity = 120.0;
    b.foundation.soil_density = 1800.0;
    b.foundation.soil_poisson = nu;
    b.foundation.foundation_mass = 2e5;
    b.foundation.foundation_inertia = 1e6;
    b.foundation.floor_inertias.assign(3, 2e6);
    const double trapped =
        nu > 1.0 / 3.0 ? 0.3 * M_PI * (nu - 1.0 / 3.0) * 1800.0 * std::pow(5.0, 5) : 0.0;
    const FoundationConstants f = foundation_constants(b.foundation);
    EXPECT_NEAR(f.trapped_rocking_inertia, trapped, 1e-12 * (trapped + 1.0));
    const BaseMatrices bm = assemble_on_base(b);
    EXPECT_NEAR(bm.M(4, 4), 1e6 + trapped + 6e6, 1e-12 * bm.M(4, 4));
    const Eigen::VectorXd expected = relative_model_periods(b);
    ASSERT_EQ(bm.periods.size(), 5);
    ASSERT_EQ(expected.size(), 5);
    for (int i = 0; i < 5; ++i)
      EXPECT_NEAR(bm.periods(i), expected(i), 1e-10 * expected(i)) << "mode " << i + 1;
    if (trapped > 0.0) {
      // Without the trapped soil (springs of the same constants): other periods.
      Building s = b;
      s.foundation = springs(f.sway_stiffness, f.rocking_stiffness, 2e5, 1e6, {2e6, 2e6, 2e6});
      const BaseMatrices without = assemble_on_base(s);
      EXPECT_GT(worst_relative(bm.periods, without.periods), 1e-4);
    }
  }
}

// The damping ratio of each mode, phi^T C phi / (2 omega phi^T M phi), is a ratio of quadratic
// forms and does not depend on the coordinates: the relative model, solved here by a
// generalized eigensolver, gives the library's BaseMatrices::damping_ratios. A massive base;
// longest period first.
Eigen::VectorXd relative_model_damping(const Building& b) {
  const RelativeModel r = relative_model(b);
  const int m = static_cast<int>(r.M.rows());
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(r.K, r.M);  // phi^T M phi = 1
  Eigen::VectorXd zeta(m);
  for (int i = 0; i < m; ++i) {  // ascending omega^2: longest period first
    const Eigen::VectorXd phi = eig.eigenvectors().col(i);
    zeta(i) = phi.dot(r.C * phi) / (2.0 * std::sqrt(eig.eigenvalues()(i)));
  }
  return zeta;
}

// The modal damping ratios against the relative model: on a fixed base (Rayleigh damping, 5 %
// at its two anchor modes), with springs and dashpots, and for a raft on Wolf's cone (the 5-storey
// building of studies/ssi-soft-soil.ini as it stood before issue 38: a 20 m square plan as the
// equal-area disk, r = 11.3 m; the study now stands on Gazetas footings of the thesis' 20 m x 8 m
// plan), whose shortest-period mode is overdamped by the cone's radiation dashpots (about 5:
// C_x / (2 sqrt(K_x m0)) alone).
TEST(BuildingOnBase, ModalDampingRatiosMatchTheRelativeModel) {
  Building three;
  three.masses = {1.2e5, 1.0e5, 0.7e5};
  three.stiffnesses = {9e7, 7e7, 4e7};
  three.storey_heights = {4.0, 3.2, 3.0};
  three.damping_ratio = 0.05;
  {
    const BaseMatrices fixed = assemble_on_base(three);
    ASSERT_EQ(fixed.damping_ratios.size(), 3);
    const BuildingMatrices bm = assemble(three);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(bm.K, bm.M);
    for (int i = 0; i < 3; ++i) {
      const Eigen::VectorXd phi = eig.eigenvectors().col(i);
      EXPECT_NEAR(fixed.damping_ratios(i),
                  phi.dot(bm.C * phi) / (2.0 * std::sqrt(eig.eigenvalues()(i))), 1e-10);
      EXPECT_LT(fixed.damping_ratios(i), 0.2);
    }
    EXPECT_NEAR(fixed.damping_ratios(0), 0.05, 1e-10);  // an anchor of the Rayleigh damping
  }
  Building on_springs = three;
  on_springs.foundation = test::springs_foundation(6e8, 2e11, 3e7, 4e9, 2e5, 3e6);
  on_springs.foundation.floor_inertias = {1e6, 8e5, 6e5};
  Building on_cone = uniform_building(5, 48e3, 8.4e7);
  on_cone.damping_ratio = 0.05;
  on_cone.foundation = test::cone_foundation(11.3, 150.0, 1800.0, 0.4, 48e3, 1.6e6);
  on_cone.foundation.floor_inertias = {1.6e6};
  for (const Building* b : {&on_springs, &on_cone}) {
    const BaseMatrices bm = assemble_on_base(*b);
    const Eigen::VectorXd expected = relative_model_damping(*b);
    ASSERT_EQ(bm.damping_ratios.size(), expected.size());
    for (int i = 0; i < expected.size(); ++i)
      EXPECT_NEAR(bm.damping_ratios(i), expected(i), 1e-9 * std::max(1.0, expected(i)))
          << "mode " << i + 1;
  }
  const BaseMatrices cone = assemble_on_base(on_cone);
  const FoundationConstants f = foundation_constants(on_cone.foundation);
  EXPECT_NEAR(f.sway_damping / (2.0 * std::sqrt(f.sway_stiffness * 48e3)), 5.2, 0.1);
  EXPECT_GT(cone.damping_ratios(cone.damping_ratios.size() - 1), 1.0);
  // The ratios are the classical estimate; the state matrix [0 I; -M^-1 K, -M^-1 C] of the
  // non-classically damped system says the same: as many oscillating root pairs as modes below
  // 1 (the raft's sway and rocking become four real roots, -2243, -244, -45 and -22 1/s), the
  // fastest at the shortest such mode's period to 1 %.
  const int n = cone.dofs();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  const Eigen::MatrixXd Mi = cone.M.inverse();
  A.bottomLeftCorner(n, n) = -Mi * cone.K0;
  A.bottomRightCorner(n, n) = -Mi * cone.C;
  Eigen::EigenSolver<Eigen::MatrixXd> es(A);
  int pairs = 0, below = 0;
  double fastest = 0.0, shortest = 1e9;
  for (int i = 0; i < 2 * n; ++i)
    if (es.eigenvalues()(i).imag() > 0.0) {
      ++pairs;
      fastest = std::max(fastest, es.eigenvalues()(i).imag());
    }
  for (int i = 0; i < cone.periods.size(); ++i)
    if (cone.damping_ratios(i) < 1.0) ++below, shortest = std::min(shortest, cone.periods(i));
  EXPECT_EQ(pairs, below);
  EXPECT_EQ(below, 5);
  EXPECT_NEAR(2.0 * M_PI / fastest, shortest, 0.01 * shortest);
}

// The solvers' automatic step is a twentieth of the shortest period of a mode that oscillates
// (step_period): on fixed bases every mode does, so it is the shortest period bit for bit; for
// the soft-soil pair on cone rafts (the study's pair before issue 38, 20 m and 12 m square
// plans) the overdamped raft modes (undamped periods of 0.01-0.03 s) are left out, and what
// remains is the buildings' own highest storey modes, within 15 % of the fixed-base buildings'
// shortest periods (the foundation lengthens them a little).
TEST(BuildingOnBase, StepPeriodLeavesOutOverdampedModes) {
  BuildingRow row;
  row.buildings = {uniform_building(5, 48e3, 8.4e7), uniform_building(3, 29e3, 6.7e7)};
  row.gaps = {{0.01, 0.01, 0.01}};
  for (Building& b : row.buildings) b.damping_ratio = 0.05;
  const AssembledRow fixed = assemble(row);
  EXPECT_EQ(step_period(fixed), shortest_period(fixed));
  row.buildings[0].foundation = test::cone_foundation(11.3, 150.0, 1800.0, 0.4, 48e3, 1.6e6);
  row.buildings[0].foundation.floor_inertias = {1.6e6};
  row.buildings[1].foundation = test::cone_foundation(6.8, 150.0, 1800.0, 0.4, 29e3, 3.48e5);
  row.buildings[1].foundation.floor_inertias = {3.48e5};
  const AssembledRow soil = assemble(row);
  EXPECT_LT(shortest_period(soil), 0.04);
  EXPECT_GT(step_period(soil), shortest_period(soil));
  EXPECT_GE(step_period(soil), shortest_period(fixed));
  EXPECT_LT(step_period(soil), 1.15 * shortest_period(fixed));
  for (std::size_t b = 0; b < soil.periods.size(); ++b)
    for (int i = 0; i < soil.periods[b].size(); ++i)
      if (soil.periods[b](i) < step_period(soil)) {
        EXPECT_GE(soil.damping_ratios[b](i), 1.0);
      }
}

// A base too light for its spring and dashpot (issue 38, drop_light_base_masses): where the
// base's own root, (c + sqrt(c^2 - 4 m k)) / (2 m) overdamped or sqrt(k / m), times the
// fixed-base building's shortest period reaches 1e4, its mass is taken as 0; just below, kept.
// The sway of an SDOF (T = 0.5 s) on springs K_x = 1e9 N/m, C_x = 1e7 N s/m: overdamped for
// m0 < C^2 / (4 K) = 2.5e4 kg, fast root ~ C / m0, so the bound lies near m0 = C T / 1e4 = 500 kg.
TEST(BuildingOnBase, ABaseTooLightForItsDashpotIsTakenMassless) {
  Building b = uniform_building(1, 1e5, 4.0 * M_PI * M_PI * 1e5 / 0.25);
  const double t = assemble(b).periods(0), cx = 1e7, kx = 1e9;
  ASSERT_NEAR(t, 0.5, 1e-9);
  auto rate = [&](double m) { return (cx + std::sqrt(cx * cx - 4.0 * m * kx)) / (2.0 * m); };
  for (const double m0 : {400.0, 480.0, 520.0, 600.0, 4e4}) {
    SCOPED_TRACE(m0);
    b.foundation = test::springs_foundation(kx, 1e12, cx, 1e3, m0, 1e6);
    const BaseMatrices a = assemble_on_base(b);
    const bool light = rate(m0) * t >= 1e4;
    EXPECT_EQ(a.M(1, 1), light ? 0.0 : m0);
    EXPECT_EQ(a.M(2, 2), 1e6);  // the rotation (its own root slow) keeps its inertia
    EXPECT_EQ(a.light_base, light ? std::vector<int>{1} : std::vector<int>{});
    EXPECT_EQ(a.periods.size(), light ? 2 : 3);  // the raft's own mode gone with its mass
  }
  EXPECT_GE(rate(480.0) * t, 1e4);  // the cases straddle the bound
  EXPECT_LT(rate(520.0) * t, 1e4);
}

// base_roots(m, c, k) against the quadratic m s^2 + c s + k = 0 it solves: overdamped, the two
// real rates r satisfy m r^2 - c r + k = 0 (s = -r) and Vieta's slow + fast = c / m,
// slow x fast = k / m; oscillating, both are |s| = sqrt(k / m); massless, both k / c (the
// first-order DOF c x' + k x = 0). Cases: the study's 48 t raft on its Gazetas sway constants
// (overdamped), a 100 kg raft on them, a raft on stiff springs with a small dashpot
// (oscillating), one near critical damping, and one so overdamped (4 m k / c^2 = 4e-7) that the
// slow root written (c - sqrt(disc)) / (2 m) would lose about 1e-9 of itself to cancellation,
// a residual a thousand times the test's tolerance.
TEST(BuildingOnBase, BaseRootsSolveTheirQuadratic) {
  struct Case {
    double m, c, k;
  };
  for (const Case& q :
       {Case{4.8e4, 4.32e7, 1.45e9}, Case{100.0, 4.32e7, 1.45e9}, Case{100.0, 1e3, 1e13},
        Case{1.0, 1e8, 1e9}, Case{4.8e4, 2.0 * std::sqrt(4.8e4 * 2.0e9) * (1.0 + 1e-12), 2.0e9}}) {
    const BaseRoots r = base_roots(q.m, q.c, q.k);
    const bool over = q.c * q.c > 4.0 * q.m * q.k;
    EXPECT_EQ(r.real, over);
    if (over) {
      EXPECT_LE(r.slow, r.fast);
      EXPECT_NEAR(r.slow + r.fast, q.c / q.m, 1e-12 * q.c / q.m);
      EXPECT_NEAR(r.slow * r.fast, q.k / q.m, 1e-11 * q.k / q.m);
      for (const double x : {r.slow, r.fast})  // each a root, against the terms' size
        EXPECT_NEAR(q.m * x * x - q.c * x + q.k, 0.0, 1e-12 * (q.m * x * x + q.c * x + q.k));
    } else {
      EXPECT_DOUBLE_EQ(r.slow, std::sqrt(q.k / q.m));
      EXPECT_DOUBLE_EQ(r.fast, r.slow);
    }
  }
  const BaseRoots massless = base_roots(0.0, 2.0e3, 1.0e13);
  EXPECT_TRUE(massless.real);
  EXPECT_DOUBLE_EQ(massless.slow, 1.0e13 / 2.0e3);
  EXPECT_DOUBLE_EQ(massless.fast, massless.slow);
}

}  // namespace
}  // namespace pound

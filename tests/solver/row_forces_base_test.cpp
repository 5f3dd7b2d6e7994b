// The O(n) forces of a row with buildings on flexible foundations (issue 29; RowForces'
// storey-by-storey path, docs/integration.md "Right-hand side") against the matrices:
// K_t u + off + C v with K_t, off and C as the compressed rows assemble them (the assembled K
// and C of structure/building_on_base.hpp at the initial stiffness), for random states of
// elastic, bilinear and deteriorating (imk) storeys, with and without P-Delta, with initial or
// tangent-stiffness Rayleigh damping and with modal damping, on a cone, on springs, beside a
// fixed base and on a massless base.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../support/buildings.hpp"
#include "../support/random_branches.hpp"
#include "solver/row_forces.hpp"

namespace pound {
namespace {

struct Case {
  std::string law = "elastic";
  bool p_delta = false;
  bool tangent = false;  // damping_stiffness = tangent
  bool modal = false;    // damping = modal
  bool fixed_right = false;
  bool massless = false;
};

std::string name_of(const Case& c) {
  return c.law + (c.p_delta ? " p-delta" : "") + (c.tangent ? " tangent" : "") +
         (c.modal ? " modal" : "") + (c.fixed_right ? " beside a fixed base" : "") +
         (c.massless ? " massless base" : "");
}

// The chapter 8 pair, the 5-storey building on a cone (the soft-soil study's footing and
// soil) and the 3-storey one on springs (or a fixed base).
AssembledRow row_of(const Case& c) {
  BuildingRow row = test::chapter8_pair(0.01);
  const double fy[2] = {1.0e6, 4.0e5};
  for (int b = 0; b < 2; ++b) {
    Building& bd = row.buildings[b];
    bd.hysteresis = c.law;
    if (c.law != "elastic") bd.yield_shears.assign(bd.floors(), fy[b]);
    bd.p_delta = c.p_delta;
    if (c.tangent) bd.damping_stiffness = DampingStiffness::tangent;
    if (c.modal) bd.damping = DampingKind::modal;
  }
  row.buildings[0].foundation = test::cone_foundation(
      11.3, 150.0, 1800.0, 0.4, c.massless ? 0.0 : 48e3, c.massless ? 0.0 : 1.6e6);
  if (!c.massless) row.buildings[0].foundation.floor_inertias = {1.6e6};
  if (!c.fixed_right)
    row.buildings[1].foundation =
        test::springs_foundation(1.0e9, 3.0e10, 3.0e7, 6.0e8, 29e3, 3.48e5);
  return assemble(row);
}

// dv of the O(n) path against -M^-1 (K u + off + C v) of the matrices, to rounding: each
// entry within 1e-13 of the sum of the magnitudes of its terms.
void expect_same(const Eigen::MatrixXd& K, const std::vector<double>& off, const Eigen::MatrixXd& C,
                 const AssembledRow& a, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                 const Eigen::VectorXd& dv, const std::string& what) {
  const int n = a.dofs();
  for (int i = 0; i < n; ++i) {
    double f = off[i], mag = std::fabs(off[i]);
    for (int j = 0; j < n; ++j) {
      f += K(i, j) * u(j) + C(i, j) * v(j);
      mag += std::fabs(K(i, j) * u(j)) + std::fabs(C(i, j) * v(j));
    }
    const double im = a.inv_mass(i);
    EXPECT_NEAR(dv(i), -im * f, 1e-13 * im * mag + 1e-300) << what << ", DOF " << i;
  }
}

TEST(RowForcesOnBase, StoreyByStoreyForcesAreTheMatrices) {
  std::vector<Case> cases;
  for (const std::string law : {"elastic", "bilinear", "imk"})
    for (int p_delta = 0; p_delta < 2; ++p_delta)
      for (int damping = 0; damping < 3; ++damping) {
        if (law == "elastic" && damping == 1) continue;  // (tangent: no branch to change)
        Case c;
        c.law = law;
        c.p_delta = p_delta;
        c.tangent = damping == 1;
        c.modal = damping == 2;
        cases.push_back(c);
      }
  Case mixed;
  mixed.law = "imk", mixed.p_delta = true, mixed.tangent = true, mixed.fixed_right = true;
  cases.push_back(mixed);
  Case massless;
  massless.law = "bilinear", massless.p_delta = true, massless.massless = true;
  cases.push_back(massless);

  std::mt19937 rng(29);
  for (const Case& c : cases) {
    const AssembledRow a = row_of(c);
    const int n = a.dofs();
    ASSERT_GE(a.rot[0], 0) << name_of(c);
    RowForces forces(a, a.storeys);
    const Eigen::VectorXd ag = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd dv(n), cv(n);
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd u(n), v(n);
      test::random_motion(a, rng, u.data(), v.data());
      const std::string what = name_of(c) + ", trial " + std::to_string(trial);
      // The initial stiffness and damping: the assembled K and C themselves.
      const std::vector<double> zero(n, 0.0);
      if (a.linear) {
        forces.linear(u.data(), v.data(), ag.data(), dv.data());
        expect_same(a.K, zero, a.C, a, u, v, dv, what + " (linear)");
      }
      if (!c.tangent) {
        forces.damping(v.data(), cv.data());
        const Eigen::VectorXd ref = a.C * v;
        for (int i = 0; i < n; ++i)
          EXPECT_NEAR(cv(i), ref(i), 1e-13 * (a.C.row(i).cwiseAbs() * v.cwiseAbs())(0))
              << what << " (damping), DOF " << i;
      }
      // Random branches: the tangent lines and, with tangent damping, their dampers.
      const std::vector<StoreyState> states = test::random_storey_states(a, rng);
      forces.set_lines(states);
      if (forces.tangent_damping()) forces.set_tangent_damping(states);
      Eigen::MatrixXd K, C;
      forces.stiffness(true, K);
      forces.damping_matrix(C);
      forces.affine(u.data(), v.data(), ag.data(), dv.data());
      expect_same(K, forces.offsets(), C, a, u, v, dv, what + " (affine)");
    }
  }
}

// The dense blocks of a linear row on flexible foundations (issue 38; RowForces::set_dense)
// against the storey-by-storey O(n) path (affine() on the elastic branches: the same K and C),
// within 1e-13 of the sum of the magnitudes of the terms (expect_same's tolerance); rows with a
// massless base keep the O(n) path.
TEST(RowForcesOnBase, DenseBlocksAreTheStoreyByStoreyForces) {
  std::mt19937 rng(38);
  for (int variant = 0; variant < 5; ++variant) {
    Case c;
    c.p_delta = variant == 1 || variant == 3;
    c.modal = variant == 2;
    c.fixed_right = variant == 3;
    c.massless = variant == 4;
    const AssembledRow a = row_of(c);
    const int n = a.dofs();
    ASSERT_TRUE(a.linear) << name_of(c);
    RowForces forces(a, a.storeys);
    EXPECT_EQ(forces.dense_path(), !c.massless) << name_of(c);
    forces.set_lines(std::vector<StoreyState>(n));
    const Eigen::VectorXd ag = Eigen::VectorXd::Constant(n, 2.5);
    Eigen::MatrixXd K, C;
    forces.stiffness(true, K);
    forces.damping_matrix(C);
    Eigen::VectorXd dense(n), base(n);
    for (int trial = 0; trial < 20; ++trial) {
      Eigen::VectorXd u(n), v(n);
      test::random_motion(a, rng, u.data(), v.data());
      forces.linear(u.data(), v.data(), ag.data(), dense.data());
      forces.affine(u.data(), v.data(), ag.data(), base.data());
      for (int i = 0; i < n; ++i) {
        double mag = 0.0;
        for (int j = 0; j < n; ++j) mag += std::fabs(K(i, j) * u(j)) + std::fabs(C(i, j) * v(j));
        EXPECT_NEAR(dense(i), base(i), 1e-13 * a.inv_mass(i) * mag + 1e-300)
            << name_of(c) << ", trial " << trial << ", DOF " << i;
      }
    }
  }
}

}  // namespace
}  // namespace pound

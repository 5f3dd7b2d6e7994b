// The exact steps of a row on flexible foundations (issue 38; solver/exact_steps.hpp): each
// building's block stepped in place (its padded propagator read from and written to the row's
// state) against linear_step_apply on the gathered block, bit for bit; and the derivative at a
// step's end from the blocks' own z' = A z + B w (ExactSteps::rates) against the right-hand
// side RowDynamics::rhs (its O(n) or dense forces), to rounding, at random states of elastic
// and bilinear storeys (random branches: the offsets' term), with and without P-Delta, the
// 5-storey building on a cone and the 3-storey one on springs or a fixed base.
#include "solver/exact_steps.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "../support/buildings.hpp"
#include "../support/random_branches.hpp"
#include "solver/linear_step.hpp"
#include "solver/row_dynamics.hpp"

namespace pound {
namespace {

AssembledRow soil_row(const std::string& law, bool p_delta, bool fixed_right) {
  BuildingRow row = test::chapter8_pair(0.01);
  const double fy[2] = {1.0e6, 4.0e5};
  for (int b = 0; b < 2; ++b) {
    Building& bd = row.buildings[b];
    bd.hysteresis = law;
    if (law != "elastic") bd.yield_shears.assign(bd.floors(), fy[b]);
    bd.p_delta = p_delta;
  }
  row.buildings[0].foundation = test::cone_foundation(11.3, 150.0, 1800.0, 0.4, 48e3, 1.6e6);
  row.buildings[0].foundation.floor_inertias = {1.6e6};
  if (!fixed_right)
    row.buildings[1].foundation =
        test::springs_foundation(1.0e9, 3.0e10, 3.0e7, 6.0e8, 29e3, 3.48e5);
  return assemble(row);
}

// Each storey on a random branch (test::random_storey_states), its tangent taken up.
void random_branches(const AssembledRow& a, RowDynamics& dyn, std::mt19937& rng) {
  const std::vector<StoreyState> states = test::random_storey_states(a, rng);
  for (int i = 0; i < a.dofs(); ++i) {
    if (a.storeys[i].foundation) continue;
    dyn.storey[i] = states[i];
    dyn.storey_changed(i);
  }
}

Eigen::VectorXd random_state(const AssembledRow& a, const RowDynamics& dyn, std::mt19937& rng) {
  Eigen::VectorXd y = Eigen::VectorXd::Zero(dyn.layout().size);
  test::random_motion(a, rng, y.data(), y.data() + a.dofs());
  return y;
}

// The propagators of the current stiffness (after their warm-up of grid points).
void make_ready(ExactSteps& ex, const RowDynamics& dyn, const AssembledRow& a) {
  for (int k = 0; k <= ExactStepCache::kExactWarmup && !ex.ready(dyn, a); ++k) {
  }
  ASSERT_TRUE(ex.ready(dyn, a));
}

// Building b's entries of z = [u; v]: its floors, its base's sway and rotation (ExactSteps).
std::vector<int> block_state(const AssembledRow& a, int b) {
  std::vector<int> dofs, st;
  const int nb = static_cast<int>(a.offset.size());
  const int end = b + 1 < nb ? a.offset[b + 1] : a.floors;
  for (int i = a.offset[b]; i < end; ++i) dofs.push_back(i);
  if (a.sway[b] >= 0) dofs.push_back(a.sway[b]);
  if (a.rot[b] >= 0) dofs.push_back(a.rot[b]);
  for (int i : dofs) st.push_back(i);
  for (int i : dofs) st.push_back(a.dofs() + i);
  return st;
}

TEST(ExactStepsOnBase, BlocksSteppedInPlaceAreTheGatheredSteps) {
  std::mt19937 rng(38);
  for (const bool fixed_right : {false, true}) {
    const AssembledRow a = soil_row("elastic", true, fixed_right);
    const RowDynamics dyn(a, a.storeys, false, nullptr);
    ExactStepCache cache;
    ExactSteps ex;
    ex.enable(a, 0.004, 0.0, &cache);
    make_ready(ex, dyn, a);
    const int nb = static_cast<int>(a.offset.size());
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int trial = 0; trial < 10; ++trial) {
      const Eigen::VectorXd y0 = random_state(a, dyn, rng);
      Eigen::VectorXd y1 = y0;
      const double a0[1] = {3.0 * unit(rng)}, a1[1] = {3.0 * unit(rng)};
      ex.step(1, a0, a1, y0, y1);
      // Each block's entry (the cache's, in order of the blocks) by linear_step_apply.
      for (int b = 0; b < nb; ++b) {
        const std::vector<int> st = block_state(a, b);
        const int ns = static_cast<int>(st.size());
        const ExactStepCache::Entry* e = nullptr;
        for (const auto& entry : cache.entries)
          if (entry.block == b && entry.ready) e = &entry;
        ASSERT_NE(e, nullptr);
        Eigen::VectorXd z0(ns), z1(ns), c = Eigen::VectorXd::Zero(ns);
        for (int k = 0; k < ns; ++k) z0(k) = y0(st[k]);
        linear_step_apply(e->step, 1, a0, a1, c.data(), z0.data(), z1.data());
        for (int k = 0; k < ns; ++k)
          EXPECT_EQ(y1(st[k]), z1(k)) << "building " << b << ", entry " << k;
      }
    }
  }
}

TEST(ExactStepsOnBase, RatesAreTheRightHandSide) {
  std::mt19937 rng(29);
  struct Case {
    std::string law;
    bool p_delta, fixed_right;
  };
  for (const Case& c : {Case{"elastic", false, false}, Case{"elastic", true, false},
                        Case{"bilinear", true, false}, Case{"bilinear", false, true}}) {
    const std::string name =
        c.law + (c.p_delta ? ", P-Delta" : "") + (c.fixed_right ? ", beside a fixed base" : "");
    const AssembledRow a = soil_row(c.law, c.p_delta, c.fixed_right);
    const int n = a.dofs();
    RowDynamics dyn(a, a.storeys, false, nullptr);
    for (int trial = 0; trial < 10; ++trial) {
      if (c.law != "elastic") random_branches(a, dyn, rng);
      ExactSteps ex;
      ex.enable(a, 0.004, 0.0, nullptr);
      ASSERT_TRUE(ex.has_rates()) << name;
      make_ready(ex, dyn, a);
      Eigen::VectorXd y = random_state(a, dyn, rng);
      Eigen::VectorXd rhs, rates = Eigen::VectorXd::Zero(y.size());
      dyn.rhs(0.0, y, rhs);
      ex.rates(dyn, dyn.ground_channel_acc(0.0), y, rates);
      Eigen::MatrixXd K, C;
      dyn.stiffness(K);
      dyn.damping_matrix(C);
      const std::vector<double>& off = dyn.offsets();
      for (int i = 0; i < n; ++i) {
        EXPECT_EQ(rates(i), rhs(i)) << name << ", u' of DOF " << i;
        // Within 1e-12 of the sum of the magnitudes of the force's terms.
        double mag = dyn.affine() ? std::fabs(off[i]) : 0.0;
        for (int j = 0; j < n; ++j)
          mag += std::fabs(K(i, j) * y(j)) + std::fabs(C(i, j) * y(n + j));
        EXPECT_NEAR(rates(n + i), rhs(n + i), 1e-12 * a.inv_mass(i) * mag)
            << name << ", trial " << trial << ", v' of DOF " << i;
      }
    }
  }
}

}  // namespace
}  // namespace pound

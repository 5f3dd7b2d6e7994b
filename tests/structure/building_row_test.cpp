#include "structure/building_row.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "../support/buildings.hpp"
#include "core/error.hpp"

namespace pound {
namespace {

using test::uniform_building;

TEST(Building, TwoStoreyPeriodsMatchClosedForm) {
  // Uniform 2-storey shear building: w^2 = (3 -/+ sqrt 5) / 2 k / m (Chopra example 10.1).
  const double m = 1000.0, k = 1e6;
  const BuildingMatrices bm = assemble(uniform_building(2, m, k));
  const double w1 = std::sqrt((3 - std::sqrt(5.0)) / 2 * k / m);
  const double w2 = std::sqrt((3 + std::sqrt(5.0)) / 2 * k / m);
  EXPECT_NEAR(bm.periods(0), 2 * M_PI / w1, 1e-12);
  EXPECT_NEAR(bm.periods(1), 2 * M_PI / w2, 1e-12);
}

TEST(Building, RayleighAndModalDampingGiveTheRatioOnTheirModes) {
  for (DampingKind kind : {DampingKind::rayleigh, DampingKind::modal}) {
    Building b = uniform_building(4, 2000.0, 3e6, 0.05);
    b.damping = kind;
    const BuildingMatrices bm = assemble(b);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(bm.K, bm.M);
    const int checked = kind == DampingKind::modal ? 4 : 2;
    for (int i = 0; i < checked; ++i) {
      const Eigen::VectorXd phi = eig.eigenvectors().col(i);
      const double w = std::sqrt(eig.eigenvalues()(i));
      const double xi = phi.dot(bm.C * phi) / (2 * w * phi.dot(bm.M * phi));
      EXPECT_NEAR(xi, 0.05, 1e-12) << "mode " << i + 1;
    }
  }
}

// One storey: mass-proportional damping, or with damping_stiffness = tangent (whose changes act
// on the stiffness-proportional part) stiffness-proportional; the same ratio xi on its mode.
TEST(Building, OneStoreyIsDampedByItsMassOrWithTangentDampingByItsStiffness) {
  for (DampingStiffness ds : {DampingStiffness::initial, DampingStiffness::tangent}) {
    Building b = uniform_building(1, 2000.0, 3e6, 0.05);
    b.damping_stiffness = ds;
    const BuildingMatrices bm = assemble(b);
    const double w = std::sqrt(3e6 / 2000.0);
    EXPECT_NEAR(bm.C(0, 0) / (2 * w * 2000.0), 0.05, 1e-14);
    if (ds == DampingStiffness::tangent) {
      EXPECT_EQ(bm.rayleigh_a0, 0.0);
      EXPECT_NEAR(bm.rayleigh_a1, 2 * 0.05 / w, 1e-15);
    } else {
      EXPECT_NEAR(bm.rayleigh_a0, 2 * 0.05 * w, 1e-12);
      EXPECT_EQ(bm.rayleigh_a1, 0.0);
    }
  }
}

TEST(BuildingRow, UnequalHeightsCollideUpToTheLowerRoof) {
  // A 5-storey building between a 3-storey and a 4-storey one (a row, thesis chapter 2).
  BuildingRow row;
  row.buildings = {uniform_building(3, 1e3, 1e6), uniform_building(5, 1e3, 1e6),
                   uniform_building(4, 1e3, 1e6)};
  row.gaps = {{0.01, 0.02, 0.03}, {0.0, 0.0, 0.0, 0.0}};
  const AssembledRow a = assemble(row);
  ASSERT_EQ(a.dofs(), 12);
  ASSERT_EQ(a.sites.size(), 7u);
  EXPECT_EQ(a.sites[2].dof_left, 2);   // floor 3 of building 1
  EXPECT_EQ(a.sites[2].dof_right, 5);  // floor 3 of building 2
  EXPECT_DOUBLE_EQ(a.sites[2].gap, 0.03);
  EXPECT_EQ(a.sites[6].dof_left, 3 + 3);
  EXPECT_EQ(a.sites[6].dof_right, 8 + 3);
  // Block diagonal: no coupling between buildings except through contacts.
  EXPECT_EQ(a.K.block(0, 3, 3, 9).norm(), 0.0);
}

TEST(Building, ValidationNamesTheFloor) {
  Building b = uniform_building(3, 1e3, 1e6);
  b.masses[1] = -5;
  try {
    validate(b, "study.ini:4");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("floor 2"), std::string::npos);
  }
  b.masses[1] = std::nan("");
  EXPECT_THROW(validate(b, "x"), InputError);
}

}  // namespace
}  // namespace pound

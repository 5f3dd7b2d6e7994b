// Where slabs meet (issue 36, structure/contact_geometry.hpp): the site rule at and about
// (t1 + t2) / 2, the column's sway shape, point stiffness and fixed-end reactions against an
// Euler-Bernoulli beam solved here, and the weighted points of the assembled row.
#include "structure/contact_geometry.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>
#include <vector>

#include "../support/buildings.hpp"
#include "core/error.hpp"
#include "structure/building_row.hpp"

namespace pound {
namespace {

using test::uniform_building;

// A building of n storeys of height h [m] on a base at elevation z0 [m], slabs t [m] thick.
Building at(int n, double h, double z0, double t) {
  Building b = uniform_building(n, 1e5, 5e7);
  b.storey_heights.assign(n, h);
  b.base_elevation = z0;
  b.slab_thickness = t;
  return b;
}

TEST(ContactGeometry, AlignedFloorsMeetTheirNamesakesSlabToSlab) {
  const auto g = pair_sites(at(5, 3.0, 0.0, 0.2), at(3, 3.0, 0.0, 0.2));
  ASSERT_EQ(g.size(), 3u);
  for (int j = 0; j < 3; ++j) {
    EXPECT_EQ(g[j].kind, SiteKind::slab);
    EXPECT_EQ(g[j].slab_floor, j);
    EXPECT_EQ(g[j].hit, j);
  }
}

TEST(ContactGeometry, SlabsWithinHalfTheirThicknessesMeetSlabToSlab) {
  // t1 = t2 = 0.25 m: reach 0.25 m. The right building's floors stand 0.125 m (inside),
  // 0.25 m (at the limit) and 0.375 m (outside) above the left one's.
  for (double d : {0.125, 0.25}) {
    const auto g = pair_sites(at(2, 3.0, 0.0, 0.25), at(2, 3.0, d, 0.25));
    ASSERT_EQ(g.size(), 2u) << d;
    EXPECT_EQ(g[0].kind, SiteKind::slab) << d;
    EXPECT_EQ(g[1].kind, SiteKind::slab) << d;
  }
  const auto g = pair_sites(at(2, 3.0, 0.0, 0.25), at(2, 3.0, 0.375, 0.25));
  // L's floor 1 (3.0 m) in R's storey 1 (0.375-3.375 m): xi = 2.625 / 3; R's floor 1 (3.375 m)
  // in L's storey 2 (3-6 m): xi = 0.375 / 3; L's floor 2 (6 m) in R's storey 2: xi = 2.625 / 3;
  // R's floor 2 (6.375 m) above L's roof: nothing.
  ASSERT_EQ(g.size(), 3u);
  const int side[] = {0, 1, 0}, slab[] = {0, 0, 1}, storey[] = {0, 1, 1};
  const double xi[] = {0.875, 0.125, 0.875};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(g[k].kind, SiteKind::column) << k;
    EXPECT_EQ(g[k].slab_side, side[k]) << k;
    EXPECT_EQ(g[k].slab_floor, slab[k]) << k;
    EXPECT_EQ(g[k].hit, storey[k]) << k;
    EXPECT_NEAR(g[k].xi, xi[k], 1e-15) << k;
  }
}

TEST(ContactGeometry, SlabsBelowTheNeighboursBaseOrAboveItsRoofMeetNothing) {
  // Right building on a base 7 m up a slope: L's floors at 3 and 6 m are below it, R's floors
  // at 10 and 13 m above L's roof.
  EXPECT_TRUE(pair_sites(at(2, 3.0, 0.0, 0.2), at(2, 3.0, 7.0, 0.2)).empty());
  // Storey heights 3.6 against 3.0 (the issue's example): six column sites, none slab to slab.
  const auto g = pair_sites(at(5, 3.0, 0.0, 0.12), at(3, 3.6, 0.0, 0.12));
  ASSERT_EQ(g.size(), 6u);
  for (const auto& s : g) EXPECT_EQ(s.kind, SiteKind::column);
}

// A column fixed at both floors, h long, bending stiffness EI, as two Euler-Bernoulli elements
// meeting at a = xi h (cubic elements are exact for nodal loads): the 6 x 6 stiffness over (w,
// theta) at the bottom, the point and the top.
Eigen::MatrixXd column_stiffness(double EI, double h, double xi) {
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(6, 6);
  const double len[] = {xi * h, (1.0 - xi) * h};
  for (int e = 0; e < 2; ++e) {
    const double L = len[e];
    Eigen::Matrix4d k;
    k << 12, 6 * L, -12, 6 * L, 6 * L, 4 * L * L, -6 * L, 2 * L * L, -12, -6 * L, 12, -6 * L, 6 * L,
        2 * L * L, -6 * L, 4 * L * L;
    K.block<4, 4>(2 * e, 2 * e) += EI / (L * L * L) * k;
  }
  return K;
}

TEST(ContactGeometry, SwayShapePointStiffnessAndReactionsAgreeWithABeam) {
  const double h = 3.2, k_storey = 6.7e7, phi = 0.5;
  const double EI = phi * k_storey * h * h * h / 12.0;  // 12 EI / h^3 = phi k_storey
  for (double xi : {0.1, 0.25, 0.5, 0.8333}) {
    const Eigen::MatrixXd K = column_stiffness(EI, h, xi);
    // The point's free DOFs (w, theta) = rows 2, 3; the ends fixed.
    const Eigen::Matrix2d Kpp = K.block<2, 2>(2, 2);
    // Sway: the top moved by 1 without rotation, the bottom held; no load at the point.
    const Eigen::Vector2d sway = Kpp.partialPivLu().solve(-K.block<2, 1>(2, 4));
    EXPECT_NEAR(column_shape(xi), sway(0), 1e-12) << xi;
    // A unit load at the point, both ends held: the point's deflection and the end reactions.
    const Eigen::Vector2d w = Kpp.partialPivLu().solve(Eigen::Vector2d(1.0, 0.0));
    EXPECT_NEAR(column_point_stiffness(k_storey, phi, xi), 1.0 / w(0),
                1e-9 * column_point_stiffness(k_storey, phi, xi))
        << xi;
    const Eigen::VectorXd r = K.block<6, 2>(0, 2) * w;  // the forces at the ends
    const double s = column_shape(xi);
    EXPECT_NEAR(-r(0), 1.0 - s, 1e-12) << xi;  // the bottom floor takes F (1 - s)
    EXPECT_NEAR(-r(4), s, 1e-12) << xi;        // the top floor F s
  }
  EXPECT_EQ(column_shape(0.5), 0.5);
  EXPECT_DOUBLE_EQ(column_point_stiffness(1.0, 1.0, 0.5), 16.0);
}

TEST(ContactGeometry, ColumnPointsWeighTheFloorsAndTheBase) {
  // L: 3 m storeys; R: 3.6 m. L's floor 2 (6 m) strikes R's storey 2 (3.6-7.2 m) at xi = 2/3;
  // R's floor 1 (3.6 m) strikes L's storey 2 at xi = 0.2; L's floor 1 (3 m) R's storey 1 at
  // xi = 5/6 (on R's fixed base: floor 1 alone, weight s).
  BuildingRow row;
  row.buildings = {at(3, 3.0, 0.0, 0.2), at(2, 3.6, 0.0, 0.2)};
  row.buildings[1].masses = {2e5, 1e5};
  row.gaps = {std::vector<double>(static_cast<std::size_t>(colliding_levels(row, 0)), 0.01)};
  const AssembledRow a = assemble(row);
  ASSERT_EQ(a.sites.size(), 4u);  // 3.0, 3.6, 6.0, 7.2 (R's roof in L's storey 3)
  const ContactSite& s0 = a.sites[0];
  const double s56 = column_shape(5.0 / 6.0);
  ASSERT_EQ(s0.right.count, 1);
  EXPECT_EQ(s0.right.dof[0], 3);
  EXPECT_DOUBLE_EQ(s0.right.weight[0], s56);
  EXPECT_DOUBLE_EQ(s0.mass_right, 2e5 / (s56 * s56));
  EXPECT_DOUBLE_EQ(s0.mass_left, 1e5);
  const ContactSite& s2 = a.sites[2];
  const double s23 = column_shape(2.0 / 3.0);
  ASSERT_EQ(s2.right.count, 2);
  EXPECT_EQ(s2.right.dof[0], 3);
  EXPECT_EQ(s2.right.dof[1], 4);
  EXPECT_DOUBLE_EQ(s2.right.weight[0] + s2.right.weight[1], 1.0);
  EXPECT_NEAR(s2.mass_right, 1.0 / ((1 - s23) * (1 - s23) / 2e5 + s23 * s23 / 1e5), 1e-9);
  EXPECT_NEAR(s2.column_stiffness, 0.5 * 5e7 / (4 * std::pow(2.0 / 9.0, 3)), 1e-3);
  EXPECT_TRUE(std::isfinite(a.sites[1].column_stiffness));
  EXPECT_EQ(a.sites[1].left.count, 2);  // R's slab against L's floors 1 and 2
  EXPECT_EQ(a.sites[1].left.dof[0], 0);
  EXPECT_EQ(a.sites[1].right.dof[0], 3);
}

TEST(ContactGeometry, AGapListOfAnotherLengthThanTheSitesIsAnInputError) {
  // The row above has four sites; a row built by hand with the aligned pair's three gaps is
  // refused by assemble() with a line naming the pair and the counts (the study readers
  // expand one gap to every site, pound simulate lists them).
  BuildingRow row;
  row.buildings = {at(3, 3.0, 0.0, 0.2), at(2, 3.6, 0.0, 0.2)};
  row.buildings[0].name = "L";
  row.buildings[1].name = "R";
  row.gaps = {{0.01, 0.01, 0.01}};
  try {
    assemble(row);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(),
                 "pair 1 (L | R): 3 gaps for its 4 contact sites; valid: one gap per site, in "
                 "the order pound simulate lists them");
  }
}

TEST(ContactGeometry, BuildingsWithoutNamesAreNamedByTheirPlaceInTheRow) {
  // A row built by hand (or from Python) may leave the names empty: the messages and the site
  // lines then say "building N", never an empty name.
  BuildingRow row;
  row.buildings = {at(3, 3.0, 0.0, 0.2), at(2, 3.6, 0.0, 0.2)};
  row.gaps = {{0.01}};
  try {
    assemble(row);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("pair 1 (building 1 | building 2): 1 gaps for its 4", 0),
              0u)
        << e.what();
  }
  const std::vector<std::string> lines = describe_sites(row);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_NE(lines[0].find("building 1 floor"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("against building 2"), std::string::npos) << lines[0];
}

}  // namespace
}  // namespace pound

// The displacements the code rules combine at a contact site (issue 36): a slab's own floor, a
// struck point (1 - s) u_{j-1} + s u_j with s = 3 xi^2 - 2 xi^3 and u_0 = 0, values worked by
// hand; and EN 1998-1 4.4.2.7(3)'s case from the sites.
#include "risk/site_displacements.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pound {
namespace {

const std::vector<double> kU = {0.01, 0.03, 0.06};  // peak displacement of floors 1-3 [m]

SiteGeometry column_site(int slab_side, int slab_floor, int storey, double xi) {
  SiteGeometry g;
  g.kind = SiteKind::column;
  g.slab_side = slab_side;
  g.slab_floor = slab_floor;
  g.hit = storey;
  g.xi = xi;
  return g;
}

TEST(SiteDisplacements, TheStruckPointSwaysAsTheColumnBetweenItsFloors) {
  // Storey 2 (0-based 1) at mid-height: s = 0.5, halfway between 0.01 and 0.03.
  EXPECT_NEAR(struck_point_displacement(kU, 1, 0.5), 0.02, 1e-15);
  // At xi = 0.25: s = 3/16 - 2/64 = 0.15625; 0.84375 x 0.01 + 0.15625 x 0.03 = 0.013125.
  EXPECT_NEAR(struck_point_displacement(kU, 1, 0.25), 0.013125, 1e-15);
  // Storey 1 stands on the base (u_0 = 0): at xi = 0.4, s = 0.48 - 0.128 = 0.352, 0.00352.
  EXPECT_NEAR(struck_point_displacement(kU, 0, 0.4), 0.00352, 1e-15);
  // At the floors themselves: the floors' own values.
  EXPECT_EQ(struck_point_displacement(kU, 2, 1.0), 0.06);
  EXPECT_EQ(struck_point_displacement(kU, 2, 0.0), 0.03);
}

TEST(SiteDisplacements, EachSideTakesItsSlabOrItsStruckPoint) {
  const std::vector<double> right = {0.005, 0.02};
  SiteGeometry slab;  // left floor 2 against right floor 2: their own values
  slab.slab_floor = 1;
  slab.hit = 1;
  SiteDisplacements d = site_displacements(slab, kU, right);
  EXPECT_EQ(d.left, 0.03);
  EXPECT_EQ(d.right, 0.02);
  // The left building's floor 3 strikes the right one's storey 2 at xi = 0.25:
  // 0.84375 x 0.005 + 0.15625 x 0.02 = 0.00734375.
  d = site_displacements(column_site(0, 2, 1, 0.25), kU, right);
  EXPECT_EQ(d.left, 0.06);
  EXPECT_NEAR(d.right, 0.00734375, 1e-15);
  // The right building's floor 1 strikes the left one's storey 1 at xi = 0.5: 0.5 x 0.01.
  d = site_displacements(column_site(1, 0, 0, 0.5), kU, right);
  EXPECT_NEAR(d.left, 0.005, 1e-15);
  EXPECT_EQ(d.right, 0.005);
  // A floor the lists do not hold: NaN, not a read past the end.
  EXPECT_TRUE(std::isnan(site_displacements(column_site(0, 3, 1, 0.5), kU, right).left));
  EXPECT_TRUE(std::isnan(site_displacements(column_site(1, 0, 3, 0.5), kU, right).left));
}

TEST(SiteDisplacements, FloorsCoincideOnlyWhereEverySiteIsSlabToSlab) {
  EXPECT_EQ(ec8_case(same_index_sites(3)), Ec8Case::floors_coincide);
  std::vector<SiteGeometry> sites = same_index_sites(2);
  EXPECT_EQ(sites[1].slab_floor, 1);
  EXPECT_EQ(sites[1].hit, 1);
  sites.push_back(column_site(1, 2, 1, 0.3));
  EXPECT_EQ(ec8_case(sites), Ec8Case::floors_offset);
  EXPECT_EQ(ec8_case({}), Ec8Case::floors_offset);  // no site: nothing to reduce
}

}  // namespace
}  // namespace pound

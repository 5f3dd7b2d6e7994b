// The contact sites of a campaign's row, read from the study stored in its file (issue 36):
// aligned floors meet slab to slab; a row with offset floors (worked by hand below) meets its
// neighbour's columns; a stored study this version cannot read is an error naming the file.
#include "risk/study_sites.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

namespace pound {
namespace {

// Two 2-storey buildings, their keys as a campaign file stores them ("key = value", sorted).
std::string two_buildings(const std::string& heights_left, const std::string& heights_right) {
  return "building1.masses = 1e5, 1e5\n"
         "building1.stiffnesses = 1e8, 1e8\n"
         "building1.storey_heights = " +
         heights_left +
         "\n"
         "building2.masses = 1e5, 1e5\n"
         "building2.stiffnesses = 1e8, 1e8\n"
         "building2.storey_heights = " +
         heights_right +
         "\n"
         "pair1.gap = 0.01\n";
}

CampaignData stored(const std::string& study) {
  CampaignData c;
  c.path = "run.h5";
  c.study = study;
  return c;
}

TEST(StudySites, AlignedFloorsMeetSlabToSlab) {
  const auto sites = study_pair_sites(stored(two_buildings("3, 3", "3, 3")));
  ASSERT_EQ(sites.size(), 1u);
  ASSERT_EQ(sites[0].size(), 2u);
  for (int l = 0; l < 2; ++l) {
    EXPECT_EQ(sites[0][l].kind, SiteKind::slab);
    EXPECT_EQ(sites[0][l].slab_floor, l);
    EXPECT_EQ(sites[0][l].hit, l);
  }
}

TEST(StudySites, OffsetFloorsStrikeTheNeighboursColumns) {
  // Left floors at 4 and 8 m, right floors at 2 and 6 m (slabs 0.2 m: within 0.2 m is slab to
  // slab). Right floor 1 (2 m) strikes left storey 1 (0-4 m) at xi 0.5; left floor 1 (4 m)
  // right storey 2 (2-6 m) at xi 0.5; right floor 2 (6 m) left storey 2 (4-8 m) at xi 0.5;
  // left floor 2 (8 m) stands above the right roof: nothing.
  const auto sites = study_pair_sites(stored(two_buildings("4, 4", "2, 4")));
  ASSERT_EQ(sites.size(), 1u);
  ASSERT_EQ(sites[0].size(), 3u);
  const int side[] = {1, 0, 1}, floor[] = {0, 0, 1}, storey[] = {0, 1, 1};
  const double z[] = {2.0, 4.0, 6.0};
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(sites[0][k].kind, SiteKind::column) << k;
    EXPECT_EQ(sites[0][k].slab_side, side[k]) << k;
    EXPECT_EQ(sites[0][k].slab_floor, floor[k]) << k;
    EXPECT_EQ(sites[0][k].hit, storey[k]) << k;
    EXPECT_DOUBLE_EQ(sites[0][k].xi, 0.5) << k;
    EXPECT_DOUBLE_EQ(sites[0][k].elevation, z[k]) << k;
  }
}

TEST(StudySites, AnUnreadableStoredStudyNamesTheFile) {
  try {
    study_pair_sites(stored(two_buildings("3, 3", "3, 3") + "building1.no_such_key = 1\n"));
    ADD_FAILURE() << "an unknown key was read";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("run.h5"), std::string::npos) << m;
    EXPECT_NE(m.find("no_such_key"), std::string::npos) << m;
  }
  EXPECT_THROW(study_pair_sites(stored("")), InputError);  // no buildings
}

}  // namespace
}  // namespace pound

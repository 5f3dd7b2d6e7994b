// The campaign-file reader of pound fragility on damaged files (issue 14, found by
// fuzz_campaign_file): a dataset that declares more values than the file stores is refused with
// one InputError naming the file and the dataset, not a std::length_error from a vector of
// 10^18 doubles.
#include "fragility/campaign_reader.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <string>
#include <vector>

#include "../support/scratch_dir.hpp"
#include "core/error.hpp"

namespace pound {
namespace {

// A file whose /samples/status declares `rows` rows (chunked, nothing written: no storage).
std::string declaring_file(const std::string& name, hsize_t rows) {
  const std::string path = test::process_scratch_dir() / name;
  const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  const hid_t g = H5Gcreate2(f, "/samples", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  hsize_t max = H5S_UNLIMITED, chunk = 16;
  const hid_t space = H5Screate_simple(1, &rows, &max);
  const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
  H5Pset_chunk(plist, 1, &chunk);
  const hid_t d = H5Dcreate2(g, "status", H5T_NATIVE_INT, space, H5P_DEFAULT, plist, H5P_DEFAULT);
  H5Dclose(d);
  H5Pclose(plist);
  H5Sclose(space);
  H5Gclose(g);
  H5Fclose(f);
  return path;
}

TEST(CampaignReader, BuildingNamesKeepTheirPositions) {
  using V = std::vector<std::string>;
  EXPECT_EQ(split_building_names("left, right", 2), (V{"left", "right"}));
  // An empty item keeps its place (building 2 of 3 unnamed); missing ones are numbered.
  EXPECT_EQ(split_building_names("a, , c", 3), (V{"a", "building2", "c"}));
  EXPECT_EQ(split_building_names("a,", 3), (V{"a", "building2", "building3"}));
  EXPECT_EQ(split_building_names("", 2), (V{"building1", "building2"}));
  EXPECT_EQ(split_building_names(" x\t", 1), (V{"x"}));
}

TEST(CampaignReader, ADatasetDeclaringMoreValuesThanTheFileStoresIsRefused) {
  for (const hsize_t rows : {hsize_t{1} << 60, hsize_t{1000}}) {
    const std::string path = declaring_file("declares.h5", rows);
    try {
      read_campaign(path);
      FAIL() << rows << " rows without storage were read";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                path + ": /samples/status declares " + std::to_string(rows) +
                    " values but the file does not store them; a damaged file or not a campaign "
                    "result file of 'pound campaign' (schema in src/campaign/result_file.hpp)");
    }
  }
}

}  // namespace
}  // namespace pound

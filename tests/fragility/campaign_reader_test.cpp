// The campaign-file reader of pound fragility on damaged files (issue 14, found by
// fuzz_campaign_file): a dataset that declares more values than the file stores is refused with
// one InputError naming the file and the dataset, not a std::length_error from a vector of
// 10^18 doubles.
#include "fragility/campaign_reader.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "../support/h5_gzip.hpp"
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

// Bit for bit (NaN where a building has fewer floors compares equal to itself).
bool same(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

// A result file of `pound campaign` repacked with gzip (as `h5repack -f GZIP=6` leaves it)
// stores fewer bytes than its values take; fragility, summary and risk refused it as "declares
// N values but the file does not store them; a damaged file". It reads as the file as written.
TEST(CampaignReader, AResultFileCompressedWithGzipReadsAsWritten) {
  const std::string plain = test::process_scratch_dir() / "smoke.h5";
  const std::string packed = test::process_scratch_dir() / "smoke-gzip.h5";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 0);  // Open MPI's components leak at exit
  const std::string cmd = std::string(POUND_BINARY) + " campaign --config " + POUND_SOURCE_DIR +
                          "/studies/campaign-smoke.ini --quiet --samples 12 --out " + plain +
                          " 2>" + plain + ".log";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::filesystem::copy_file(plain, packed);
  ASSERT_GE(test::gzip_numeric_datasets(packed), 20);
  const CampaignData a = read_campaign(plain);
  CampaignData b;
  ASSERT_NO_THROW(b = read_campaign(packed));
  EXPECT_EQ(b.samples, 12u);
  EXPECT_EQ(b.status, a.status);
  EXPECT_TRUE(same(b.im, a.im));
  EXPECT_TRUE(same(b.scale, a.scale));
  ASSERT_EQ(b.parameters.size(), a.parameters.size());
  for (std::size_t i = 0; i < a.parameters.size(); ++i)
    EXPECT_TRUE(same(b.parameters[i].values, a.parameters[i].values)) << a.parameters[i].key;
  ASSERT_EQ(b.floor_arrays.size(), a.floor_arrays.size());
  ASSERT_FALSE(a.floor_arrays.empty());
  for (const auto& [name, arr] : a.floor_arrays)
    EXPECT_TRUE(b.has(name) && same(b.floor_array(name).v, arr.v)) << name;
  EXPECT_TRUE(same(b.peak_force.v, a.peak_force.v));
  EXPECT_TRUE(same(b.impacts.v, a.impacts.v));
  EXPECT_TRUE(same(b.approach_free.v, a.approach_free.v));
  EXPECT_EQ(b.levels, a.levels);
}

}  // namespace
}  // namespace pound

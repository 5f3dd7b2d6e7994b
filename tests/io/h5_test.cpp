// The HDF5 helpers on damaged files. tests/io/data/fuzz-crash-group-members.h5 is the input with
// which fuzz_campaign_file (issue 14) crashed pound merge: its /samples group counts links that
// HDF5 cannot name, and a name length of -1 became a string of 2^64 - 1 characters
// (std::length_error, "internal error" instead of a one-line error).
#include "io/h5.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <string>

#include "../support/scratch_dir.hpp"
#include "campaign/merge.hpp"
#include "core/error.hpp"

namespace pound {
namespace {

const std::string kCrash =
    std::string(POUND_SOURCE_DIR) + "/tests/io/data/fuzz-crash-group-members.h5";

TEST(H5, MembersOfAGroupThatCannotNameItsLinksAreTheOnesItCanName) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(kCrash.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  H5G_info_t info;
  const hid_t g = H5Gopen2(f, "/samples", H5P_DEFAULT);
  ASSERT_GE(g, 0);
  ASSERT_GE(H5Gget_info(g, &info), 0);
  H5Gclose(g);
  std::vector<std::string> names;
  ASSERT_NO_THROW(names = h5::group_members(f, "/samples"));
  EXPECT_LT(names.size(), info.nlinks);  // the damage is there: fewer names than links
  for (const auto& n : names) EXPECT_FALSE(n.empty());
  H5Fclose(f);
}

TEST(H5, MergeOfTheDamagedFileEndsCleanly) {
  // It merges what the file names (the one part covers every sample), or says what is wrong;
  // no other exception, and nothing left open.
  const std::string out = test::process_scratch_dir() / "merged-damaged.h5";
  try {
    merge_campaign_parts({kCrash}, out);
  } catch (const InputError&) {
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

// Found by fuzz_campaign_file: an attribute of several values was read into room for one (the
// overflow happened inside HDF5's conversion, where the sanitizers do not look). Such an
// attribute reads as absent ("").
TEST(H5, AnAttributeOfSeveralValuesReadsAsAbsent) {
  const std::string path = test::process_scratch_dir() / "attributes.h5";
  {
    h5::File f(path);
    hsize_t three = 3;
    const double v[3] = {4, 5, 6};
    const hid_t s = H5Screate_simple(1, &three, nullptr);
    const hid_t a = H5Acreate2(f.id(), "seed", H5T_NATIVE_DOUBLE, s, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_DOUBLE, v);
    H5Aclose(a);
    const hid_t str = H5Tcopy(H5T_C_S1);
    H5Tset_size(str, 4);
    const hid_t b = H5Acreate2(f.id(), "study", str, s, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(b, str, "abcdefghijkl");
    H5Aclose(b);
    H5Tclose(str);
    H5Sclose(s);
    h5::attribute(f.id(), "/", "one", 7.0);
    f.close();
  }
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_EQ(h5::root_attribute_text(f, "seed"), "");
  EXPECT_EQ(h5::root_attribute_text(f, "study"), "");
  EXPECT_EQ(h5::root_attribute_text(f, "one"), "7");
  H5Fclose(f);
}

}  // namespace
}  // namespace pound

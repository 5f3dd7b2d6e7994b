// The HDF5 helpers on damaged files. tests/io/data/fuzz-crash-group-members.h5 is the input with
// which fuzz_campaign_file (issue 14) crashed pound merge: its /samples group counts links that
// HDF5 cannot name, and a name length of -1 became a string of 2^64 - 1 characters
// (std::length_error, "internal error" instead of a one-line error).
#include "io/h5.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <string>
#include <utility>
#include <vector>

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

// An integer-list attribute (a campaign file's floors, one per building) reads back as written,
// as integers; as text it is absent when it holds several values and its number when one.
TEST(H5, AnIntegerListAttributeReadsBack) {
  const std::string path = test::process_scratch_dir() / "integers.h5";
  {
    h5::File f(path);
    h5::attribute(f.id(), "/", "floors", std::vector<int>{5, 3});
    h5::attribute(f.id(), "/", "one", std::vector<int>{4});
    f.close();
  }
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t a = H5Aopen(f, "floors", H5P_DEFAULT);
  const hid_t t = H5Aget_type(a), s = H5Aget_space(a);
  EXPECT_EQ(H5Tget_class(t), H5T_INTEGER);
  ASSERT_EQ(H5Sget_simple_extent_npoints(s), 2);
  std::vector<int> v(2);
  EXPECT_GE(H5Aread(a, H5T_NATIVE_INT, v.data()), 0);
  EXPECT_EQ(v, (std::vector<int>{5, 3}));
  H5Sclose(s);
  H5Tclose(t);
  H5Aclose(a);
  EXPECT_EQ(h5::root_attribute_text(f, "floors"), "");
  EXPECT_EQ(h5::root_attribute_text(f, "one"), "4");
  H5Fclose(f);
}

// A dataset compressed with gzip (as `h5repack -f GZIP=6` leaves a result file) stores fewer
// bytes than its values take; it was refused as "declares N values but the file does not store
// them". It is read whole, the same values. One whose chunks are not all in the file (2^60 rows
// declared, or a chunk never written) is still refused in one line (not a std::length_error),
// and so is one whose chunk stores far fewer bytes than gzip could unpack its values from (found
// in review: 128 MB were allocated before H5Dread failed on the chunk).
TEST(H5, ACompressedDatasetIsReadWholeAndOneWithoutItsChunksRefused) {
  const std::string path = test::process_scratch_dir() / "compressed.h5";
  std::vector<double> x(4000);
  std::vector<int> k(3000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = 0.5 * double(i % 10) - 1.25;
  for (std::size_t i = 0; i < k.size(); ++i) k[i] = int(i % 3);
  {
    h5::File f(path);
    // A gzip dataset of `rows` in chunks of `chunk`, its first `written` rows written.
    auto compressed = [&](const char* name, hid_t type, hsize_t rows, hsize_t chunk,
                          const void* data, hsize_t written) {
      const hid_t space = H5Screate_simple(1, &rows, nullptr);
      const hid_t dcpl = H5Pcreate(H5P_DATASET_CREATE);
      H5Pset_chunk(dcpl, 1, &chunk);
      H5Pset_deflate(dcpl, 6);
      const hid_t d = H5Dcreate2(f.id(), name, type, space, H5P_DEFAULT, dcpl, H5P_DEFAULT);
      if (written) {
        const hsize_t start = 0;
        H5Sselect_hyperslab(space, H5S_SELECT_SET, &start, nullptr, &written, nullptr);
        const hid_t mem = H5Screate_simple(1, &written, nullptr);
        H5Dwrite(d, type, mem, space, H5P_DEFAULT, data);
        H5Sclose(mem);
      }
      const hsize_t stored = H5Dget_storage_size(d);
      H5Dclose(d);
      H5Pclose(dcpl);
      H5Sclose(space);
      return stored;
    };
    // The check that refused them: fewer bytes stored than the values take.
    EXPECT_LT(compressed("/x", H5T_NATIVE_DOUBLE, x.size(), 1000, x.data(), x.size()),
              x.size() * 8 / 4);
    EXPECT_LT(compressed("/k", H5T_NATIVE_INT, k.size(), 3000, k.data(), k.size()),
              k.size() * 4 / 4);
    compressed("/huge", H5T_NATIVE_DOUBLE, hsize_t{1} << 60, 1024, nullptr, 0);
    compressed("/part", H5T_NATIVE_DOUBLE, x.size(), 1000, x.data(), 1000);  // 1 of 4 chunks
    // One gzip chunk of 2^24 values (128 MB) stored as 64 bytes, as a damaged file may hold:
    // gzip cannot unpack that much from them.
    const hsize_t rows = hsize_t{1} << 24, offset = 0;
    compressed("/bomb", H5T_NATIVE_DOUBLE, rows, rows, nullptr, 0);
    const hid_t bomb = H5Dopen2(f.id(), "/bomb", H5P_DEFAULT);
    const std::vector<unsigned char> junk(64, 0x5a);
    EXPECT_GE(H5Dwrite_chunk(bomb, H5P_DEFAULT, 0, &offset, junk.size(), junk.data()), 0);
    EXPECT_EQ(H5Dget_storage_size(bomb), junk.size());
    H5Dclose(bomb);
    f.close();
  }
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(f, 0);
  std::vector<hsize_t> dims;
  EXPECT_EQ(h5::read_numbers(f, "/x", path, &dims, "not a test file"), x);
  EXPECT_EQ(dims, std::vector<hsize_t>{x.size()});
  const std::vector<double> got = h5::read_numbers(f, "/k", path, &dims, "not a test file");
  EXPECT_EQ(got, std::vector<double>(k.begin(), k.end()));
  for (const auto& [name, count] :
       {std::pair<std::string, std::string>{"/huge", "1152921504606846976"}, {"/part", "4000"}}) {
    try {
      h5::read_numbers(f, name, path, &dims, "not a test file");
      ADD_FAILURE() << name << " was read";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), path + ": " + name + " declares " + count +
                                           " values but the file does not store them; a damaged "
                                           "file or not a test file");
    }
  }
  try {
    h5::read_numbers(f, "/bomb", path, &dims, "not a test file");
    ADD_FAILURE() << "/bomb was read";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path +
                                         ": /bomb declares 16777216 values in 64 compressed bytes, "
                                         "more than gzip unpacks them to; a damaged file or not a "
                                         "test file");
  }
  H5Fclose(f);
}

}  // namespace
}  // namespace pound

// pound merge on damaged parts (issue 14, found by fuzz_campaign_file and the review of its
// findings): a part declaring more rows than it stores, a "samples" attribute that is not one
// number, a dataset without rows; each is one InputError naming the part, and every HDF5
// identifier the merge opened is closed again.
#include "campaign/merge.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "../support/h5_gzip.hpp"
#include "../support/scratch_dir.hpp"
#include "core/error.hpp"
#include "io/h5.hpp"

namespace pound {
namespace {

std::string text_of(hid_t f, const char* name, const std::string& value) {
  h5::attribute(f, "/", name, value);
  return value;
}

// A part of a 4-sample campaign holding samples [0, 4) with one dataset /samples/id of `rows`
// declared rows (none stored when `store` is false), or of rank 0 when rows == 0.
// A group of the file, created when absent.
hid_t H5Gopen_or_create(hid_t f, const char* name) {
  return H5Lexists(f, name, H5P_DEFAULT) > 0
             ? H5Gopen2(f, name, H5P_DEFAULT)
             : H5Gcreate2(f, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
}

// With `with_statistics`, the part also holds the datasets the amplification statistics of
// the joined file read (a whole campaign file as far as merge is concerned).
std::string part(const std::string& name, hsize_t rows, bool store, bool scalar_samples = true,
                 bool with_statistics = false) {
  const std::string path = test::process_scratch_dir() / name;
  const hid_t f = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  text_of(f, "study", "a study");
  text_of(f, "seed", "7");
  text_of(f, "sample_range", "0:4");
  if (scalar_samples) {
    h5::attribute(f, "/", "samples", 4.0);
  } else {  // three numbers where one is expected (read into one double: a stack overflow)
    hsize_t three = 3;
    const double v[3] = {4, 4, 4};
    const hid_t s = H5Screate_simple(1, &three, nullptr);
    const hid_t a = H5Acreate2(f, "samples", H5T_NATIVE_DOUBLE, s, H5P_DEFAULT, H5P_DEFAULT);
    H5Awrite(a, H5T_NATIVE_DOUBLE, v);
    H5Aclose(a);
    H5Sclose(s);
  }
  if (with_statistics) {
    // What /amplification reads besides /samples/id: one building of one floor, one level.
    const std::vector<int> status(4, 0);
    const std::vector<double> im = {1.0, 2.0, 1.0, 2.0}, one = {1.0, 1.0, 1.0, 1.0};
    h5::write(f, "/samples/status", status);
    h5::write(f, "/samples/im", im, 4);
    h5::attribute(f, "/", "im_levels_mps2", "1, 2");
    for (const char* dataset : {"peak_disp_pounding", "peak_disp_free", "peak_drift_ratio_pounding",
                                "peak_drift_ratio_free", "peak_accel_pounding", "peak_accel_free",
                                "impacts", "peak_force"}) {
      const hsize_t dims[3] = {4, 1, 1};
      const hid_t sp = H5Screate_simple(3, dims, nullptr);
      const std::string path_in_file = std::string("/response/") + dataset;
      h5::ensure_group(f, "/response");
      const hid_t d = H5Dcreate2(f, path_in_file.c_str(), H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT);
      H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, one.data());
      H5Dclose(d);
      H5Sclose(sp);
    }
  }
  const hid_t g = H5Gopen_or_create(f, "/samples");
  hsize_t max = H5S_UNLIMITED, chunk = 4;
  const hid_t space = rows ? H5Screate_simple(1, &rows, &max) : H5Screate(H5S_SCALAR);
  const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
  if (rows) H5Pset_chunk(plist, 1, &chunk);
  const hid_t d = H5Dcreate2(g, "id", H5T_NATIVE_LONG, space, H5P_DEFAULT, plist, H5P_DEFAULT);
  const long ids[4] = {0, 1, 2, 3};
  if (store) H5Dwrite(d, H5T_NATIVE_LONG, H5S_ALL, H5S_ALL, H5P_DEFAULT, ids);
  H5Dclose(d);
  H5Pclose(plist);
  H5Sclose(space);
  H5Gclose(g);
  H5Fclose(f);
  return path;
}

std::string error_of(const std::string& part_path) {
  const std::string out = test::process_scratch_dir() / "merged.h5";
  try {
    merge_campaign_parts({part_path}, out);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Merge, DamagedPartsAreRefusedWithOneLineAndEveryIdentifierClosed) {
  const std::string good = part("good.h5", 4, true, true, true);
  EXPECT_EQ(error_of(good), "");  // the well-formed part merges
  // A part without the response datasets: the statistics of the joined file name the parts.
  const std::string bare = part("bare.h5", 4, true);
  EXPECT_EQ(error_of(bare), "the parts joined (" + bare +
                                "): no dataset /samples/status; not a campaign result file of "
                                "'pound campaign' (schema in src/campaign/result_file.hpp)");
  const std::string lying = part("lying.h5", 4, false);
  EXPECT_EQ(error_of(lying),
            lying +
                ": /samples/id declares 4 values but the file does not store them (a damaged "
                "file)");
  const std::string scalar = part("scalar.h5", 0, true);
  EXPECT_EQ(error_of(scalar), scalar + ": /samples/id is not a table of rows (1 to 3 dimensions)");
  const std::string three = part("three.h5", 4, true, false);
  EXPECT_NE(error_of(three).find("the parts end at sample 3 but the campaign has -1 samples"),
            std::string::npos)
      << error_of(three);
  // Nothing left open: no file, dataset, group, attribute or named datatype.
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

// A "samples" attribute that is no count (NaN, 1e300, 2.5) was converted to long for the
// message (undefined behaviour): the message shows it as stored and says what is valid.
TEST(Merge, ASampleCountThatIsNoCountIsShownAsStored) {
  for (const double n : {double(NAN), 1e300, 2.5, 0.0}) {
    const std::string p = part("count.h5", 4, true, true, true);
    const hid_t f = H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Adelete(f, "samples");
    h5::attribute(f, "/", "samples", n);
    H5Fclose(f);
    char shown[32];
    std::snprintf(shown, sizeof shown, "%.15g", n);
    EXPECT_EQ(error_of(p), p + ": the parts end at sample 3 but the campaign has " + shown +
                               " samples (attribute samples; valid: one whole number from 1 "
                               "to 1e15)");
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

TEST(Merge, ASampleRangeIsTwoWholeDecimalNumbers) {
  for (const std::string bad : {"0x0:4", "0:4abc", " 0:4", "0:4.5", "4:0", "0:1e99"}) {
    const std::string p = part("range.h5", 4, true, true, true);
    const hid_t f = H5Fopen(p.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    H5Adelete(f, "sample_range");
    h5::attribute(f, "/", "sample_range", bad);
    H5Fclose(f);
    EXPECT_EQ(error_of(p), p + ": bad sample_range '" + bad + "' (expected LO:HI)") << bad;
  }
}

// A part compressed with gzip (`h5repack -f GZIP=6`) stores fewer bytes than its values take;
// it was refused as damaged. It merges, to the same numbers as the part as written.
TEST(Merge, ACompressedPartMergesToTheSameNumbers) {
  const std::string plain = part("plain.h5", 4, true, true, true);
  const std::string packed = part("packed.h5", 4, true, true, true);
  ASSERT_EQ(test::gzip_numeric_datasets(packed), 11);  // id, status, im, 8 responses
  {
    const hid_t f = H5Fopen(packed.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t d = H5Dopen2(f, "/samples/id", H5P_DEFAULT);
    const hid_t dcpl = H5Dget_create_plist(d);
    EXPECT_EQ(H5Pget_nfilters(dcpl), 1);
    EXPECT_LT(H5Dget_storage_size(d), 4 * sizeof(long));  // what the check refused
    H5Pclose(dcpl);
    H5Dclose(d);
    H5Fclose(f);
  }
  const std::string a = test::process_scratch_dir() / "merged-plain.h5";
  const std::string b = test::process_scratch_dir() / "merged-packed.h5";
  merge_campaign_parts({plain}, a);
  ASSERT_NO_THROW(merge_campaign_parts({packed}, b));
  for (const char* name : {"/samples/id", "/samples/status", "/samples/im",
                           "/response/peak_drift_ratio_pounding", "/response/peak_force"}) {
    std::vector<hsize_t> da, db;
    const hid_t fa = H5Fopen(a.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t fb = H5Fopen(b.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    EXPECT_EQ(h5::read_numbers(fa, name, a, &da, "-"), h5::read_numbers(fb, name, b, &db, "-"))
        << name;
    EXPECT_EQ(da, db) << name;
    H5Fclose(fa);
    H5Fclose(fb);
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

}  // namespace
}  // namespace pound

// The peak storey drift ratio's datasets were renamed (issue 31): /response/peak_drift_pounding
// and peak_drift_free are now peak_drift_ratio_pounding and _free. A file written before holds
// the old names: the campaign reader, the amplification statistics and merge read them there
// (stored_dataset_path), and merge writes the joined file under the new names.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <string>
#include <vector>

#include "../support/campaign_process.hpp"
#include "campaign/amplification_file.hpp"
#include "campaign/floor_arrays.hpp"
#include "campaign/merge.hpp"
#include "fragility/campaign_reader.hpp"

namespace pound {
namespace {

const char* const kRenamed[][2] = {
    {"/response/peak_drift_ratio_pounding", "/response/peak_drift_pounding"},
    {"/response/peak_drift_ratio_free", "/response/peak_drift_free"},
};

bool has(const std::string& file, const char* path) {
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const bool yes = H5Lexists(f, path, H5P_DEFAULT) > 0;
  H5Fclose(f);
  return yes;
}

// A campaign file of this version, and a copy of it as a pound before the renaming wrote it:
// the drift ratios under their former names, and no /amplification (computed again from them).
struct Files {
  std::string now, before;
};

const Files& files() {
  static const Files f = [] {
    Files x;
    x.now = test::make_smoke_campaign(test::campaign_dir() + "/names-now.h5", 16);
    x.before = test::campaign_dir() + "/names-before.h5";
    std::filesystem::copy_file(x.now, x.before, std::filesystem::copy_options::overwrite_existing);
    const hid_t h = H5Fopen(x.before.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    for (const auto& r : kRenamed)
      EXPECT_GE(H5Lmove(h, r[0], h, r[1], H5P_DEFAULT, H5P_DEFAULT), 0) << r[0];
    EXPECT_GE(H5Ldelete(h, "/amplification", H5P_DEFAULT), 0);
    H5Fclose(h);
    return x;
  }();
  return f;
}

TEST(FormerNames, TheCurrentNameIsFoundAndTheFormerOneFallsBack) {
  const hid_t now = H5Fopen(files().now.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t before = H5Fopen(files().before.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  for (const auto& r : kRenamed) {
    EXPECT_EQ(stored_dataset_path(now, r[0]), r[0]);
    EXPECT_EQ(stored_dataset_path(before, r[0]), r[1]);
    EXPECT_EQ(current_dataset_path(r[1]), r[0]);
    EXPECT_EQ(current_dataset_path(r[0]), r[0]);
  }
  // Any other dataset is itself, present or not.
  EXPECT_EQ(stored_dataset_path(before, "/response/peak_disp_free"), "/response/peak_disp_free");
  EXPECT_EQ(stored_dataset_path(before, "/response/none"), "/response/none");
  EXPECT_EQ(current_dataset_path("/response/peak_force"), "/response/peak_force");
  H5Fclose(now);
  H5Fclose(before);
}

TEST(FormerNames, TheCampaignReaderGivesAnOlderFileTheCurrentNames) {
  const CampaignData now = read_campaign(files().now), before = read_campaign(files().before);
  ASSERT_EQ(now.floor_arrays.size(), before.floor_arrays.size());
  for (const char* name : {"peak_drift_ratio_pounding", "peak_drift_ratio_free"}) {
    ASSERT_TRUE(before.floor_arrays.count(name)) << name;
    EXPECT_EQ(before.floor_array(name).v, now.floor_array(name).v) << name;
  }
}

TEST(FormerNames, TheAmplificationOfAnOlderFileIsTheSame) {
  const hid_t now = H5Fopen(files().now.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const hid_t before = H5Fopen(files().before.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  const AmplificationTable a = compute_amplification(now, files().now),
                           b = compute_amplification(before, files().before);
  H5Fclose(now);
  H5Fclose(before);
  ASSERT_EQ(a.measures.size(), b.measures.size());
  for (std::size_t m = 0; m < a.measures.size(); ++m) {
    EXPECT_EQ(a.measures[m].name, b.measures[m].name);
    EXPECT_EQ(a.measures[m].count, b.measures[m].count);
    EXPECT_EQ(a.measures[m].median, b.measures[m].median) << a.measures[m].name;
    EXPECT_EQ(a.measures[m].fraction_above_1, b.measures[m].fraction_above_1);
  }
}

TEST(FormerNames, MergeWritesAnOlderPartUnderTheCurrentNames) {
  const std::string merged = test::campaign_dir() + "/names-merged.h5";
  merge_campaign_parts({files().before}, merged);
  for (const auto& r : kRenamed) {
    EXPECT_FALSE(has(merged, r[1])) << r[1];
    ASSERT_TRUE(has(merged, r[0])) << r[0];
    EXPECT_EQ(test::read_raw(merged, r[0]), test::read_raw(files().now, r[0])) << r[0];
  }
  test::expect_same_numbers(merged, files().now);
}

}  // namespace
}  // namespace pound

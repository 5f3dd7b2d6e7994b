// Amplification statistics: the percentiles of a known sample, the intensity groups (stripes by
// sample id, equal-count bins), and /amplification computed from a made-up result file whose
// ratios are known, failed samples counted and not used, written and read back.
#include "campaign/amplification.hpp"

#include <gtest/gtest.h>
#include <hdf5.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../support/scratch_dir.hpp"
#include "campaign/amplification_file.hpp"
#include "core/error.hpp"
#include "io/h5.hpp"

namespace pound {
namespace {

TEST(Amplification, SummaryOfAKnownSample) {
  std::vector<double> v;
  for (int i = 101; i >= 1; --i) v.push_back(i);  // 101 .. 1: order does not matter
  const ValueSummary s = summarize(v);
  EXPECT_EQ(s.count, 101);
  EXPECT_DOUBLE_EQ(s.mean, 51.0);
  EXPECT_DOUBLE_EQ(s.median, 51.0);
  EXPECT_DOUBLE_EQ(s.p16, 17.0);  // 1 + 0.16 x 100 (type 7)
  EXPECT_DOUBLE_EQ(s.p84, 85.0);
  EXPECT_DOUBLE_EQ(s.fraction_above_1, 100.0 / 101.0);  // 1 itself is not above 1
  std::vector<double> two = {1.0, 2.0};
  EXPECT_DOUBLE_EQ(summarize(two).p16, 1.16);  // interpolated between the two
  std::vector<double> none;
  EXPECT_EQ(summarize(none).count, 0);
  EXPECT_TRUE(std::isnan(summarize(none).median));
}

TEST(Amplification, StripesBySampleIdAndBinsOfEqualCount) {
  // A part file of samples 7 .. 18 of a three-stripe campaign: sample i is on stripe i mod 3.
  std::vector<long> id;
  std::vector<char> ok;
  std::vector<double> im;
  for (long i = 7; i < 19; ++i) {
    id.push_back(i);
    ok.push_back(i != 10);  // sample 10 failed (no IM)
    im.push_back(i == 10 ? 0.0 : double(i % 3 + 1) * (1.0 + 1e-9 * double(i)));
  }
  const IntensityGroups s = intensity_groups({1.0, 2.0, 3.0}, id, ok, im);
  ASSERT_TRUE(s.stripes);
  EXPECT_EQ(s.samples, (std::vector<long>{4, 4, 4}));
  EXPECT_EQ(s.failed, (std::vector<long>{0, 1, 0}));  // 10 mod 3 = 1
  EXPECT_EQ(s.failed_total, 1);
  EXPECT_EQ(s.of_sample[3], 1);
  EXPECT_NEAR(s.im[2], 3.0, 1e-7);
  // A sampled scale: 100 samples in 100 / 20 = 5 bins of 20, at their geometric mean IM.
  std::vector<long> ids(100);
  std::vector<char> oks(100, 1);
  std::vector<double> ims(100);
  for (int i = 0; i < 100; ++i) ids[i] = i, ims[i] = std::exp(0.01 * ((i * 37) % 100));
  const IntensityGroups b = intensity_groups({}, ids, oks, ims);
  ASSERT_FALSE(b.stripes);
  ASSERT_EQ(b.im.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(b.samples[k], 20);
    EXPECT_NEAR(b.im[k], std::exp(0.01 * (20 * k + 9.5)), 1e-12) << k;  // mean of ln
    EXPECT_NEAR(b.im_lo[k], std::exp(0.01 * 20 * k), 1e-12);
  }
}

TEST(Amplification, CellValuesAreExactUpToTheirCapacityAndASystematicSubsampleBeyond) {
  // Up to the capacity: the summary of every value, as summarize gives it.
  CellValues exact(7, 7);
  std::vector<double> v = {1.3, 0.7, 1.0, 2.0, 1.1, 0.9, 1.5};
  for (double x : v) exact.add(x);
  EXPECT_TRUE(exact.exact());
  const ValueSummary a = exact.summary(), b = summarize(v);
  EXPECT_EQ(a.count, 7);
  EXPECT_EQ(a.median, b.median);
  EXPECT_EQ(a.p16, b.p16);
  EXPECT_EQ(a.p84, b.p84);
  EXPECT_DOUBLE_EQ(a.mean, b.mean);
  EXPECT_DOUBLE_EQ(a.fraction_above_1, 4.0 / 7.0);
  // 100,000 values of a shuffled uniform sequence on (0, 2), capacity 1000: every 100th value
  // is kept. Count, mean and the fraction above 1 stay exact; the quantiles come from 1000
  // values, within a few standard errors (sqrt(p (1 - p) / 1000) x 2 = 0.023 at p = 0.16)
  // of the exact 0.32, 1 and 1.68.
  const long n = 100000;
  CellValues sub(n, 1000);
  EXPECT_FALSE(sub.exact());
  double sum = 0.0;
  long above = 0;
  for (long i = 0; i < n; ++i) {
    const double x = 2.0 * (double((i * 7919) % n) + 0.5) / double(n);  // a permutation
    sum += x;
    above += x > 1.0;
    sub.add(x);
  }
  const ValueSummary s = sub.summary();
  EXPECT_EQ(s.count, n);
  EXPECT_DOUBLE_EQ(s.mean, sum / double(n));
  EXPECT_DOUBLE_EQ(s.fraction_above_1, double(above) / double(n));
  EXPECT_NEAR(s.median, 1.0, 0.07);
  EXPECT_NEAR(s.p16, 0.32, 0.07);
  EXPECT_NEAR(s.p84, 1.68, 0.07);
  EXPECT_NE(s.median, 1.0);  // not the exact quantile: a subsample was used
  // No values: NaN statistics, count 0.
  CellValues none(10, 4);
  EXPECT_EQ(none.summary().count, 0);
}

TEST(Amplification, BinEdgesFromASubsampleOfTheIntensities) {
  // 10,000 successful samples with IMs exp(u), u uniform on a grid: 10 bins. Edges from every
  // 10th IM (a subsample of 1000) put 1000 +- 10 samples in each bin, and a failed sample in
  // none.
  std::vector<double> all;
  for (int i = 0; i < 10000; ++i) all.push_back(std::exp(1e-4 * double((i * 7907) % 10000)));
  std::vector<double> sub;
  for (std::size_t i = 0; i < all.size(); i += 10) sub.push_back(all[i]);
  std::sort(sub.begin(), sub.end());
  const IntensityGrouping g = bin_grouping(sub, long(all.size()));
  ASSERT_FALSE(g.stripes);
  ASSERT_EQ(g.groups, 10u);
  ASSERT_EQ(g.edges.size(), 9u);
  GroupTally tally(g);
  for (std::size_t i = 0; i < all.size(); ++i) tally.add(long(i), true, all[i]);
  tally.add(10000, false, 0.0);
  const IntensityGroups r = tally.result({});
  for (std::size_t k = 0; k < 10; ++k) EXPECT_NEAR(double(r.samples[k]), 1000.0, 10.0) << k;
  EXPECT_EQ(r.failed_total, 1);
  EXPECT_EQ(g.group(5, false, 1.5), -1);
  EXPECT_EQ(stripe_grouping(3).group(10, false, 0.0), 1);  // a stripe keeps its failed samples
}

// A dataset of doubles [n, a, b].
void put(hid_t f, const std::string& name, const std::vector<double>& v, hsize_t n, hsize_t a,
         hsize_t b) {
  h5::ensure_group(f, "/response");
  const hsize_t dims[3] = {n, a, b};
  const hid_t sp = H5Screate_simple(3, dims, nullptr);
  const hid_t d =
      H5Dcreate2(f, name.c_str(), H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Dclose(d);
  H5Sclose(sp);
}

TEST(Amplification, FromAResultFileWithKnownRatios) {
  // 30 samples on two stripes; building 1 has two floors, building 2 one (NaN above). Sample s
  // has the ratio 1 + 0.01 s at every floor of building 1 and 0.9 at building 2; sample 5
  // failed. Contact at sample s when s is even, with the force 1000 s N.
  const std::string path = test::process_scratch_dir() / "amp.h5";
  const hsize_t n = 30;
  {
    h5::File file(path);
    const hid_t f = file.id();
    std::vector<int> status(n, 0);
    status[5] = 1;
    std::vector<double> im(n), id(n);
    for (hsize_t s = 0; s < n; ++s) im[s] = s % 2 ? 4.0 : 2.0, id[s] = double(s);
    h5::write(f, "/samples/status", status);
    h5::write(f, "/samples/im", im, n);
    h5::write(f, "/samples/id", id, n);
    h5::attribute(f, "/", "im_levels_mps2", "2.000000, 4.000000");
    const double nan = std::nan("");
    for (const char* m : {"disp", "drift", "accel"}) {
      std::vector<double> p(n * 4), q(n * 4);
      for (hsize_t s = 0; s < n; ++s) {
        const bool failed = s == 5;
        const double free[4] = {0.01, 0.02, 0.03, nan};
        const double ratio[4] = {1 + 0.01 * double(s), 1 + 0.01 * double(s), 0.9, nan};
        for (int k = 0; k < 4; ++k) {
          q[s * 4 + k] = failed ? nan : free[k];
          p[s * 4 + k] = failed ? nan : free[k] * ratio[k];
        }
      }
      put(f, std::string("/response/peak_") + m + "_pounding", p, n, 2, 2);
      put(f, std::string("/response/peak_") + m + "_free", q, n, 2, 2);
    }
    std::vector<double> impacts(n), force(n);
    for (hsize_t s = 0; s < n; ++s) {
      impacts[s] = s == 5 ? nan : s % 2 == 0 ? 2.0 : 0.0;
      force[s] = s == 5 ? nan : s % 2 == 0 ? 1000.0 * double(s) : 0.0;
    }
    put(f, "/response/impacts", impacts, n, 1, 1);
    put(f, "/response/peak_force", force, n, 1, 1);
    const AmplificationTable t = compute_amplification(f, path);
    write_amplification(f, t);
  }
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  AmplificationTable t;
  ASSERT_TRUE(read_amplification(f, path, &t));
  H5Fclose(f);
  ASSERT_EQ(t.groups, 2u);
  EXPECT_TRUE(t.stripes);
  EXPECT_EQ(t.samples, (std::vector<long>{15, 15}));
  EXPECT_EQ(t.failed, (std::vector<long>{0, 1}));
  EXPECT_EQ(t.failed_total, 1);
  ASSERT_EQ(t.measures.size(), 3u);
  for (const auto& m : t.measures) {
    // Stripe 0: even samples 0 .. 28, ratios 1.00 .. 1.28 (median 1.14, 14 of 15 above 1).
    EXPECT_EQ(m.count[t.at(0, 0, 0)], 15) << m.name;
    EXPECT_NEAR(m.median[t.at(0, 0, 1)], 1.14, 1e-12) << m.name;
    EXPECT_NEAR(m.mean[t.at(0, 0, 0)], 1.14, 1e-12);
    EXPECT_NEAR(m.p16[t.at(0, 0, 0)], 1.0 + 0.02 * 0.16 * 14, 1e-12);
    EXPECT_NEAR(m.fraction_above_1[t.at(0, 0, 0)], 14.0 / 15.0, 1e-12);
    // Stripe 1: odd samples without the failed sample 5.
    EXPECT_EQ(m.count[t.at(1, 0, 0)], 14) << m.name;
    EXPECT_NEAR(m.median[t.at(1, 1, 0)], 0.9, 1e-12);
    EXPECT_EQ(m.fraction_above_1[t.at(1, 1, 0)], 0.0);
    EXPECT_EQ(m.count[t.at(1, 1, 1)], 0);  // building 2 has no second floor
    EXPECT_TRUE(std::isnan(m.median[t.at(1, 1, 1)]));
  }
  EXPECT_EQ(t.contact_count[t.site(0, 0, 0)], 15);
  EXPECT_DOUBLE_EQ(t.pounded_fraction[t.site(0, 0, 0)], 1.0);
  EXPECT_DOUBLE_EQ(t.pounded_fraction[t.site(1, 0, 0)], 0.0);
  EXPECT_DOUBLE_EQ(t.force_median[t.site(0, 0, 0)], 14000.0);
  EXPECT_DOUBLE_EQ(t.force_median[t.site(1, 0, 0)], 0.0);
  EXPECT_TRUE(std::isnan(t.force_median_pounded[t.site(1, 0, 0)]));
  // A file without /response/collapsed_* and /samples/model (older than issue 23): neither the
  // collapse shares nor per-model tables.
  EXPECT_FALSE(t.has_collapse);
  EXPECT_TRUE(t.models.empty());
}

// A damaged /amplification group (found by reading it as fuzz_campaign_file would: the
// arrays were read whole into room sized by another array) is refused with one line before
// anything is indexed.
TEST(Amplification, ADamagedGroupIsRefusedBeforeAnythingIsIndexed) {
  const std::string path = test::process_scratch_dir() / "amp-damaged.h5";
  AmplificationTable good;
  good.groups = 2;
  good.buildings = 1;
  good.floors = 2;
  good.pairs = 1;
  good.levels = 1;
  good.im = good.im_lo = good.im_hi = {1.0, 2.0};
  good.samples = {3, 3};
  good.failed = {0, 1};
  for (const char* m : {"disp", "drift", "accel"}) {
    AmplificationMeasure a;
    a.name = m;
    a.count.assign(4, 3);
    a.mean = a.median = a.p16 = a.p84 = a.fraction_above_1 = {1.0, 1.1, 1.2, 1.3};
    good.measures.push_back(a);
  }
  good.contact_count = {3, 2};
  good.pounded_fraction = {0.5, 1.0};
  good.force_median = good.force_median_pounded = {10.0, 20.0};
  good.has_collapse = true;
  good.collapse_count = {3, 2};
  good.collapsed_pounding = {0.0, 0.5};
  good.collapsed_free = {1.0 / 3.0, 1.0};
  good.stopped_pounding = {1.0 / 3.0, 0.0};
  AmplificationTable model = good;
  model.model = "sears";
  good.models = {model};
  // Each damage: a name, what it does to the file, and what the message must say.
  struct Damage {
    const char* what;
    void (*apply)(hid_t);
    const char* says;
  };
  const Damage damages[] = {
      {"a larger mean",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/disp/mean", H5P_DEFAULT);
         put(f, "/amplification/disp/mean", std::vector<double>(12, 1.0), 2, 2, 3);
       },
       "/amplification/disp/mean is not of the shape [groups, 1, 2]"},
      {"fewer groups",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/samples", H5P_DEFAULT);
         h5::write(f, "/amplification/samples", std::vector<double>{3.0}, 1);
       },
       "/amplification/samples is not one value per group"},
      {"a 2-D contact array",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/contact/force_median", H5P_DEFAULT);
         h5::write(f, "/amplification/contact/force_median", std::vector<double>{1, 2}, 2, 1);
       },
       "/amplification/contact/force_median is not of the shape [groups, 1, 1]"},
      {"no design", [](hid_t f) { H5Adelete_by_name(f, "/amplification", "design", H5P_DEFAULT); },
       "/amplification has no attribute design"},
      {"text where the mean is",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/drift/median", H5P_DEFAULT);
         const hid_t t = H5Tcopy(H5T_C_S1);
         H5Tset_size(t, 4);
         const hsize_t n = 4;
         const hid_t sp = H5Screate_simple(1, &n, nullptr);
         const hid_t d = H5Dcreate2(f, "/amplification/drift/median", t, sp, H5P_DEFAULT,
                                    H5P_DEFAULT, H5P_DEFAULT);
         H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, "abcdefghijklmnop");
         H5Dclose(d);
         H5Sclose(sp);
         H5Tclose(t);
       },
       "/amplification/drift/median does not hold numbers"},
      // Counts that are no counts: converting NaN or 1e300 to long was undefined behaviour.
      {"NaN in a count",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/disp/count", H5P_DEFAULT);
         put(f, "/amplification/disp/count", {3.0, NAN, 3.0, 3.0}, 2, 1, 2);
       },
       "/amplification/disp/count holds nan; valid: whole numbers from 0 to 1e15 (counts)"},
      {"1e300 samples",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/samples", H5P_DEFAULT);
         h5::write(f, "/amplification/samples", std::vector<double>{1e300, 3.0}, 2);
       },
       "/amplification/samples holds 1e+300; valid: whole numbers from 0 to 1e15"},
      {"a fraction of a contact",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/contact/count", H5P_DEFAULT);
         put(f, "/amplification/contact/count", {3.0, 2.5}, 2, 1, 1);
       },
       "/amplification/contact/count holds 2.5; valid: whole numbers"},
      {"1e300 failed samples",
       [](hid_t f) {
         H5Adelete_by_name(f, "/amplification", "failed", H5P_DEFAULT);
         h5::attribute(f, "/amplification", "failed", 1e300);
       },
       "/amplification:failed holds 1e+300; valid: whole numbers"},
      {"no floor",
       [](hid_t f) {
         for (const char* m : {"disp", "drift", "accel"})
           for (const char* a : {"count", "mean", "median", "p16", "p84", "fraction_above_1"}) {
             const std::string name = std::string("/amplification/") + m + "/" + a;
             H5Ldelete(f, name.c_str(), H5P_DEFAULT);
             put(f, name, {}, 2, 1, 0);
           }
       },
       "/amplification/disp/count has no building or no floor"},
      {"a collapse share of another shape",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/collapse/collapsed_free", H5P_DEFAULT);
         put(f, "/amplification/collapse/collapsed_free", std::vector<double>(6, 0.0), 2, 3, 1);
       },
       "/amplification/collapse/collapsed_free is not of the shape [groups, 1] (the buildings of "
       "/disp/count)"},
      {"a collapse count that is no count",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/collapse/count", H5P_DEFAULT);
         h5::write(f, "/amplification/collapse/count", std::vector<double>{3.0, NAN}, 2, 1);
       },
       "/amplification/collapse/count holds nan; valid: whole numbers from 0 to 1e15"},
      {"a model without the collapse shares",
       [](hid_t f) { H5Ldelete(f, "/amplification/models/sears/collapse", H5P_DEFAULT); },
       "/amplification/models/sears does not have the groups and shapes of /amplification"},
      {"a model of fewer groups",
       [](hid_t f) {
         H5Ldelete(f, "/amplification/models/sears/samples", H5P_DEFAULT);
         h5::write(f, "/amplification/models/sears/samples", std::vector<double>{3.0}, 1);
       },
       "/amplification/models/sears/samples is not one value per group of "
       "/amplification/models/sears/im"},
  };
  for (const Damage& d : damages) {
    {
      h5::File file(path);
      write_amplification(file.id(), good);
      d.apply(file.id());
    }
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    AmplificationTable t;
    try {
      read_amplification(f, path, &t);
      ADD_FAILURE() << d.what << ": read";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(path + ": " + std::string(d.says)), std::string::npos)
          << d.what << ": " << m;
      EXPECT_EQ(m.find('\n'), std::string::npos);
    }
    H5Fclose(f);
    EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0) << d.what;
  }
  // The undamaged group reads back as written.
  {
    h5::File file(path);
    write_amplification(file.id(), good);
  }
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  AmplificationTable t;
  ASSERT_TRUE(read_amplification(f, path, &t));
  H5Fclose(f);
  EXPECT_EQ(t.failed, good.failed);
  EXPECT_EQ(t.measures[2].median, good.measures[2].median);
  EXPECT_EQ(t.force_median_pounded, good.force_median_pounded);
  EXPECT_EQ(t.floors, 2u);
  EXPECT_TRUE(t.stripes);
  EXPECT_EQ(t.collapsed_free, good.collapsed_free);
  ASSERT_EQ(t.models.size(), 1u);
  EXPECT_EQ(t.models[0].model, "sears");
  EXPECT_EQ(t.models[0].collapse_count, good.collapse_count);
}

}  // namespace
}  // namespace pound

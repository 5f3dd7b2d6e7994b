// The collapse shares and the per-model tables of /amplification (issue 23), on made-up campaign
// files whose numbers are known: the shares against a count done here, each model's table
// against the pooled table of a file holding only that model's samples, the groups of a sampled
// scale (the pooled bin edges), the group written and read back, and files without the collapse
// arrays or the model labels (older ones) as before.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "../support/scratch_dir.hpp"
#include "campaign/amplification_file.hpp"
#include "core/error.hpp"
#include "io/h5.hpp"

namespace pound {
namespace {

const double kNaN = std::nan("");

// How a made-up campaign file is written.
struct MadeUp {
  bool collapse = true;         // /response/collapsed_pounding, collapsed_free
  bool model = true;            // /samples/model
  bool variable_labels = true;  // variable-length strings (pound) or fixed length (h5py, numpy)
  bool stripes = true;          // two PGA stripes (sample s on s % 2), else a sampled scale
};

// The contact model of sample s.
std::string model_of(long s) {
  return s % 3 == 0 ? "sears" : "hc-linear";
}
bool failed(long s) {
  return s == 5 || s == 12;
}
// Whether building b collapsed in sample s with (pounding) and without pounding.
bool collapsed(long s, int b, bool pounding) {
  if (pounding) return b == 0 ? s % 4 == 0 : s % 6 == 0;
  return b == 0 ? s % 8 == 0 : s % 9 == 0;
}

// A dataset of doubles [n, a, b], or [n, a] when b = 0.
void put(hid_t f, const std::string& name, const std::vector<double>& v, hsize_t n, hsize_t a,
         hsize_t b) {
  h5::ensure_group(f, name.substr(0, name.rfind('/')));
  const hsize_t dims[3] = {n, a, b};
  const hid_t sp = H5Screate_simple(b ? 3 : 2, dims, nullptr);
  const hid_t d =
      H5Dcreate2(f, name.c_str(), H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data());
  H5Dclose(d);
  H5Sclose(sp);
}

void put_labels(hid_t f, const std::vector<std::string>& labels, bool variable) {
  const hsize_t n = labels.size();
  const hid_t t = H5Tcopy(H5T_C_S1);
  std::vector<const char*> p;
  std::vector<char> fixed(labels.size() * 16, '\0');
  if (variable) {
    H5Tset_size(t, H5T_VARIABLE);
    for (const auto& s : labels) p.push_back(s.c_str());
  } else {
    H5Tset_size(t, 16);
    for (std::size_t i = 0; i < labels.size(); ++i)
      std::memcpy(fixed.data() + 16 * i, labels[i].data(), labels[i].size());
  }
  const hid_t sp = H5Screate_simple(1, &n, nullptr);
  const hid_t d = H5Dcreate2(f, "/samples/model", t, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT,
           variable ? static_cast<const void*>(p.data()) : fixed.data());
  H5Dclose(d);
  H5Sclose(sp);
  H5Tclose(t);
}

// A campaign file of the samples `ids` (rows in that order): building 1 with two floors,
// building 2 with one (NaN above), one pair with one level; ratios, contacts and collapses
// that vary from sample to sample; samples 5 and 12 failed.
void write_campaign(const std::string& path, const std::vector<long>& ids, const MadeUp& how) {
  h5::File file(path);
  const hid_t f = file.id();
  const std::size_t n = ids.size();
  std::vector<int> status;
  std::vector<double> id, im;
  std::vector<std::string> labels;
  for (long s : ids) {
    status.push_back(failed(s) ? 1 : 0);
    id.push_back(double(s));
    const double stripe = s % 2 ? 4.0 : 2.0;
    im.push_back(failed(s) && !how.stripes ? kNaN
                 : how.stripes             ? stripe * (1.0 + 1e-3 * double(s))
                                           : std::exp(0.01 * double((s * 37) % 100)));
    labels.push_back(model_of(s));
  }
  h5::write(f, "/samples/status", status);
  h5::write(f, "/samples/im", im, n);
  h5::write(f, "/samples/id", id, n);
  if (how.model) put_labels(f, labels, how.variable_labels);
  if (how.stripes) h5::attribute(f, "/", "im_levels_mps2", "2, 4");
  for (const char* m : {"disp", "drift", "accel"}) {
    std::vector<double> p(n * 4), q(n * 4);
    for (std::size_t i = 0; i < n; ++i) {
      const long s = ids[i];
      const double free[4] = {0.01, 0.02, 0.03, kNaN};
      const double ratio[4] = {1.0 + 0.01 * double((s * 7) % 30),
                               1.0 + 0.02 * double((s * 11) % 30),
                               0.8 + 0.01 * double((s * 13) % 40), kNaN};
      for (int k = 0; k < 4; ++k) {
        q[i * 4 + k] = failed(s) ? kNaN : free[k];
        p[i * 4 + k] = failed(s) ? kNaN : free[k] * ratio[k];
      }
    }
    put(f, std::string("/response/peak_") + m + "_pounding", p, n, 2, 2);
    put(f, std::string("/response/peak_") + m + "_free", q, n, 2, 2);
  }
  std::vector<double> impacts, force, cp, cf;
  for (long s : ids) {
    const double hits = double((s * 5) % 3);
    impacts.push_back(failed(s) ? kNaN : hits);
    force.push_back(failed(s) ? kNaN : hits > 0 ? 100.0 * double(s) : 0.0);
    for (int b = 0; b < 2; ++b) {
      cp.push_back(failed(s) ? kNaN : collapsed(s, b, true) ? 1.0 : 0.0);
      cf.push_back(failed(s) ? kNaN : collapsed(s, b, false) ? 1.0 : 0.0);
    }
  }
  put(f, "/response/impacts", impacts, n, 1, 1);
  put(f, "/response/peak_force", force, n, 1, 1);
  if (how.collapse) {
    put(f, "/response/collapsed_pounding", cp, n, 2, 0);
    put(f, "/response/collapsed_free", cf, n, 2, 0);
  }
}

std::vector<long> range(long lo, long hi) {
  std::vector<long> v;
  for (long s = lo; s < hi; ++s) v.push_back(s);
  return v;
}

AmplificationTable computed(const std::string& path) {
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  EXPECT_GE(f, 0) << path;
  AmplificationTable t = compute_amplification(f, path);
  H5Fclose(f);
  return t;
}

// Equal numbers, NaN where the other has NaN.
template <class T>
void expect_same(const std::vector<T>& a, const std::vector<T>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i)
    EXPECT_TRUE(a[i] == b[i] || (std::isnan(double(a[i])) && std::isnan(double(b[i]))))
        << what << "[" << i << "]: " << a[i] << " and " << b[i];
}

void expect_same_table(const AmplificationTable& a, const AmplificationTable& b,
                       const std::string& what) {
  EXPECT_EQ(a.stripes, b.stripes) << what;
  EXPECT_EQ(a.groups, b.groups) << what;
  EXPECT_EQ(a.buildings, b.buildings) << what;
  EXPECT_EQ(a.floors, b.floors) << what;
  EXPECT_EQ(a.failed_total, b.failed_total) << what;
  expect_same(a.im, b.im, what + " im");
  expect_same(a.im_lo, b.im_lo, what + " im_lo");
  expect_same(a.im_hi, b.im_hi, what + " im_hi");
  expect_same(a.samples, b.samples, what + " samples");
  expect_same(a.failed, b.failed, what + " failed");
  ASSERT_EQ(a.measures.size(), b.measures.size()) << what;
  for (std::size_t k = 0; k < a.measures.size(); ++k) {
    const auto &x = a.measures[k], &y = b.measures[k];
    const std::string m = what + " " + x.name;
    expect_same(x.count, y.count, m + " count");
    expect_same(x.mean, y.mean, m + " mean");
    expect_same(x.median, y.median, m + " median");
    expect_same(x.p16, y.p16, m + " p16");
    expect_same(x.p84, y.p84, m + " p84");
    expect_same(x.fraction_above_1, y.fraction_above_1, m + " fraction_above_1");
  }
  expect_same(a.contact_count, b.contact_count, what + " contact count");
  expect_same(a.pounded_fraction, b.pounded_fraction, what + " pounded_fraction");
  expect_same(a.force_median, b.force_median, what + " force_median");
  expect_same(a.force_median_pounded, b.force_median_pounded, what + " force_median_pounded");
  EXPECT_EQ(a.has_collapse, b.has_collapse) << what;
  expect_same(a.collapse_count, b.collapse_count, what + " collapse count");
  expect_same(a.collapsed_pounding, b.collapsed_pounding, what + " collapsed_pounding");
  expect_same(a.collapsed_free, b.collapsed_free, what + " collapsed_free");
  expect_same(a.stopped_pounding, b.stopped_pounding, what + " stopped_pounding");
}

TEST(AmplificationModels, CollapseSharesAreTheCountsOfCollapsedSamples) {
  const std::string path = test::process_scratch_dir() / "collapse.h5";
  const std::vector<long> ids = range(0, 60);
  write_campaign(path, ids, {});
  const AmplificationTable t = computed(path);
  ASSERT_TRUE(t.has_collapse);
  ASSERT_EQ(t.groups, 2u);
  ASSERT_EQ(t.models.size(), 2u);
  // The count done here, per table (pooled, then per model), group and building.
  auto check = [&](const AmplificationTable& x, const std::string& model) {
    for (std::size_t g = 0; g < 2; ++g)
      for (int b = 0; b < 2; ++b) {
        long n = 0, with = 0, without = 0, stopped = 0;
        for (long s : ids) {
          if (std::size_t(s % 2) != g || failed(s) || (!model.empty() && model_of(s) != model))
            continue;
          ++n;
          with += collapsed(s, b, true);
          without += collapsed(s, b, false);
          stopped += !collapsed(s, b, true) && collapsed(s, 1 - b, true);
        }
        const std::size_t at = x.building_at(g, std::size_t(b));
        const std::string where =
            model + " group " + std::to_string(g) + " building " + std::to_string(b);
        ASSERT_GT(n, 0) << where;
        EXPECT_EQ(x.collapse_count[at], n) << where;
        EXPECT_DOUBLE_EQ(x.collapsed_pounding[at], double(with) / double(n)) << where;
        EXPECT_DOUBLE_EQ(x.collapsed_free[at], double(without) / double(n)) << where;
        EXPECT_DOUBLE_EQ(x.stopped_pounding[at], double(stopped) / double(n)) << where;
      }
  };
  check(t, "");
  for (const auto& m : t.models) check(m, m.model);
  // Stripe 0 (even samples 0 .. 58 but the failed 12): 29 samples; building 1 collapsed with
  // pounding in the multiples of 4 from 0 to 56 but 12 (14), without in those of 8 (8).
  EXPECT_EQ(t.collapse_count[t.building_at(0, 0)], 29);
  EXPECT_DOUBLE_EQ(t.collapsed_pounding[t.building_at(0, 0)], 14.0 / 29.0);
  EXPECT_DOUBLE_EQ(t.collapsed_free[t.building_at(0, 0)], 8.0 / 29.0);
  // Stripe 1 (odd samples but 5): no odd multiple of 4 or 8.
  EXPECT_EQ(t.collapsed_pounding[t.building_at(1, 0)], 0.0);
  // Building 2 in stripe 0 collapsed with pounding in the multiples of 6 but 12 (0, 6, 18, 24,
  // 30, 36, 42, 48, 54); it stood, stopped by building 1's collapse, in those of 4 that are not
  // (4, 8, 16, 20, 28, 32, 40, 44, 52, 56): 10 of 29.
  EXPECT_DOUBLE_EQ(t.stopped_pounding[t.building_at(0, 1)], 10.0 / 29.0);
}

TEST(AmplificationModels, EachModelsTableIsThePooledTableOfItsSamplesAlone) {
  const std::string all = test::process_scratch_dir() / "models-all.h5";
  const std::vector<long> ids = range(0, 90);
  write_campaign(all, ids, {});
  const AmplificationTable t = computed(all);
  ASSERT_EQ(t.models.size(), 2u);
  EXPECT_EQ(t.models[0].model, "hc-linear");  // byte order
  EXPECT_EQ(t.models[1].model, "sears");
  for (std::size_t g = 0; g < t.groups; ++g)
    EXPECT_EQ(t.models[0].samples[g] + t.models[1].samples[g], t.samples[g]) << g;
  EXPECT_EQ(t.models[0].failed_total, 1);  // sample 5 (hc-linear) and 12 (sears) failed
  EXPECT_EQ(t.models[1].failed_total, 1);
  // The two models' ratios differ: the pooled table is neither.
  EXPECT_NE(t.models[0].measures[2].median[t.at(0, 0, 1)],
            t.models[1].measures[2].median[t.at(0, 0, 1)]);
  for (const auto& m : t.models) {
    // A file of that model's samples alone (the same ids, hence the same stripes; labels of
    // fixed length this time): its pooled table is the model's table, and its only model's too.
    std::vector<long> mine;
    for (long s : ids)
      if (model_of(s) == m.model) mine.push_back(s);
    const std::string one = test::process_scratch_dir() / ("models-" + m.model + ".h5");
    MadeUp how;
    how.variable_labels = false;
    write_campaign(one, mine, how);
    const AmplificationTable alone = computed(one);
    expect_same_table(m, alone, m.model);
    ASSERT_EQ(alone.models.size(), 1u);
    EXPECT_EQ(alone.models[0].model, m.model);
    expect_same_table(alone.models[0], alone, m.model + " alone");
  }
}

TEST(AmplificationModels, ASampledScaleKeepsThePooledBinsPerModel) {
  const std::string path = test::process_scratch_dir() / "models-bins.h5";
  const std::vector<long> ids = range(0, 120);
  MadeUp how;
  how.stripes = false;
  write_campaign(path, ids, how);
  const AmplificationTable t = computed(path);
  ASSERT_FALSE(t.stripes);
  ASSERT_EQ(t.groups, 5u);  // 118 successful samples / 20
  for (const auto& m : t.models) {
    ASSERT_EQ(m.groups, t.groups);
    for (std::size_t g = 0; g < t.groups; ++g) {
      // The model's samples whose IM lies in the pooled bin: their count and geometric mean.
      long n = 0;
      double log_sum = 0.0;
      for (long s : ids) {
        const double im = std::exp(0.01 * double((s * 37) % 100));
        if (failed(s) || model_of(s) != m.model || im < t.im_lo[g] || im > t.im_hi[g]) continue;
        ++n;
        log_sum += std::log(im);
      }
      ASSERT_GT(n, 0) << m.model << " bin " << g;
      EXPECT_EQ(m.samples[g], n) << m.model << " bin " << g;
      EXPECT_NEAR(m.im[g], std::exp(log_sum / double(n)), 1e-12) << m.model << " bin " << g;
    }
  }
  for (std::size_t g = 0; g < t.groups; ++g)
    EXPECT_EQ(t.models[0].samples[g] + t.models[1].samples[g], t.samples[g]) << g;
}

TEST(AmplificationModels, WrittenAndReadBackWithAndWithoutCollapseAndModels) {
  for (const bool newer : {true, false}) {
    const std::string path =
        test::process_scratch_dir() / (newer ? "round-new.h5" : "round-old.h5");
    MadeUp how;
    how.collapse = how.model = newer;
    write_campaign(path, range(0, 40), how);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const AmplificationTable t = compute_amplification(f, path);
    EXPECT_EQ(t.has_collapse, newer);
    EXPECT_EQ(t.models.size(), newer ? 2u : 0u);
    write_amplification(f, t);
    EXPECT_EQ(H5Lexists(f, "/amplification/collapse", H5P_DEFAULT) > 0, newer);
    EXPECT_EQ(H5Lexists(f, "/amplification/models", H5P_DEFAULT) > 0, newer);
    if (newer) {
      EXPECT_EQ(h5::attribute_text(f, "/amplification/models", "labels"), "hc-linear, sears");
      EXPECT_EQ(h5::attribute_text(f, "/amplification/models/sears", "model"), "sears");
      EXPECT_EQ(h5::attribute_text(f, "/amplification/collapse/collapsed_free", "units"), "-");
    }
    AmplificationTable back;
    ASSERT_TRUE(read_amplification(f, path, &back));
    expect_same_table(back, t, newer ? "newer" : "older");
    ASSERT_EQ(back.models.size(), t.models.size());
    for (std::size_t m = 0; m < t.models.size(); ++m) {
      EXPECT_EQ(back.models[m].model, t.models[m].model);
      expect_same_table(back.models[m], t.models[m], t.models[m].model);
    }
    EXPECT_TRUE(amplification_complete(f, back));
    if (newer) {  // a group of an older pound: no collapse shares, no models
      AmplificationTable older = back;
      older.has_collapse = false;
      EXPECT_FALSE(amplification_complete(f, older));
      older = back;
      older.models.clear();
      EXPECT_FALSE(amplification_complete(f, older));
    }
    H5Fclose(f);
  }
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

TEST(AmplificationModels, LabelsThatCannotNameAGroupAreRefusedWithOneLine) {
  const std::string path = test::process_scratch_dir() / "bad-labels.h5";
  struct Case {
    std::vector<std::string> labels;
    std::string says;
  };
  const Case cases[] = {
      {{"sears", "hc/linear"}, "/samples/model holds the label 'hc/linear'"},
      {{"sears", "a,b"}, "/samples/model holds the label 'a,b'"},
      {{"sears", ""}, "/samples/model holds an empty label"},
  };
  for (const Case& c : cases) {
    MadeUp how;
    how.model = false;
    write_campaign(path, range(0, 2), how);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    put_labels(f, c.labels, true);
    try {
      compute_amplification(f, path);
      ADD_FAILURE() << c.says;
    } catch (const InputError& e) {
      EXPECT_EQ(
          std::string(e.what()),
          path + ": " + c.says + "; valid: contact model names (not empty, without '/' or ',')");
    }
    H5Fclose(f);
  }
  // Fixed-length labels of 300 bytes (65,536 of them a block): refused.
  {
    MadeUp how;
    how.model = false;
    write_campaign(path, range(0, 2), how);
    const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hid_t t = H5Tcopy(H5T_C_S1);
    H5Tset_size(t, 300);
    const hsize_t n = 2;
    const hid_t sp = H5Screate_simple(1, &n, nullptr);
    const hid_t d = H5Dcreate2(f, "/samples/model", t, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    const std::vector<char> zeros(600, '\0');
    H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, zeros.data());
    H5Dclose(d);
    H5Sclose(sp);
    H5Tclose(t);
    try {
      compute_amplification(f, path);
      ADD_FAILURE() << "labels of 300 bytes read";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), path +
                                           ": /samples/model holds strings of 300 bytes; valid: "
                                           "labels of at most 256 bytes");
    }
    H5Fclose(f);
  }
  // Numbers where the labels should be.
  MadeUp how;
  how.model = false;
  write_campaign(path, range(0, 2), how);
  const hid_t f = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  h5::write(f, "/samples/model", std::vector<double>{1.0, 2.0}, 2);
  try {
    compute_amplification(f, path);
    ADD_FAILURE() << "numbers read as labels";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ": /samples/model does not hold text; valid: one label per sample (strings)");
  }
  H5Fclose(f);
  EXPECT_EQ(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL), 0);
}

}  // namespace
}  // namespace pound

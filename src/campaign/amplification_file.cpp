#include "campaign/amplification_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/error.hpp"
#include "io/h5.hpp"
#include "io/options.hpp"

namespace pound {
namespace {

constexpr hsize_t kBlockRows = 65536;  // rows read at a time
// Values kept for quantiles in one pass over the response (32 MB), shared by its cells, and the
// least a cell keeps; a cell with fewer values than it may keep has exact quantiles.
constexpr std::size_t kQuantileValues = std::size_t(1) << 22;
constexpr std::size_t kCellValues = 4096;
// Successful samples' IMs kept for the edges of the IM bins of a sampled scale (8 MB).
constexpr long kImValues = 1L << 20;

struct Measure {
  const char* name;
  const char* pounding;
  const char* free;
};
constexpr Measure kMeasures[] = {
    {"disp", "/response/peak_disp_pounding", "/response/peak_disp_free"},
    {"drift", "/response/peak_drift_pounding", "/response/peak_drift_free"},
    {"accel", "/response/peak_accel_pounding", "/response/peak_accel_free"},
};

// An open dataset of the file, closed at scope exit.
class Dataset {
 public:
  Dataset(hid_t file, const std::string& name, const std::string& path) : name_(name) {
    if (H5Lexists(file, name.c_str(), H5P_DEFAULT) <= 0 ||
        (id_ = H5Dopen2(file, name.c_str(), H5P_DEFAULT)) < 0)
      throw InputError(path + ": no dataset " + name +
                       "; not a campaign result file of 'pound campaign' (schema in "
                       "src/campaign/result_file.hpp)");
    const hid_t s = H5Dget_space(id_);
    dims_.resize(std::size_t(std::max(0, H5Sget_simple_extent_ndims(s))));
    H5Sget_simple_extent_dims(s, dims_.data(), nullptr);
    H5Sclose(s);
  }
  ~Dataset() { H5Dclose(id_); }
  Dataset(const Dataset&) = delete;
  Dataset& operator=(const Dataset&) = delete;
  const std::vector<hsize_t>& dims() const { return dims_; }

  // Rows [row, row + count) of a 1-D dataset, converted to T's native type.
  template <class T>
  void rows1(hsize_t row, hsize_t count, hid_t mem_type, std::vector<T>& out) const {
    out.resize(std::size_t(count));
    if (count == 0) return;
    const hid_t fs = H5Dget_space(id_);
    H5Sselect_hyperslab(fs, H5S_SELECT_SET, &row, nullptr, &count, nullptr);
    const hid_t ms = H5Screate_simple(1, &count, nullptr);
    const herr_t st = H5Dread(id_, mem_type, ms, fs, H5P_DEFAULT, out.data());
    H5Sclose(ms);
    H5Sclose(fs);
    if (st < 0) throw InputError("HDF5: reading " + name_ + " failed");
  }
  // Rows [row, row + count) of a 3-D dataset [N, a, b], columns [a0, a0 + na) of its second
  // dimension, as doubles, row-major.
  void rows(hsize_t row, hsize_t count, hsize_t a0, hsize_t na, std::vector<double>& out) const {
    const hsize_t start[3] = {row, a0, 0}, n[3] = {count, na, dims_[2]};
    out.resize(std::size_t(count * na * dims_[2]));
    const hid_t fs = H5Dget_space(id_);
    H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, nullptr, n, nullptr);
    const hid_t ms = H5Screate_simple(3, n, nullptr);
    const herr_t st = H5Dread(id_, H5T_NATIVE_DOUBLE, ms, fs, H5P_DEFAULT, out.data());
    H5Sclose(ms);
    H5Sclose(fs);
    if (st < 0) throw InputError("HDF5: reading " + name_ + " failed");
  }

 private:
  std::string name_;
  hid_t id_ = -1;
  std::vector<hsize_t> dims_;
};

void write_array(hid_t file, const std::string& name, hid_t mem_type, const void* data,
                 std::vector<hsize_t> dims, const std::string& units = "") {
  h5::ensure_group(file, name.substr(0, name.rfind('/')));
  const hid_t space = H5Screate_simple(int(dims.size()), dims.data(), nullptr);
  const hid_t ds =
      H5Dcreate2(file, name.c_str(), mem_type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  if (ds < 0) throw InputError("HDF5: cannot create dataset " + name);
  hsize_t total = 1;
  for (hsize_t d : dims) total *= d;
  const herr_t st = total ? H5Dwrite(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) : 0;
  H5Dclose(ds);
  H5Sclose(space);
  if (st < 0) throw InputError("HDF5: writing " + name + " failed");
  if (!units.empty()) h5::attribute(file, name, "units", units);
}

void write_doubles(hid_t f, const std::string& name, const std::vector<double>& v,
                   std::vector<hsize_t> dims, const std::string& units = "") {
  write_array(f, name, H5T_NATIVE_DOUBLE, v.data(), std::move(dims), units);
}
void write_longs(hid_t f, const std::string& name, const std::vector<long>& v,
                 std::vector<hsize_t> dims) {
  write_array(f, name, H5T_NATIVE_LONG, v.data(), std::move(dims));
}

// The sample table (/samples/id, status, im), read in blocks of rows.
class SampleTable {
 public:
  SampleTable(hid_t file, const std::string& path)
      : id_(file, "/samples/id", path),
        status_(file, "/samples/status", path),
        im_(file, "/samples/im", path) {
    n_ = id_.dims().empty() ? 0 : id_.dims()[0];
    for (const Dataset* d : {&id_, &status_, &im_})
      if (d->dims().size() != 1 || d->dims()[0] != n_)
        throw InputError(path + ": /samples/id, status and im differ in length");
  }
  hsize_t rows() const { return n_; }
  // Rows [row, row + count).
  void read(hsize_t row, hsize_t count) {
    id_.rows1(row, count, H5T_NATIVE_LONG, id);
    status_.rows1(row, count, H5T_NATIVE_INT, status);
    im_.rows1(row, count, H5T_NATIVE_DOUBLE, im);
  }
  std::vector<long> id;
  std::vector<int> status;
  std::vector<double> im;

 private:
  Dataset id_, status_, im_;
  hsize_t n_ = 0;
};

// How the file's samples fall into intensity groups (amplification.hpp), from streamed passes
// over the sample table: with a sampled scale, the bins' edges come from the successful
// samples' IMs, or from every m-th of them when there are more than kImValues.
IntensityGroups group_samples(hid_t file, const std::string& path, SampleTable& table,
                              IntensityGrouping* grouping) {
  const std::string levels_text = h5::root_attribute_text(file, "im_levels_mps2");
  const std::vector<double> levels =
      levels_text.empty() ? std::vector<double>{}
                          : parse_number_list(levels_text, path + ": attribute im_levels_mps2");
  const hsize_t n = table.rows();
  if (!levels.empty()) {
    *grouping = stripe_grouping(levels.size());
  } else {
    long n_ok = 0;
    for (hsize_t row = 0; row < n; row += kBlockRows) {
      table.read(row, std::min<hsize_t>(kBlockRows, n - row));
      for (int st : table.status) n_ok += st == 0;
    }
    const long stride = std::max<long>(1, (n_ok + kImValues - 1) / kImValues);
    std::vector<double> sorted;
    long seen = 0;
    for (hsize_t row = 0; row < n; row += kBlockRows) {
      table.read(row, std::min<hsize_t>(kBlockRows, n - row));
      for (std::size_t i = 0; i < table.status.size(); ++i)
        if (table.status[i] == 0 && seen++ % stride == 0) sorted.push_back(table.im[i]);
    }
    std::sort(sorted.begin(), sorted.end());
    *grouping = bin_grouping(sorted, n_ok);
  }
  GroupTally tally(*grouping);
  for (hsize_t row = 0; row < n; row += kBlockRows) {
    table.read(row, std::min<hsize_t>(kBlockRows, n - row));
    for (std::size_t i = 0; i < table.id.size(); ++i)
      tally.add(table.id[i], table.status[i] == 0, table.im[i]);
  }
  return tally.result(levels);
}

// Values a statistics cell keeps for its quantiles: the budget of one pass (kQuantileValues)
// shared by its cells, at least kCellValues each.
std::size_t cell_capacity(std::size_t cells) {
  return std::max(kCellValues, kQuantileValues / std::max<std::size_t>(1, cells));
}

}  // namespace

AmplificationTable compute_amplification(hid_t file, const std::string& path) {
  AmplificationTable t;
  SampleTable table(file, path);
  const hsize_t n = table.rows();
  IntensityGrouping grouping;
  const IntensityGroups g = group_samples(file, path, table, &grouping);
  t.stripes = g.stripes;
  t.groups = g.im.size();
  t.im = g.im;
  t.im_lo = g.im_lo;
  t.im_hi = g.im_hi;
  t.samples = g.samples;
  t.failed = g.failed;
  t.failed_total = g.failed_total;
  const std::size_t G = t.groups;
  auto successful = [&](std::size_t k) { return g.samples[k] - g.failed[k]; };

  std::vector<double> bp, bf;
  for (const Measure& m : kMeasures) {
    const Dataset pd(file, m.pounding, path), fd(file, m.free, path);
    // The same [samples, buildings, floors] for every measure, at least one building and one
    // floor: `pound summary` indexes the three measures' statistics with one (b, f).
    if (pd.dims().size() != 3 || pd.dims() != fd.dims() || pd.dims()[0] != n || pd.dims()[1] < 1 ||
        pd.dims()[2] < 1 ||
        (!t.measures.empty() && (pd.dims()[1] != t.buildings || pd.dims()[2] != t.floors)))
      throw InputError(path + ": " + m.pounding + " and " + m.free +
                       " must both have the shape [samples, buildings, floors] of the other "
                       "peak_* datasets, with at least one building and one floor");
    t.buildings = pd.dims()[1];
    t.floors = pd.dims()[2];
    const std::size_t B = t.buildings, F = t.floors;
    AmplificationMeasure out;
    out.name = m.name;
    out.count.assign(G * B * F, 0);
    for (auto* v : {&out.mean, &out.median, &out.p16, &out.p84, &out.fraction_above_1})
      v->assign(G * B * F, 0.0);
    for (std::size_t b = 0; b < B; ++b) {
      // This building's ratios, per group and floor.
      std::vector<CellValues> cells;
      for (std::size_t k = 0; k < G; ++k)
        for (std::size_t fl = 0; fl < F; ++fl)
          cells.emplace_back(successful(k), cell_capacity(G * F));
      for (hsize_t row = 0; row < n; row += kBlockRows) {
        const hsize_t count = std::min<hsize_t>(kBlockRows, n - row);
        table.read(row, count);
        pd.rows(row, count, b, 1, bp);
        fd.rows(row, count, b, 1, bf);
        for (hsize_t i = 0; i < count; ++i) {
          const bool ok = table.status[i] == 0;
          const int k = grouping.group(table.id[i], ok, table.im[i]);
          if (!ok || k < 0) continue;  // failed samples are counted, not used
          for (std::size_t f = 0; f < F; ++f) {
            const double p = bp[i * F + f], q = bf[i * F + f];
            if (std::isfinite(p) && std::isfinite(q) && q > 0.0)
              cells[std::size_t(k) * F + f].add(p / q);
          }
        }
      }
      for (std::size_t k = 0; k < G; ++k)
        for (std::size_t f = 0; f < F; ++f) {
          const ValueSummary s = cells[k * F + f].summary();
          const std::size_t at = t.at(k, b, f);
          out.count[at] = s.count;
          out.mean[at] = s.mean;
          out.median[at] = s.median;
          out.p16[at] = s.p16;
          out.p84[at] = s.p84;
          out.fraction_above_1[at] = s.fraction_above_1;
        }
    }
    t.measures.push_back(std::move(out));
  }

  // Contacts per group, pair and level.
  const Dataset id_imp(file, "/response/impacts", path),
      id_force(file, "/response/peak_force", path);
  if (id_imp.dims().size() != 3 || id_imp.dims() != id_force.dims() || id_imp.dims()[0] != n)
    throw InputError(path + ": /response/impacts and /response/peak_force must both have the " +
                     "shape [samples, pairs, levels]");
  t.pairs = id_imp.dims()[1];
  t.levels = id_imp.dims()[2];
  const std::size_t P = t.pairs, L = t.levels, S = G * P * L;
  t.contact_count.assign(S, 0);
  std::vector<long> pounded(S, 0);
  std::vector<CellValues> force, force_pounded;
  for (std::size_t at = 0; at < S; ++at) {
    force.emplace_back(successful(at / (P * L)), cell_capacity(2 * S));
    force_pounded.emplace_back(successful(at / (P * L)), cell_capacity(2 * S));
  }
  for (hsize_t row = 0; row < n; row += kBlockRows) {
    const hsize_t count = std::min<hsize_t>(kBlockRows, n - row);
    table.read(row, count);
    id_imp.rows(row, count, 0, P, bp);
    id_force.rows(row, count, 0, P, bf);
    for (hsize_t i = 0; i < count; ++i) {
      const bool ok = table.status[i] == 0;
      const int k = grouping.group(table.id[i], ok, table.im[i]);
      if (!ok || k < 0) continue;
      for (std::size_t j = 0; j < P * L; ++j) {
        const double imp = bp[i * P * L + j], fo = bf[i * P * L + j];
        if (!std::isfinite(imp)) continue;  // no such level
        const std::size_t at = std::size_t(k) * P * L + j;
        ++t.contact_count[at];
        pounded[at] += imp > 0.0;
        if (std::isfinite(fo)) {
          force[at].add(fo);
          if (imp > 0.0) force_pounded[at].add(fo);
        }
      }
    }
  }
  const double nan = std::nan("");
  for (std::size_t at = 0; at < S; ++at) {
    t.pounded_fraction.push_back(
        t.contact_count[at] ? double(pounded[at]) / double(t.contact_count[at]) : nan);
    t.force_median.push_back(force[at].summary().median);
    t.force_median_pounded.push_back(force_pounded[at].summary().median);
  }
  return t;
}

void write_amplification(hid_t file, const AmplificationTable& t) {
  const std::string root = "/amplification";
  h5::ensure_group(file, root);
  h5::attribute(file, root, "design", t.stripes ? "stripes" : "bins");
  h5::attribute(file, root, "failed", double(t.failed_total));
  h5::attribute(file, root, "quantiles",
                "linear interpolation between order statistics (Hyndman & Fan 1996, type 7)");
  h5::attribute(file, root, "definition",
                "amplification = peak with pounding / peak without pounding of each floor "
                "(drift: of the storey below it), samples with a finite, positive free value; "
                "failed samples are counted in 'failed', not used");
  const hsize_t G = t.groups;
  write_doubles(file, root + "/im", t.im, {G}, "m/s^2");
  write_doubles(file, root + "/im_lo", t.im_lo, {G}, "m/s^2");
  write_doubles(file, root + "/im_hi", t.im_hi, {G}, "m/s^2");
  write_longs(file, root + "/samples", t.samples, {G});
  write_longs(file, root + "/failed", t.failed, {G});
  const std::vector<hsize_t> gbf = {G, t.buildings, t.floors}, gpl = {G, t.pairs, t.levels};
  for (const auto& m : t.measures) {
    const std::string p = root + "/" + m.name;
    write_longs(file, p + "/count", m.count, gbf);
    write_doubles(file, p + "/mean", m.mean, gbf, "-");
    write_doubles(file, p + "/median", m.median, gbf, "-");
    write_doubles(file, p + "/p16", m.p16, gbf, "-");
    write_doubles(file, p + "/p84", m.p84, gbf, "-");
    write_doubles(file, p + "/fraction_above_1", m.fraction_above_1, gbf, "-");
  }
  write_longs(file, root + "/contact/count", t.contact_count, gpl);
  write_doubles(file, root + "/contact/pounded_fraction", t.pounded_fraction, gpl, "-");
  write_doubles(file, root + "/contact/force_median", t.force_median, gpl, "N");
  write_doubles(file, root + "/contact/force_median_pounded", t.force_median_pounded, gpl, "N");
}

bool read_amplification(hid_t file, const std::string& path, AmplificationTable* t) {
  const std::string root = "/amplification";
  if (H5Lexists(file, root.c_str(), H5P_DEFAULT) <= 0) return false;
  const std::string kind = "not the /amplification group of 'pound campaign' (docs/campaign.md)";
  auto bad = [&](const std::string& what) { return InputError(path + ": " + root + what); };
  const std::string design = h5::attribute_text(file, root, "design");
  if (design != "stripes" && design != "bins")
    throw bad(" has no attribute design = stripes or bins; " + kind);
  t->stripes = design == "stripes";
  // Counts are whole numbers from 0 to 1e15: a damaged file's NaN or 1e300 is refused here,
  // before a conversion to long (undefined behaviour out of range).
  auto count_of = [&](double x, const std::string& name) {
    if (!(x >= 0.0 && x <= 1e15 && x == std::floor(x))) {
      char shown[32];
      std::snprintf(shown, sizeof shown, "%.15g", x);
      throw bad(name + " holds " + shown + "; valid: whole numbers from 0 to 1e15 (counts); " +
                kind);
    }
    return long(x);
  };
  const std::string failed = h5::attribute_text(file, root, "failed");
  t->failed_total = failed.empty()
                        ? 0
                        : count_of(parse_number(failed, path + ": " + root + ":failed"), ":failed");
  // Every array has G rows (the groups of /amplification/im) and every 3-D array of a kind the
  // same shape: a damaged file is refused before anything is indexed.
  std::vector<hsize_t> dims;
  auto one_d = [&](const std::string& name) {
    std::vector<double> v = h5::read_numbers(file, root + name, path, &dims, kind);
    if (dims.size() != 1 || (name != "/im" && v.size() != t->groups))
      throw bad(name + " is not one value per group of /amplification/im; " + kind);
    return v;
  };
  auto as_longs = [&](const std::vector<double>& v, const std::string& name) {
    std::vector<long> out;
    out.reserve(v.size());
    for (double x : v) out.push_back(count_of(x, name));
    return out;
  };
  t->im = one_d("/im");
  t->groups = t->im.size();
  t->im_lo = one_d("/im_lo");
  t->im_hi = one_d("/im_hi");
  t->samples = as_longs(one_d("/samples"), "/samples");
  t->failed = as_longs(one_d("/failed"), "/failed");
  // A 3-D array [G, a, b]; its a and b when `shape` is empty, else they must be those.
  auto three_d = [&](const std::string& name, std::vector<hsize_t>& shape) {
    std::vector<double> v = h5::read_numbers(file, root + name, path, &dims, kind);
    if (dims.size() != 3 || dims[0] != t->groups || (!shape.empty() && dims != shape))
      throw bad(name + " is not of the shape [groups, " +
                (shape.empty() ? std::string("a, b")
                               : std::to_string(shape[1]) + ", " + std::to_string(shape[2])) +
                "]; " + kind);
    shape = dims;
    return v;
  };
  t->measures.clear();
  std::vector<hsize_t> floors;
  for (const Measure& m : kMeasures) {
    AmplificationMeasure a;
    a.name = m.name;
    const std::string p = std::string("/") + m.name;
    a.count = as_longs(three_d(p + "/count", floors), p + "/count");
    a.mean = three_d(p + "/mean", floors);
    a.median = three_d(p + "/median", floors);
    a.p16 = three_d(p + "/p16", floors);
    a.p84 = three_d(p + "/p84", floors);
    a.fraction_above_1 = three_d(p + "/fraction_above_1", floors);
    t->measures.push_back(std::move(a));
  }
  if (floors[1] < 1 || floors[2] < 1)
    throw bad(
        "/disp/count has no building or no floor (shape [groups, buildings, floors] with "
        "buildings, floors >= 1); " +
        kind);
  t->buildings = floors[1];
  t->floors = floors[2];
  std::vector<hsize_t> levels;
  t->contact_count = as_longs(three_d("/contact/count", levels), "/contact/count");
  t->pounded_fraction = three_d("/contact/pounded_fraction", levels);
  t->force_median = three_d("/contact/force_median", levels);
  t->force_median_pounded = three_d("/contact/force_median_pounded", levels);
  t->pairs = levels[1];
  t->levels = levels[2];
  return true;
}

}  // namespace pound

// compute_amplification (amplification_file.hpp): the statistics of /amplification from a
// campaign file's /samples and /response datasets, read in blocks of rows (campaign_rows.hpp).
// The pooled table first; then, where the study samples the contact model (/samples/model),
// the same code once per model with a sample filter, over the pooled table's intensity groups.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <memory>

#include "campaign/amplification_file.hpp"
#include "campaign/campaign_rows.hpp"
#include "campaign/collapse_flags.hpp"
#include "campaign/floor_arrays.hpp"
#include "core/error.hpp"
#include "io/h5.hpp"
#include "io/options.hpp"

namespace pound {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Values kept for quantiles in one pass over the response (32 MB), shared by its cells, and the
// least a cell keeps; a cell with fewer values than it may keep has exact quantiles.
constexpr std::size_t kQuantileValues = std::size_t(1) << 22;
constexpr std::size_t kCellValues = 4096;
// Successful samples' IMs kept for the edges of the IM bins of a sampled scale (8 MB).
constexpr long kImValues = 1L << 20;

// Values a statistics cell keeps for its quantiles: the budget of one pass (kQuantileValues)
// shared by its cells, at least kCellValues each.
std::size_t cell_capacity(std::size_t cells) {
  return std::max(kCellValues, kQuantileValues / std::max<std::size_t>(1, cells));
}

// The stripes' levels (root attribute im_levels_mps2, m/s^2); empty for a sampled scale.
std::vector<double> stripe_levels(hid_t file, const std::string& path) {
  const std::string text = h5::root_attribute_text(file, "im_levels_mps2");
  return text.empty() ? std::vector<double>{}
                      : parse_number_list(text, path + ": attribute im_levels_mps2");
}

// How the file's samples fall into intensity groups (amplification.hpp), from streamed passes
// over every sample (no filter): with a sampled scale, the bins' edges come from the
// successful samples' IMs, or from every m-th of them when there are more than kImValues.
IntensityGrouping make_grouping(SampleRows& rows, const std::vector<double>& levels) {
  if (!levels.empty()) return stripe_grouping(levels.size());
  const hsize_t n = rows.rows();
  long n_ok = 0;
  for (hsize_t row = 0; row < n; row += kBlockRows) {
    rows.read(row, std::min(kBlockRows, n - row));
    for (int st : rows.status) n_ok += st == 0;
  }
  const long stride = std::max<long>(1, (n_ok + kImValues - 1) / kImValues);
  std::vector<double> sorted;
  long seen = 0;
  for (hsize_t row = 0; row < n; row += kBlockRows) {
    rows.read(row, std::min(kBlockRows, n - row));
    for (std::size_t i = 0; i < rows.status.size(); ++i)
      if (rows.status[i] == 0 && seen++ % stride == 0) sorted.push_back(rows.im[i]);
  }
  std::sort(sorted.begin(), sorted.end());
  return bin_grouping(sorted, n_ok);
}

// One pass's view of the samples: the file, its sample table (with its filter) and the groups.
struct Pass {
  hid_t file;
  const std::string& path;
  SampleRows& rows;
  const IntensityGrouping& grouping;
  std::vector<long> successful;  // per group: successful samples the filter keeps
  // /response/collapsed_pounding [samples, buildings], null in a file older than issue 23.
  const RowBlocks* collapsed = nullptr;

  // The group of row i of the last block read; -1 for a sample not used (failed, in no group,
  // or of another model).
  int group_of(std::size_t i) const {
    const bool ok = rows.status[i] == 0;
    if (!ok || !rows.kept(i)) return -1;
    return grouping.group(rows.id[i], ok, rows.im[i]);
  }
  // Block by block, the columns [a0, a0 + na) of two datasets of the same layout (RowBlocks::
  // rows), and f(k, x, y) for each row in a group k (group_of >= 0), x and y its values. With
  // `standing` = a building's index, the rows where that building's pounding run was stopped
  // by another building's collapse are left out (stopped_by_another: its pounding peaks cover
  // only part of the record, its free peaks all of it).
  template <class F>
  void each_used_row(const RowBlocks& a, const RowBlocks& b, hsize_t a0, hsize_t na, F&& f,
                     long standing = -1) const {
    std::vector<double> va, vb, vc;
    const hsize_t n = rows.rows();
    // (collapse_statistics refuses a file whose flags are not [samples, buildings])
    const bool censor = standing >= 0 && collapsed != nullptr && collapsed->dims().size() == 2 &&
                        collapsed->dims()[0] == n && hsize_t(standing) < collapsed->dims()[1];
    const std::size_t nb = censor ? collapsed->dims()[1] : 0;
    for (hsize_t row = 0; row < n; row += kBlockRows) {
      const hsize_t count = std::min(kBlockRows, n - row);
      rows.read(row, count);
      a.rows(row, count, a0, na, va);
      b.rows(row, count, a0, na, vb);
      if (censor) collapsed->rows(row, count, 0, nb, vc);
      const std::size_t width = va.size() / count;
      for (hsize_t i = 0; i < count; ++i)
        if (const int k = group_of(i); k >= 0) {
          if (censor && stopped_by_another(vc.data() + i * nb, nb, std::size_t(standing))) continue;
          f(std::size_t(k), va.data() + i * width, vb.data() + i * width);
        }
    }
  }
};

// The per-group numbers (IM, its range, samples, failures) of the samples the filter keeps.
IntensityGroups tally_groups(SampleRows& rows, const IntensityGrouping& grouping,
                             const std::vector<double>& levels) {
  GroupTally tally(grouping);
  const hsize_t n = rows.rows();
  for (hsize_t row = 0; row < n; row += kBlockRows) {
    rows.read(row, std::min(kBlockRows, n - row));
    for (std::size_t i = 0; i < rows.id.size(); ++i)
      if (rows.kept(i)) tally.add(rows.id[i], rows.status[i] == 0, rows.im[i]);
  }
  return tally.result(levels);
}

// The statistics of one building's ratios pounding / free of measure `out` [G, B, F], over the
// samples in which its pounding run was not stopped by another building's collapse.
void building_ratios(const Pass& p, const RowBlocks& pd, const RowBlocks& fd, std::size_t b,
                     AmplificationTable& t, AmplificationMeasure& out) {
  const std::size_t G = t.groups, F = t.floors;
  std::vector<CellValues> cells;
  for (std::size_t k = 0; k < G; ++k)
    for (std::size_t fl = 0; fl < F; ++fl)
      cells.emplace_back(p.successful[k], cell_capacity(G * F));
  // Failed samples are counted, not used.
  p.each_used_row(
      pd, fd, b, 1,
      [&](std::size_t k, const double* bp, const double* bf) {
        for (std::size_t f = 0; f < F; ++f) {
          const double x = bp[f], q = bf[f];
          if (std::isfinite(x) && std::isfinite(q) && q > 0.0) cells[k * F + f].add(x / q);
        }
      },
      long(b));
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

// The amplification of peak displacement, drift and acceleration per group, building, floor.
void measure_statistics(const Pass& p, AmplificationTable& t) {
  const hsize_t n = p.rows.rows();
  for (std::size_t m = 0; m < std::size(kAmplificationMeasures); ++m) {
    const char* name = kAmplificationMeasures[m];
    const std::string array = std::string("/response/") + kAmplificationArrays[m];
    const std::string pounding = stored_dataset_path(p.file, array + "_pounding");
    const std::string free = stored_dataset_path(p.file, array + "_free");
    const RowBlocks pd(p.file, pounding, p.path), fd(p.file, free, p.path);
    // The same [samples, buildings, floors] for every measure, at least one building and one
    // floor: `pound summary` indexes the three measures' statistics with one (b, f).
    if (pd.dims().size() != 3 || pd.dims() != fd.dims() || pd.dims()[0] != n || pd.dims()[1] < 1 ||
        pd.dims()[2] < 1 ||
        (!t.measures.empty() && (pd.dims()[1] != t.buildings || pd.dims()[2] != t.floors)))
      throw InputError(p.path + ": " + pounding + " and " + free +
                       " must both have the shape [samples, buildings, floors] of the other "
                       "peak_* datasets, with at least one building and one floor");
    t.buildings = pd.dims()[1];
    t.floors = pd.dims()[2];
    const std::size_t cells = t.groups * t.buildings * t.floors;
    AmplificationMeasure out;
    out.name = name;
    out.count.assign(cells, 0);
    for (auto* v : {&out.mean, &out.median, &out.p16, &out.p84, &out.fraction_above_1})
      v->assign(cells, 0.0);
    for (std::size_t b = 0; b < t.buildings; ++b) building_ratios(p, pd, fd, b, t, out);
    t.measures.push_back(std::move(out));
  }
}

// Contacts per group, pair and level.
void contact_statistics(const Pass& p, AmplificationTable& t) {
  const hsize_t n = p.rows.rows();
  const RowBlocks imp(p.file, "/response/impacts", p.path),
      force_d(p.file, "/response/peak_force", p.path);
  if (imp.dims().size() != 3 || imp.dims() != force_d.dims() || imp.dims()[0] != n)
    throw InputError(p.path + ": /response/impacts and /response/peak_force must both have the " +
                     "shape [samples, pairs, levels]");
  t.pairs = imp.dims()[1];
  t.levels = imp.dims()[2];
  const std::size_t P = t.pairs, L = t.levels, S = t.groups * P * L;
  t.contact_count.assign(S, 0);
  std::vector<long> pounded(S, 0);
  std::vector<CellValues> force, force_pounded;
  for (std::size_t at = 0; at < S; ++at) {
    force.emplace_back(p.successful[at / (P * L)], cell_capacity(2 * S));
    force_pounded.emplace_back(p.successful[at / (P * L)], cell_capacity(2 * S));
  }
  p.each_used_row(imp, force_d, 0, P, [&](std::size_t k, const double* bi, const double* bf) {
    for (std::size_t j = 0; j < P * L; ++j) {
      const double hits = bi[j], fo = bf[j];
      if (!std::isfinite(hits)) continue;  // no such level
      const std::size_t at = k * P * L + j;
      ++t.contact_count[at];
      pounded[at] += hits > 0.0;
      if (std::isfinite(fo)) {
        force[at].add(fo);
        if (hits > 0.0) force_pounded[at].add(fo);
      }
    }
  });
  for (std::size_t at = 0; at < S; ++at) {
    t.pounded_fraction.push_back(
        t.contact_count[at] ? double(pounded[at]) / double(t.contact_count[at]) : kNaN);
    t.force_median.push_back(force[at].summary().median);
    t.force_median_pounded.push_back(force_pounded[at].summary().median);
  }
}

// The share of samples whose building collapsed, per group and building, with and without
// pounding; nothing for a file without /response/collapsed_pounding (older than issue 23).
void collapse_statistics(const Pass& p, AmplificationTable& t) {
  t.has_collapse = H5Lexists(p.file, "/response/collapsed_pounding", H5P_DEFAULT) > 0;
  if (!t.has_collapse) return;
  const hsize_t n = p.rows.rows();
  const std::size_t B = t.buildings, S = t.groups * B;
  const RowBlocks cp(p.file, "/response/collapsed_pounding", p.path),
      cf(p.file, "/response/collapsed_free", p.path);
  const std::vector<hsize_t> shape = {n, B};
  if (cp.dims() != shape || cf.dims() != shape)
    throw InputError(p.path +
                     ": /response/collapsed_pounding and /response/collapsed_free must both have "
                     "the shape [samples, buildings] = [" +
                     std::to_string(n) + ", " + std::to_string(B) + "] of the peak_* datasets");
  t.collapse_count.assign(S, 0);
  std::vector<long> with(S, 0), without(S, 0), stopped(S, 0);
  p.each_used_row(cp, cf, 0, B, [&](std::size_t k, const double* bp, const double* bf) {
    // The pounding run stops at the row's first collapse: a building standing then, beside
    // one that collapsed, was stopped.
    for (std::size_t b = 0; b < B; ++b) {
      const double x = bp[b], y = bf[b];
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      const std::size_t at = k * B + b;
      ++t.collapse_count[at];
      with[at] += x > 0.5;  // 1 collapsed, 0 standing
      without[at] += y > 0.5;
      stopped[at] += stopped_by_another(bp, B, b);
    }
  });
  t.collapsed_pounding.assign(S, kNaN);
  t.collapsed_free.assign(S, kNaN);
  t.stopped_pounding.assign(S, kNaN);
  for (std::size_t at = 0; at < S; ++at)
    if (const double c = double(t.collapse_count[at]); c > 0) {
      t.collapsed_pounding[at] = double(with[at]) / c;
      t.collapsed_free[at] = double(without[at]) / c;
      t.stopped_pounding[at] = double(stopped[at]) / c;
    }
}

// The share of samples whose struck columns failed in shear (ratio >= 1), per group and
// building, with and without pounding (issue 36); nothing for a file without a finite ratio.
void column_shear_statistics(const Pass& p, AmplificationTable& t) {
  t.has_column_shear = H5Lexists(p.file, "/response/column_shear_ratio_pounding", H5P_DEFAULT) > 0;
  if (!t.has_column_shear) return;
  const std::size_t B = t.buildings, S = t.groups * B;
  const RowBlocks rp(p.file, "/response/column_shear_ratio_pounding", p.path),
      rf(p.file, "/response/column_shear_ratio_free", p.path);
  const std::vector<hsize_t> shape = {p.rows.rows(), B};
  if (rp.dims() != shape || rf.dims() != shape)
    throw InputError(p.path +
                     ": /response/column_shear_ratio_pounding and _free must both have "
                     "the shape [samples, buildings] of the peak_* datasets");
  t.column_shear_count.assign(S, 0);
  std::vector<long> with(S, 0), without(S, 0);
  p.each_used_row(rp, rf, 0, B, [&](std::size_t k, const double* bp, const double* bf) {
    for (std::size_t b = 0; b < B; ++b) {
      if (!std::isfinite(bp[b]) || !std::isfinite(bf[b])) continue;
      const std::size_t at = k * B + b;
      ++t.column_shear_count[at];
      with[at] += bp[b] >= 1.0;
      without[at] += bf[b] >= 1.0;
    }
  });
  // A study without strengths or without slab-to-column sites: no table (NaN ratios only).
  t.has_column_shear = std::any_of(t.column_shear_count.begin(), t.column_shear_count.end(),
                                   [](long c) { return c > 0; });
  if (!t.has_column_shear) return;
  t.column_shear_failed_pounding.assign(S, kNaN);
  t.column_shear_failed_free.assign(S, kNaN);
  for (std::size_t at = 0; at < S; ++at)
    if (const double c = double(t.column_shear_count[at]); c > 0) {
      t.column_shear_failed_pounding[at] = double(with[at]) / c;
      t.column_shear_failed_free[at] = double(without[at]) / c;
    }
}

// The table of the samples that `rows`' filter keeps, in the groups of `grouping`.
AmplificationTable table_of(hid_t file, const std::string& path, SampleRows& rows,
                            const IntensityGrouping& grouping, const std::vector<double>& levels) {
  const IntensityGroups g = tally_groups(rows, grouping, levels);
  AmplificationTable t;
  t.stripes = g.stripes;
  t.groups = g.im.size();
  t.im = g.im;
  t.im_lo = g.im_lo;
  t.im_hi = g.im_hi;
  t.samples = g.samples;
  t.failed = g.failed;
  t.failed_total = g.failed_total;
  Pass p{file, path, rows, grouping, {}};
  std::unique_ptr<RowBlocks> collapsed;
  if (H5Lexists(file, "/response/collapsed_pounding", H5P_DEFAULT) > 0) {
    collapsed = std::make_unique<RowBlocks>(file, "/response/collapsed_pounding", path);
    p.collapsed = collapsed.get();
  }
  for (std::size_t k = 0; k < t.groups; ++k) p.successful.push_back(g.samples[k] - g.failed[k]);
  measure_statistics(p, t);
  contact_statistics(p, t);
  collapse_statistics(p, t);
  column_shear_statistics(p, t);
  return t;
}

}  // namespace

AmplificationTable compute_amplification(hid_t file, const std::string& path) {
  SampleRows rows(file, path);
  const std::vector<double> levels = stripe_levels(file, path);
  const IntensityGrouping grouping = make_grouping(rows, levels);
  AmplificationTable t = table_of(file, path, rows, grouping, levels);
  for (std::size_t m = 0; m < rows.models().size(); ++m) {
    rows.keep_model(int(m));
    t.models.push_back(table_of(file, path, rows, grouping, levels));
    t.models.back().model = rows.models()[m];
  }
  return t;
}

}  // namespace pound

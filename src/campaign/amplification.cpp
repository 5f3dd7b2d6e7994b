#include "campaign/amplification.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace pound {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

double sorted_quantile(const std::vector<double>& v, double p) {
  if (v.empty()) return kNaN;
  const double h = p * double(v.size() - 1);  // Hyndman & Fan (1996) type 7
  const std::size_t i = std::size_t(std::floor(h));
  const std::size_t j = std::min(v.size() - 1, i + 1);
  return v[i] + (h - double(i)) * (v[j] - v[i]);
}

ValueSummary summarize(std::vector<double>& values) {
  ValueSummary s;
  s.count = long(values.size());
  if (values.empty()) {
    s.mean = s.median = s.p16 = s.p84 = s.fraction_above_1 = kNaN;
    return s;
  }
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  long above = 0;
  for (double x : values) {
    sum += x;
    above += x > 1.0;
  }
  s.mean = sum / double(values.size());
  s.median = sorted_quantile(values, 0.5);
  s.p16 = sorted_quantile(values, 0.16);
  s.p84 = sorted_quantile(values, 0.84);
  s.fraction_above_1 = double(above) / double(values.size());
  return s;
}

CellValues::CellValues(long expected, std::size_t capacity) {
  const long cap = long(std::max<std::size_t>(1, capacity));
  stride_ = expected > cap ? (expected + cap - 1) / cap : 1;
  kept_.reserve(std::size_t(std::min(std::max(expected, 0L), cap)));
}

void CellValues::add(double x) {
  if (seen_ % stride_ == 0) kept_.push_back(x);
  ++seen_;
  sum_ += x;
  above_ += x > 1.0;
}

ValueSummary CellValues::summary() {
  ValueSummary s = summarize(kept_);
  s.count = seen_;
  if (seen_ > 0) {
    s.mean = sum_ / double(seen_);
    s.fraction_above_1 = double(above_) / double(seen_);
  }
  std::vector<double>().swap(kept_);
  return s;
}

int IntensityGrouping::group(long id, bool ok, double im) const {
  if (stripes) return int(id % long(groups));
  if (!ok) return -1;
  return int(std::upper_bound(edges.begin(), edges.end(), im) - edges.begin());
}

IntensityGrouping stripe_grouping(std::size_t levels) {
  IntensityGrouping g;
  g.stripes = true;
  g.groups = levels;
  return g;
}

IntensityGrouping bin_grouping(const std::vector<double>& sorted_im, long n_ok) {
  IntensityGrouping g;
  g.stripes = false;
  g.groups = std::size_t(std::max<long>(1, std::min<long>(10, n_ok / 20)));
  const std::size_t m = sorted_im.size();
  for (std::size_t k = 1; k < g.groups && m > 0; ++k)
    g.edges.push_back(sorted_im[k * m / g.groups]);
  return g;
}

GroupTally::GroupTally(const IntensityGrouping& g)
    : g_(g),
      sum_(g.groups, 0.0),
      lo_(g.groups, std::numeric_limits<double>::infinity()),
      hi_(g.groups, -std::numeric_limits<double>::infinity()),
      used_(g.groups, 0),
      samples_(g.groups, 0),
      failed_(g.groups, 0) {}

void GroupTally::add(long id, bool ok, double im) {
  failed_total_ += !ok;
  const int k = g_.group(id, ok, im);
  if (k < 0) return;
  const std::size_t i = std::size_t(k);
  ++samples_[i];
  if (!ok) {
    ++failed_[i];
    return;
  }
  sum_[i] += g_.stripes ? im : std::log(im);  // a bin's IM is the geometric mean
  ++used_[i];
  lo_[i] = std::min(lo_[i], im);
  hi_[i] = std::max(hi_[i], im);
}

IntensityGroups GroupTally::result(const std::vector<double>& levels) const {
  IntensityGroups r;
  r.stripes = g_.stripes;
  r.samples = samples_;
  r.failed = failed_;
  r.failed_total = failed_total_;
  for (std::size_t k = 0; k < g_.groups; ++k) {
    const bool any = used_[k] > 0;
    const double mean = any ? sum_[k] / double(used_[k]) : kNaN;
    const double fallback = g_.stripes && k < levels.size() ? levels[k] : kNaN;
    r.im.push_back(!any ? fallback : g_.stripes ? mean : std::exp(mean));
    r.im_lo.push_back(any ? lo_[k] : fallback);
    r.im_hi.push_back(any ? hi_[k] : fallback);
  }
  return r;
}

IntensityGroups intensity_groups(const std::vector<double>& levels, const std::vector<long>& id,
                                 const std::vector<char>& ok, const std::vector<double>& im) {
  const std::size_t n = ok.size();
  IntensityGrouping grouping;
  if (!levels.empty()) {
    grouping = stripe_grouping(levels.size());
  } else {
    std::vector<double> sorted;
    for (std::size_t s = 0; s < n; ++s)
      if (ok[s]) sorted.push_back(im[s]);
    std::sort(sorted.begin(), sorted.end());
    grouping = bin_grouping(sorted, long(sorted.size()));
  }
  GroupTally tally(grouping);
  for (std::size_t s = 0; s < n; ++s) tally.add(id[s], ok[s], im[s]);
  IntensityGroups g = tally.result(levels);
  g.of_sample.resize(n);
  for (std::size_t s = 0; s < n; ++s) g.of_sample[s] = grouping.group(id[s], ok[s], im[s]);
  return g;
}

}  // namespace pound

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

IntensityGroups intensity_groups(const std::vector<double>& levels, const std::vector<long>& id,
                                 const std::vector<char>& ok, const std::vector<double>& im) {
  IntensityGroups g;
  const std::size_t n = ok.size();
  g.of_sample.assign(n, -1);
  for (char k : ok) g.failed_total += !k;
  if (!levels.empty()) {
    const std::size_t L = levels.size();
    g.stripes = true;
    std::vector<double> sum(L, 0.0);
    std::vector<long> used(L, 0);
    g.samples.assign(L, 0);
    g.failed.assign(L, 0);
    g.im_lo.assign(L, std::numeric_limits<double>::infinity());
    g.im_hi.assign(L, -std::numeric_limits<double>::infinity());
    for (std::size_t s = 0; s < n; ++s) {
      const std::size_t k = std::size_t(id[s] % long(L));
      g.of_sample[s] = int(k);
      ++g.samples[k];
      if (!ok[s]) {
        ++g.failed[k];
        continue;
      }
      sum[k] += im[s];
      ++used[k];
      g.im_lo[k] = std::min(g.im_lo[k], im[s]);
      g.im_hi[k] = std::max(g.im_hi[k], im[s]);
    }
    for (std::size_t k = 0; k < L; ++k) {
      g.im.push_back(used[k] ? sum[k] / double(used[k]) : levels[k]);
      if (!used[k]) g.im_lo[k] = g.im_hi[k] = levels[k];
    }
    return g;
  }
  g.stripes = false;
  std::vector<std::size_t> order;
  for (std::size_t s = 0; s < n; ++s)
    if (ok[s]) order.push_back(s);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return im[a] < im[b]; });
  const std::size_t bins = std::max<std::size_t>(1, std::min<std::size_t>(10, order.size() / 20));
  for (std::size_t k = 0; k < bins; ++k) {
    const std::size_t lo = k * order.size() / bins, hi = (k + 1) * order.size() / bins;
    double log_sum = 0.0;
    for (std::size_t i = lo; i < hi; ++i) {
      log_sum += std::log(im[order[i]]);
      g.of_sample[order[i]] = int(k);
    }
    const long count = long(hi - lo);
    g.im.push_back(count ? std::exp(log_sum / double(count)) : kNaN);
    g.im_lo.push_back(count ? im[order[lo]] : kNaN);
    g.im_hi.push_back(count ? im[order[hi - 1]] : kNaN);
    g.samples.push_back(count);
    g.failed.push_back(0);
  }
  return g;
}

}  // namespace pound

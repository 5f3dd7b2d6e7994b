#include "fragility/bootstrap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sampling/counter_rng.hpp"

namespace pound {

std::vector<Observation> observations(const ExceedanceDesign& d, const std::vector<char>& exceed,
                                      const std::vector<std::size_t>& rows) {
  std::vector<Observation> obs;
  const std::size_t count = rows.empty() ? d.im.size() : rows.size();
  if (d.stripes()) {
    obs.resize(d.levels.size());
    for (std::size_t s = 0; s < d.levels.size(); ++s) obs[s].im = d.levels[s];
    for (std::size_t k = 0; k < count; ++k) {
      const std::size_t i = rows.empty() ? k : rows[k];
      if (d.stripe[i] < 0 || exceed[i] == kLeftOut) continue;
      Observation& o = obs[std::size_t(d.stripe[i])];
      ++o.n;
      o.z += exceed[i] ? 1 : 0;
    }
    return obs;
  }
  obs.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = rows.empty() ? k : rows[k];
    if (exceed[i] != kLeftOut) obs.push_back({d.im[i], 1, exceed[i] ? 1L : 0L});
  }
  return obs;
}

BootstrapResampler::BootstrapResampler(const ExceedanceDesign& d, const BootstrapSettings& s)
    : groups_(d.stripes() ? d.levels.size() : 1), seed_(s.seed) {
  // The groups that are resampled: each stripe, or all analyses.
  for (std::size_t i = 0; i < d.im.size(); ++i) {
    if (d.stripes() && d.stripe[i] < 0) continue;
    groups_[d.stripes() ? std::size_t(d.stripe[i]) : 0].push_back(i);
  }
}

void BootstrapResampler::rows(int r, std::vector<std::size_t>& rows) const {
  const CounterRng rng(seed_, stream_id("fragility.bootstrap"));
  rows.clear();
  std::uint64_t draw = 0;
  for (const auto& g : groups_)
    for (std::size_t k = 0; k < g.size(); ++k) {
      const double u = rng.uniform(std::uint64_t(r), draw++);
      rows.push_back(g[std::min(g.size() - 1, std::size_t(u * double(g.size())))]);
    }
}

std::vector<std::vector<LognormalFit>> bootstrap_fits(
    const ExceedanceDesign& d, const std::vector<std::vector<char>>& outcomes,
    const BootstrapSettings& s) {
  const BootstrapResampler resampler(d, s);
  std::vector<std::vector<LognormalFit>> fits(outcomes.size());
  for (auto& f : fits) f.reserve(std::size_t(std::max(0, s.replicates)));
  std::vector<std::size_t> rows;
  for (int r = 0; r < s.replicates; ++r) {
    resampler.rows(r, rows);
    for (std::size_t c = 0; c < outcomes.size(); ++c)
      fits[c].push_back(fit_lognormal(observations(d, outcomes[c], rows)));
  }
  return fits;
}

Interval percentile_interval(std::vector<double> values, double confidence) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  values.erase(
      std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
      values.end());
  Interval iv{nan, nan, int(values.size())};
  if (values.empty()) return iv;
  std::sort(values.begin(), values.end());
  auto at = [&](double p) {  // quantile with linear interpolation (Hyndman & Fan type 7)
    const double h = p * double(values.size() - 1);
    const std::size_t i = std::size_t(std::floor(h));
    const std::size_t j = std::min(values.size() - 1, i + 1);
    return values[i] + (h - double(i)) * (values[j] - values[i]);
  };
  iv.lo = at(0.5 * (1.0 - confidence));
  iv.hi = at(0.5 * (1.0 + confidence));
  return iv;
}

}  // namespace pound

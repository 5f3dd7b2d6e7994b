#pragma once
// Bootstrap confidence bands of fragility fits (Efron & Tibshirani 1993, percentile method;
// Baker 2015 section "Uncertainty in fitted fragility functions"). A replicate redraws, with
// replacement, as many analyses from each intensity stripe as the stripe holds (resampling
// within stripes keeps the experimental design fixed), or from all analyses when the
// intensities are continuous. Every curve sees the same redrawn analyses, so ratios of two
// curves' parameters (theta with pounding / theta without) get bands as well.
// Draws come from CounterRng(seed, stream_id("fragility.bootstrap")).uniform(replicate, k):
// the same seed gives the same bands on any machine.
#include <cstdint>
#include <vector>

#include "fragility/lognormal_fit.hpp"

namespace pound {

/// Where each analysis sits: its intensity and, for multiple-stripe designs, its stripe.
struct ExceedanceDesign {
  std::vector<double> im;      ///< per analysis [m/s^2]
  std::vector<int> stripe;     ///< per analysis: stripe index into `levels`, or -1 (continuous)
  std::vector<double> levels;  ///< stripe intensities [m/s^2]; empty when continuous
  bool stripes() const { return !levels.empty(); }
};

/// exceed[i] of an analysis left out of a curve (its EDP is not finite); otherwise 1 when the
/// analysis exceeds the limit and 0 when it does not.
constexpr char kLeftOut = 2;

/// The observations of the analyses `rows` (all when empty): one per stripe with its counts,
/// or one per analysis (n = 1) when the intensities are continuous. `exceed` is per analysis;
/// analyses marked kLeftOut are not counted.
std::vector<Observation> observations(const ExceedanceDesign& d, const std::vector<char>& exceed,
                                      const std::vector<std::size_t>& rows = {});

struct BootstrapSettings {
  int replicates = 1000;   ///< bootstrap replicates [-]
  std::uint64_t seed = 1;  ///< generator seed
};

/// The analyses each bootstrap replicate draws (the draws of bootstrap_fits), for analyses
/// that refit other outcomes on the same replicates (pound risk: pounding at any gap).
class BootstrapResampler {
 public:
  BootstrapResampler(const ExceedanceDesign& d, const BootstrapSettings& s);
  /// The analyses of replicate r (as many from each stripe as it holds), into `rows`.
  void rows(int replicate, std::vector<std::size_t>& rows) const;

 private:
  std::vector<std::vector<std::size_t>> groups_;  ///< per stripe (or one): its analyses
  std::uint64_t seed_;
};

/// fits[c][r]: curve c (outcomes[c], per analysis) fitted to replicate r.
std::vector<std::vector<LognormalFit>> bootstrap_fits(
    const ExceedanceDesign& d, const std::vector<std::vector<char>>& outcomes,
    const BootstrapSettings& s);

struct Interval {
  double lo, hi;   ///< NaN when no value was finite
  int finite = 0;  ///< values that entered
};
/// Central percentile interval holding `confidence` (e.g. 0.90) of the finite values
/// (linear interpolation between order statistics); non-finite values are dropped.
Interval percentile_interval(std::vector<double> values, double confidence);

}  // namespace pound

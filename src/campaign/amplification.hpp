#pragma once
// Amplification statistics of a campaign (physics.md section 4): per intensity group (stripe,
// or equal-count bin of a sampled scale), building and floor, the distribution of the
// amplification A = peak with pounding / peak without of the floor displacement, the storey
// drift and the absolute floor acceleration; per group, pair and level, the fraction of samples
// that pounded and the peak pounding force. Pure: values in, numbers out (the file side is
// amplification_file.hpp).
#include <cstddef>
#include <string>
#include <vector>

namespace pound {

/// Count, mean, median, 16th and 84th percentiles and the fraction above 1 of a set of values.
struct ValueSummary {
  long count = 0;                 ///< values [-]
  double mean = 0.0;              ///< NaN when count = 0
  double median = 0.0;            ///< NaN when count = 0
  double p16 = 0.0, p84 = 0.0;    ///< NaN when count = 0
  double fraction_above_1 = 0.0;  ///< share of the values > 1 [-]; NaN when count = 0
};

/// Summary of `values` (reordered). Percentiles by linear interpolation between order
/// statistics (Hyndman & Fan 1996, type 7, as the fragility bands: percentile_interval).
ValueSummary summarize(std::vector<double>& values);

/// The p-quantile (0 <= p <= 1) of sorted values, type 7; NaN when empty.
double sorted_quantile(const std::vector<double>& sorted, double p);

/// How samples are grouped by intensity.
struct IntensityGroups {
  bool stripes = true;     ///< stripes (multiple-stripe analysis) or IM bins
  std::vector<double> im;  ///< per group: mean IM of its stripe, geometric mean of a bin [m/s^2]
  std::vector<double> im_lo, im_hi;  ///< per group: smallest and largest IM of its samples [m/s^2]
  std::vector<long> samples;         ///< per group: samples in it (failed included for stripes)
  std::vector<long> failed;          ///< per group: failed samples (stripes; 0 for bins)
  std::vector<int> of_sample;  ///< per sample: its group, -1 for a failed sample of a bin design
  long failed_total = 0;       ///< failed samples of the campaign
};

/// Groups of a campaign's samples. Stripes (`levels` not empty, m/s^2): sample id i lies on
/// stripe i mod L, as the campaign scales it (campaign/sample.cpp), failed samples included;
/// a stripe's IM is the mean of its successful samples' IM (its level when none succeeded).
/// Sampled scale (`levels` empty): the successful samples sorted by IM (ties by position) in
/// max(1, min(10, n / 20)) bins of equal count (as pound fragility's observations.csv); a
/// bin's IM is the geometric mean of its samples' IM; failed samples have no IM and no bin.
/// `ok` is per sample (status 0), `id` its sample id.
IntensityGroups intensity_groups(const std::vector<double>& levels, const std::vector<long>& id,
                                 const std::vector<char>& ok, const std::vector<double>& im);

}  // namespace pound

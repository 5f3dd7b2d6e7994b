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

/// The values of one statistics cell (a group, building and floor, say), kept for their
/// quantiles in bounded memory: every value while the cell expects at most `capacity` of them
/// (then its summary is exact), else every m-th value in arrival order, m = ceil(expected /
/// capacity): a systematic subsample, which is a random one here because a campaign's rows are
/// in sample-id order and the ids carry no information on the response. The count, the mean
/// and the fraction above 1 always use every value.
class CellValues {
 public:
  CellValues() = default;
  /// expected: an upper bound on the values the cell will get; capacity >= 1.
  CellValues(long expected, std::size_t capacity);
  void add(double x);
  /// Count, mean and fraction above 1 of every value, quantiles of the kept ones (as
  /// summarize); frees the kept values.
  ValueSummary summary();
  bool exact() const { return stride_ == 1; }

 private:
  long stride_ = 1, seen_ = 0, above_ = 0;
  double sum_ = 0.0;
  std::vector<double> kept_;
};

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

/// The rule that puts a sample in its intensity group, needing no per-sample memory: stripes by
/// sample id, bins by IM edges.
struct IntensityGrouping {
  bool stripes = true;
  std::size_t groups = 0;
  std::vector<double> edges;  ///< bins: the lowest IM of bins 1 .. groups - 1 [m/s^2]
  /// The group of a sample: a stripe's failed samples are in it; a failed sample of a bin
  /// design (no IM) is in none (-1).
  int group(long id, bool ok, double im) const;
};

/// Stripes: sample id i lies on stripe i mod `levels`, as the campaign scales it
/// (campaign/sample.cpp).
IntensityGrouping stripe_grouping(std::size_t levels);
/// Bins of equal count for a sampled scale: max(1, min(10, n_ok / 20)) bins (as pound
/// fragility's observations.csv), their edges the order statistics of `sorted_im` at the
/// bins' first positions; `sorted_im` holds the successful samples' IMs, sorted, or a
/// systematic subsample of them (then the bins are of equal count to that subsample's
/// resolution); n_ok is the number of successful samples.
IntensityGrouping bin_grouping(const std::vector<double>& sorted_im, long n_ok);

/// The per-group numbers of IntensityGroups (IM, its range, samples and failures), one sample
/// at a time.
class GroupTally {
 public:
  explicit GroupTally(const IntensityGrouping& g);
  void add(long id, bool ok, double im);
  /// levels: a stripe's IM when none of its samples succeeded [m/s^2] (empty for bins).
  IntensityGroups result(const std::vector<double>& levels) const;

 private:
  IntensityGrouping g_;
  std::vector<double> sum_, lo_, hi_;
  std::vector<long> used_, samples_, failed_;
  long failed_total_ = 0;
};

/// Groups of a campaign's samples held in memory (stripe_grouping or bin_grouping of all the
/// successful samples' IMs, tallied). Stripes (`levels` not empty, m/s^2): a stripe's IM is
/// the mean of its successful samples' IM (its level when none succeeded). Sampled scale
/// (`levels` empty): a bin's IM is the geometric mean of its samples' IM; failed samples have
/// no IM and no bin. `ok` is per sample (status 0), `id` its sample id.
IntensityGroups intensity_groups(const std::vector<double>& levels, const std::vector<long>& id,
                                 const std::vector<char>& ok, const std::vector<double>& im);

}  // namespace pound

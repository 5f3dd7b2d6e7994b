#pragma once
// The /amplification group of a campaign result file (docs/campaign.md, "Amplification
// statistics"), computed from the file's /samples and /response datasets at the end of a
// campaign and again by `pound merge` for the joined file (amplification_compute.cpp), and
// read back by `pound summary` (amplification_file.cpp).
//
//   /amplification                     attributes design ("stripes" or "bins"), failed (all
//                                      failed samples), quantiles, definition
//   /amplification/im, im_lo, im_hi [G]             m/s^2: the group's IM and its range
//   /amplification/samples, failed [G]              samples of the group, failed among them
//   /amplification/<m>/count [G, B, F]              samples with a finite ratio
//   /amplification/<m>/mean, median, p16, p84, fraction_above_1 [G, B, F]
//        m = disp, drift, accel: peak_<m>_pounding / peak_<m>_free of each floor (storey)
//   /amplification/contact/count [G, P, L]          samples with a result at that level
//   /amplification/contact/pounded_fraction [G, P, L]   share with a contact (impacts > 0)
//   /amplification/contact/force_median [G, P, L]        N, over those samples (0: no contact)
//   /amplification/contact/force_median_pounded [G, P, L] N, over the samples that pounded
//   /amplification/collapse/count [G, B]            successful samples of the group (with both
//                                                   collapse flags); only when the file has
//                                                   /response/collapsed_pounding (issue 23)
//   /amplification/collapse/collapsed_pounding [G, B]  share of them whose building collapsed
//                                                      with pounding (NaN when count = 0)
//   /amplification/collapse/collapsed_free [G, B]      the same without pounding
//   /amplification/collapse/stopped_pounding [G, B]    share of them whose pounding run
//                                                   stopped at another building's collapse
//                                                   while this one stood
//   /amplification/models                           only when the file has /samples/model (the
//                                                   study samples the contact model); attribute
//                                                   labels ("hc-linear, sears": the models, in
//                                                   byte order), definition
//   /amplification/models/<label>/...               the layout above (attributes design, failed,
//                                                   model), over the samples of that model alone
//                                                   in the pooled groups: the same stripes, or
//                                                   the same bin edges (a bin's IM and range
//                                                   those of the model's samples in it)
//
// Memory does not grow with the sample count: every array is read in blocks of 65,536 rows;
// the quantiles of a pass (one building's ratios, or the contacts) come from at most 2^22
// values (32 MB) shared by its cells, at least 4,096 a cell: exact while a cell has no more,
// else a systematic subsample (CellValues, amplification.hpp); the bins of a sampled scale
// take their edges from at most 2^20 IMs. Count, mean and fraction above 1 use every value.
// Each model's table is one more set of passes over the file with a sample filter.
#include <hdf5.h>

#include <string>
#include <vector>

#include "campaign/amplification.hpp"

namespace pound {

/// The amplification measures, in the order of AmplificationTable::measures.
inline constexpr const char* kAmplificationMeasures[] = {"disp", "drift", "accel"};
/// The per-floor arrays of each measure (floor_arrays.hpp), /response/<name>_pounding and
/// <name>_free, in the order of kAmplificationMeasures.
inline constexpr const char* kAmplificationArrays[] = {"peak_disp", "peak_drift_ratio",
                                                       "peak_accel"};

/// One amplification measure: its name ("disp", "drift", "accel") and statistics [G, B, F].
struct AmplificationMeasure {
  std::string name;
  std::vector<long> count;
  std::vector<double> mean, median, p16, p84, fraction_above_1;
};

struct AmplificationTable {
  bool stripes = true;
  std::size_t groups = 0, buildings = 0, floors = 0, pairs = 0, levels = 0;
  std::vector<double> im, im_lo, im_hi;  ///< [G] m/s^2
  std::vector<long> samples, failed;     ///< [G]
  long failed_total = 0;
  std::vector<AmplificationMeasure> measures;  ///< disp, drift, accel
  std::vector<long> contact_count;             ///< [G, P, L]
  std::vector<double> pounded_fraction;        ///< [G, P, L] [-]
  std::vector<double> force_median;            ///< [G, P, L] [N]
  std::vector<double> force_median_pounded;    ///< [G, P, L] [N] (NaN when none pounded)
  bool has_collapse = false;         ///< the file has /response/collapsed_* (the arrays below)
  std::vector<long> collapse_count;  ///< [G, B] successful samples with both flags
  std::vector<double> collapsed_pounding;  ///< [G, B] [-] share collapsed with pounding
  std::vector<double> collapsed_free;      ///< [G, B] [-] share collapsed without pounding
  /// [G, B] [-] share whose pounding run stopped at another building's collapse while this one
  /// stood (the run stops at the first collapse of the row: its later fate is unknown); empty
  /// when read from a stored group written before it existed.
  std::vector<double> stopped_pounding;
  /// Issue 36: the file has /response/column_shear_ratio_* (the arrays below).
  bool has_column_shear = false;
  std::vector<long> column_shear_count;  ///< [G, B] samples with a finite ratio in both runs
  /// [G, B] [-] share whose struck columns' shear demand reached their strength (ratio >= 1),
  /// with and without pounding.
  std::vector<double> column_shear_failed_pounding, column_shear_failed_free;
  std::string model;  ///< "" for every sample, else the contact model of a per-model table
  /// Per contact model (the labels of /samples/model, in byte order), the same statistics over
  /// its samples in these groups; empty when the file has no /samples/model.
  std::vector<AmplificationTable> models;
  std::size_t at(std::size_t g, std::size_t b, std::size_t f) const {
    return (g * buildings + b) * floors + f;
  }
  std::size_t site(std::size_t g, std::size_t p, std::size_t l) const {
    return (g * pairs + p) * levels + l;
  }
  std::size_t building_at(std::size_t g, std::size_t b) const { return g * buildings + b; }
};

/// From the campaign datasets of an open file (`path` names it in errors), with the collapse
/// shares when the file has /response/collapsed_pounding and a table per model when it has
/// /samples/model. Throws InputError when a dataset is missing or has the wrong shape.
AmplificationTable compute_amplification(hid_t file, const std::string& path);
/// Writes the group /amplification (the file must not hold it yet).
void write_amplification(hid_t file, const AmplificationTable& t);
/// Reads the group back; false when the file has none (a file of an older pound).
bool read_amplification(hid_t file, const std::string& path, AmplificationTable* t);
/// Whether a table read back holds everything compute_amplification would give for the file:
/// the collapse shares when the file has /response/collapsed_pounding, the per-model tables
/// when it has /samples/model (a group written before issue 23 has neither).
bool amplification_complete(hid_t file, const AmplificationTable& t);

}  // namespace pound

#pragma once
// The /amplification group of a campaign result file (docs/campaign.md, "Amplification
// statistics"), computed from the file's /samples and /response datasets at the end of a
// campaign and again by `pound merge` for the joined file, and read back by `pound summary`.
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
//
// Memory does not grow with the sample count: every array is read in blocks of 65,536 rows;
// the quantiles of a pass (one building's ratios, or the contacts) come from at most 2^22
// values (32 MB) shared by its cells, at least 4,096 a cell: exact while a cell has no more,
// else a systematic subsample (CellValues, amplification.hpp); the bins of a sampled scale
// take their edges from at most 2^20 IMs. Count, mean and fraction above 1 use every value.
#include <hdf5.h>

#include <string>
#include <vector>

#include "campaign/amplification.hpp"

namespace pound {

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
  std::size_t at(std::size_t g, std::size_t b, std::size_t f) const {
    return (g * buildings + b) * floors + f;
  }
  std::size_t site(std::size_t g, std::size_t p, std::size_t l) const {
    return (g * pairs + p) * levels + l;
  }
};

/// From the campaign datasets of an open file (`path` names it in errors). Throws InputError
/// when a dataset is missing or has the wrong shape.
AmplificationTable compute_amplification(hid_t file, const std::string& path);
/// Writes the group /amplification (the file must not hold it yet).
void write_amplification(hid_t file, const AmplificationTable& t);
/// Reads the group back; false when the file has none (a file of an older pound).
bool read_amplification(hid_t file, const std::string& path, AmplificationTable* t);

}  // namespace pound

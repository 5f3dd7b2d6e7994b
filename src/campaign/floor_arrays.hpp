#pragma once
// The per-floor response arrays of a campaign sample, as one table (floor_arrays.cpp). Each
// array is [building][floor] in a SampleOutcome (NaN where a building has fewer floors or the
// sample failed), filled from one FloorResponse field, one section of a journal record
// (journal.cpp), and the dataset /response/<name> [samples, buildings, floors] of the result
// file (result_file.cpp), which the readers find by the same name (stored_dataset_path). The
// arrays come in pairs, with pounding and without (<measure>_pounding, <measure>_free): adding
// a measure is its two SampleOutcome members plus one entry of floor_arrays.cpp.
#include <hdf5.h>

#include <string>
#include <vector>

namespace pound {

struct SampleOutcome;
struct FloorResponse;

struct FloorArrayField {
  std::string name;     ///< dataset under /response, e.g. "peak_drift_ratio_pounding"
  const char* unit;     ///< SI unit of the values ("-" dimensionless)
  std::string meaning;  ///< one line
  std::vector<double> SampleOutcome::*member;  ///< the array of a sample's outcome
  double FloorResponse::*source;               ///< its value per floor (simulate_row.hpp)
  /// The dataset's name in files written before it was renamed (issue 31: "peak_drift_pounding"
  /// for "peak_drift_ratio_pounding"), which readers fall back to; "": never renamed.
  std::string former_name;
};

/// Every per-floor array, in the order of the journal record and the result file.
const std::vector<FloorArrayField>& floor_array_fields();

/// Where `file` holds the dataset `path` ("/response/peak_drift_ratio_pounding"): `path`, or, in a
/// file written before a per-floor array was renamed, the path of its former name when only that
/// exists. Every reader of campaign files (the campaign reader, the amplification statistics,
/// merge) finds the datasets here, the one place of the fallback. `path` when neither exists.
std::string stored_dataset_path(hid_t file, const std::string& path);
/// The path a dataset of a campaign file has now: a renamed per-floor array's former path
/// ("/response/peak_drift_pounding") gives its current one, any other path itself.
std::string current_dataset_path(const std::string& path);

}  // namespace pound

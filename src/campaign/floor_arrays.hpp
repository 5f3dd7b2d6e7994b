#pragma once
// The per-floor response arrays of a campaign sample, as one table (floor_arrays.cpp). Each
// array is [building][floor] in a SampleOutcome (NaN where a building has fewer floors or the
// sample failed), filled from one FloorResponse field, one section of a journal record
// (journal.cpp), and the dataset /response/<name> [samples, buildings, floors] of the result
// file (result_file.cpp), which the fragility reader reads by the same name. Adding an array
// is its SampleOutcome member plus one entry.
#include <vector>

namespace pound {

struct SampleOutcome;
struct FloorResponse;

struct FloorArrayField {
  const char* name;     ///< dataset under /response, e.g. "peak_drift_pounding"
  const char* unit;     ///< SI unit of the values ("-" dimensionless)
  const char* meaning;  ///< one line
  std::vector<double> SampleOutcome::*member;  ///< the array of a sample's outcome
  double FloorResponse::*source;               ///< its value per floor (simulate_row.hpp)
};

/// Every per-floor array, in the order of the journal record and the result file.
const std::vector<FloorArrayField>& floor_array_fields();

}  // namespace pound

#pragma once
// The per-building response arrays of a campaign sample (issue 23: collapse), as one table like
// floor_arrays.hpp: each array is [building] in a SampleOutcome, one section of a journal record
// (journal.cpp) and the dataset /response/<name> [samples, buildings] of the result file
// (result_file.cpp), which the campaign reader reads by the same name. Adding an array is its
// SampleOutcome member plus one entry.
#include <vector>

namespace pound {

struct SampleOutcome;
struct RowSimulation;

struct BuildingArrayField {
  const char* name;     ///< dataset under /response, e.g. "collapsed_pounding"
  const char* unit;     ///< SI unit of the values ("-" dimensionless)
  const char* meaning;  ///< one line
  std::vector<double> SampleOutcome::*member;                ///< the array of a sample's outcome
  double (*source)(const RowSimulation& sim, int building);  ///< its value per building
};

/// Every per-building array, in the order of the journal record and the result file.
const std::vector<BuildingArrayField>& building_array_fields();

}  // namespace pound

#pragma once
// The JSON object `pound simulate --json` prints (README, "Commands"): per building and floor the
// peaks with and without pounding, collapse, per contact site the impacts, the damped Sears
// model's slabs, and the energy balance of each run. Numbers with 17 significant digits (they
// read back as the same doubles), non-finite ones as null. The Python module parses this text,
// so that its results are the program's, number for number.
#include <string>

#include "structure/building_row.hpp"
#include "study/simulation_run.hpp"

namespace pound {

/// The object, one line without the final newline.
std::string simulation_json(const BuildingRow& row, const SimulationRun& run);

}  // namespace pound

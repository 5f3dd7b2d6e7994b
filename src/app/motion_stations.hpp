#pragma once
// pound motion generate with stations (issue 28): the station set's files, its motions.h5 and
// its report (docs/ground.md, "What pound motion generate writes").
#include <string>

#include "ground/station_set.hpp"
#include "io/options.hpp"

namespace pound::app {

/// Generates the set of `request` (request.enabled), writes DIR/motion-NNN-sK.txt,
/// DIR/target-NNN.txt and DIR/motions.h5 and prints the report (a table, or --json).
int run_station_set(const Options& o, const StationSetRequest& request, const std::string& dir);

}  // namespace pound::app

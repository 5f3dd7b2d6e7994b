#pragma once
// Study keys of the damped Sears model in `pound simulate` (contact.model = sears): the slab of
// each building's floors and the model options (docs/sears.md).
#include <vector>

#include "io/options.hpp"
#include "sears/sears_simulation.hpp"
#include "structure/building_row.hpp"

namespace pound {

std::vector<OptionSpec> sears_row_option_specs();
/// The keys of a row under any contact model: row_option_specs() and sears_row_option_specs().
std::vector<OptionSpec> row_and_sears_option_specs();
/// Reads and validates the slab of every building and the model options.
sears::SearsRowModel sears_row_from_options(const Options& opt, const BuildingRow& row);

}  // namespace pound

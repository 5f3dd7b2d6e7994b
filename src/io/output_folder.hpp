#pragma once
// The output folder of a post-processing command (pound fragility, pound risk): the one of
// --out, or RUN-<suffix>/ beside the campaign file RUN.h5, created before the files are written
// and refused where one of them would be the campaign file itself.
#include <string>
#include <vector>

#include "io/options.hpp"

namespace pound {

/// --out, or RUN-<suffix>/ beside `input` (its stem: RUN.h5 -> RUN-<suffix>).
std::string output_folder(const Options& opt, const std::string& input, const std::string& suffix);

/// Creates `dir` (and its parents); InputError naming --out when it cannot, or when one of
/// `names` in it is `input` itself.
void make_output_folder(const Options& opt, const std::string& dir, const std::string& input,
                        const std::vector<std::string>& names);

}  // namespace pound

#pragma once
// `pound hysteresis`, the storey-law tester (issue 23), as library calls shared by the program
// (app/cmd_hysteresis.cpp) and the Python module (issue 25): one storey of a law, its stiffness,
// strength, height and law keys read and validated as a study's building, driven from rest
// through a drift history by the law's incremental form (hysteresis/drive.hpp).
#include <string>
#include <vector>

#include "io/options.hpp"
#include "structure/building.hpp"

namespace pound {

/// The options of `pound hysteresis`: law, k0, fy, height, drifts, json and the storey laws'
/// keys (storey_law_option_specs("")).
std::vector<OptionSpec> hysteresis_option_specs();
/// Its one-line description (the --help header).
extern const char* const kHysteresisSummary;

/// The one-storey building of the options (--law, --k0, --fy, --height, the law keys),
/// validated as a study's building: errors name the key and what is valid.
Building tested_storey(const Options& opt);

/// The storey shears [N] of b's storey at the drifts [m], from rest. Throws InputError when
/// there is no drift or one is not finite (`name` names the drifts in the message).
std::vector<double> storey_shears(const Options& opt, const Building& b,
                                  const std::vector<double>& drifts, const std::string& name);

}  // namespace pound

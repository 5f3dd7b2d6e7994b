#pragma once
// `pound impact` as library calls (issue 25), shared by the program (app/cmd_impact.cpp) and the
// Python module: two free bodies (no springs, no ground motion) colliding once through a contact
// model, the options read and validated as the program reads them, and the JSON it prints.
#include <string>
#include <vector>

#include "contact/impact_result.hpp"
#include "io/options.hpp"

namespace pound {

/// The options of `pound impact`: model, e, k, m1, m2, v0, dt, rtol, v0-min, json, and the
/// damped Sears model's bar keys (sears/sears_options.hpp).
std::vector<OptionSpec> impact_option_specs();
/// Its one-line description (the --help header).
extern const char* const kImpactSummary;

/// The impact the options describe (parsed into opt). Throws InputError on a bad value (one
/// line naming the key and what is valid), NumericalError on a numerical failure.
ImpactResult impact_from_options(const Options& opt);

/// The object `pound impact --json` prints, one line without the final newline: e_eff,
/// contact_duration_s, impulse_Ns, peak_force_N, max_penetration_m, v1_after, v2_after,
/// contact_phases, internal_energy1_J, internal_energy2_J (17 significant digits, null when not
/// finite).
std::string impact_json(const ImpactResult& r);

}  // namespace pound

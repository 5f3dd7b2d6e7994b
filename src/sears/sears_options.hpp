#pragma once
// Options of `pound impact --model sears`: the bars' geometry and material and the damped Sears
// model options. The common options (--m1 --m2 --v0 --json --model --dt --k) are the caller's
// (src/app/cmd_impact.cpp); sears_impact_spec_from reads --dt and --k when the user gave them
// (--k: the contact stiffness given directly, N/m flat or N/m^1.5 hertz, overriding --D or the
// radii).
#include <vector>

#include "io/options.hpp"
#include "sears/sears_impact.hpp"

namespace pound::sears {

/// Declarations of --length1 --length2 --E --rho --poisson --E1 --E2 --rho1 --rho2 --poisson1
/// --poisson2 --modes --xi-s --chi --contact --D --radius1 --radius2 --force-cap, with units
/// and defaults. --dt and --k are not declared here: they are common options of the caller.
std::vector<OptionSpec> sears_impact_option_specs();

/// The impact of bar 1 (mass m1 [kg], moving at v0 [m/s]) on bar 2 (mass m2 [kg], at rest),
/// from parsed options. Throws InputError via opt.invalid(key, ...) naming the key and what is
/// valid, including a --dt above the largest allowed step.
SearsImpactSpec sears_impact_spec_from(const Options& opt, double m1, double m2, double v0);

}  // namespace pound::sears

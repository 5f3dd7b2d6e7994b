#pragma once
// Builds a design spectrum from options. Commands that take a target spectrum append
// design_spectrum_option_specs() to their own declarations; an unknown spectrum name or a
// missing parameter gives an InputError naming the key and what is valid.
#include <memory>
#include <vector>

#include "io/options.hpp"
#include "motion/design_spectrum.hpp"

namespace pound {

/// Option declarations: spectrum, damping, ec8-type, ground-type, ag, site-class, Z, R,
/// return-period, N, fault-distance, SDS, SD1, TL, japan-level, japan-soil, japan-zone, table.
std::vector<OptionSpec> design_spectrum_option_specs();

/// The spectrum named by option "spectrum" with its parameters. Spectra without a damping
/// correction of their own (NZS 1170.5, ASCE 7) reject a damping other than 0.05.
std::unique_ptr<DesignSpectrum> make_design_spectrum(const Options& options);

}  // namespace pound

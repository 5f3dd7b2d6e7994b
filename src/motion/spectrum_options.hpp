#pragma once
// The options of `pound motion spectrum` and `pound motion target` (issue 25: shared with the
// Python module's pound.motion): the period list of a spectrum, the record file's keys, its
// processing, and the oscillators' damping and sub-steps, each validated with an error naming
// the key and what is valid.
#include <string>
#include <vector>

#include "io/options.hpp"
#include "motion/ground_motion.hpp"
#include "motion/motion_reader.hpp"
#include "motion/response_spectrum.hpp"

namespace pound {

/// periods, t-min, t-max, n-periods, json.
std::vector<OptionSpec> period_option_specs();
/// The periods [s]: the list `periods` (each >= 0), else n-periods (>= 2) log-spaced from
/// t-min to t-max (> t-min).
std::vector<double> periods_from_options(const Options& o);

/// The options of `pound motion spectrum`: input, format, units, dt, accept-any-pga, truncate,
/// scale, baseline, damping, substep and period_option_specs().
std::vector<OptionSpec> record_spectrum_option_specs();
/// The record file of those options (input, format, units, dt, accept-any-pga); a peak refused
/// as implausible names `check_pga_key` as the way to accept it.
MotionFileSpec record_file_spec(const Options& o, const std::string& check_pga_key);
/// The record truncated (truncate), scaled (scale) and baseline-corrected (baseline).
GroundMotion processed_record(const Options& o, GroundMotion m);

/// The oscillators of a spectrum.
struct SpectrumSettings {
  double damping = 0.05;            ///< in [0, 1) [-]
  ResponseSpectrumOptions options;  ///< sub-steps (substep >= 0)
};
SpectrumSettings spectrum_settings_from_options(const Options& o);

}  // namespace pound

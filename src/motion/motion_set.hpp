#pragma once
// A set of spectrum-compatible motions (issue 25): `pound motion generate` and the Python
// module's pound.motion.generate, from the same options, validation and numbers. Motion i of a
// set is generated from the stream (seed, i) (simqke.hpp), with record-to-record variability
// matched to its own random target drawn from (seed, "motion.spectrum", i)
// (spectral_variability.hpp); each is compared with its own target at the report periods (the
// matching periods without the generator's extension beyond either end). No files, no printing.
#include <memory>
#include <string>
#include <vector>

#include "io/options.hpp"
#include "motion/design_spectrum.hpp"
#include "motion/simqke.hpp"
#include "motion/spectral_variability.hpp"

namespace pound {

/// The options of `pound motion generate`: the design spectrum's, count, duration, dt, seed,
/// out, the envelope's, t-min, t-max, n-periods, max-iterations, json and the variability's
/// (with '-': --sigma-lnsa).
std::vector<OptionSpec> motion_set_option_specs();

/// What a set is generated from.
struct MotionSetRequest {
  std::unique_ptr<DesignSpectrum> target;
  long count = 1;          ///< motions, 1 to 100000
  double duration = 20.0;  ///< [s]
  long seed = 1;           ///< >= 0
  SimqkeSettings settings;
  VariabilitySettings variability;
};

/// The request of the options (every key but out and json), each validated with an error
/// naming the key and what is valid.
MotionSetRequest motion_set_from_options(const Options& o);

/// How one motion matches its own target.
struct MotionReport {
  SpectrumMatch match;                         ///< at the report periods
  double pga = 0.0, v_end = 0.0, d_end = 0.0;  ///< [m/s^2], [m/s], [m]
  int iterations = 0, attempt = 0;             ///< correction iterations, phase set
};

/// A generated set, rows by motion.
struct MotionSet {
  std::vector<double> periods;            ///< report periods [s]
  std::vector<double> design;             ///< the design spectrum there [m/s^2]
  std::vector<GroundMotion> motions;      ///< the motions [m/s^2]
  std::vector<MotionReport> reports;      ///< each against its own target
  std::vector<double> psa, targets, eps;  ///< [motions x periods]: PSA [m/s^2], own target
                                          ///< [m/s^2], eps [-] (eps with variability only)
  std::vector<double> mean, geomean;      ///< of the motions' PSA [m/s^2]
  std::vector<double> sigma;              ///< sigma of ln Sa [-] (with variability only)
  bool variable = false;                  ///< random targets (variability spectral)
};

/// Generates the set of the request (one thread).
MotionSet generate_motion_set(const MotionSetRequest& request);

}  // namespace pound

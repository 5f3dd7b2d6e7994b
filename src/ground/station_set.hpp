#pragma once
// A set of spatially varying motions for `pound motion generate --stations/--positions` (issue
// 28, docs/ground.md): motion i of the set is the S stations of StationGenerator::generate(seed,
// i) (with record-to-record variability: one random target per motion, drawn as in
// motion/motion_set.hpp and shared by its stations), each station delayed by its wave-passage
// arrival delay (wave_passage.hpp); every station compared with the motion's target at the
// report periods; the set's achieved lags and lagged coherency (achieved_coherency.hpp). Without
// any of the station options the command is motion/motion_set.hpp's, outputs unchanged. No files,
// no printing.
#include <vector>

#include "ground/achieved_coherency.hpp"
#include "ground/station_generator.hpp"
#include "io/options.hpp"
#include "motion/motion_set.hpp"

namespace pound {

/// motion_set_option_specs() and the station options: stations, spacing, positions,
/// apparent-velocity, coherency, coherency-parameters (declared without defaults, so that the
/// resolved configuration of a set without stations is what it was).
std::vector<OptionSpec> station_set_option_specs();

struct StationSetRequest {
  MotionSetRequest motions;    ///< everything of a set without stations
  bool enabled = false;        ///< a station option was given: station outputs
  StationSettings stations;    ///< positions [m] and coherency
  double apparent_velocity;    ///< [m/s]; +-inf: no delay (default)
  std::vector<double> delays;  ///< arrival delay of each station [s]
};

/// The request of the options, each validated with one line naming the flag and what is valid
/// (--stations without --spacing, positions not strictly increasing, v = 0, an unknown model, a
/// coherency parameter out of range, ...).
StationSetRequest station_set_from_options(const Options& o);

/// A generated set, motion by motion, station by station.
struct StationSet {
  std::vector<double> periods;                     ///< report periods [s]
  std::vector<double> design;                      ///< design spectrum there [m/s^2]
  std::vector<std::vector<GroundMotion>> motions;  ///< [motion][station], delayed [m/s^2]
  std::vector<std::vector<MotionReport>> reports;  ///< [motion][station], own target
  std::vector<double> psa;                         ///< [motion x station x period] [m/s^2]
  std::vector<double> targets, eps;                ///< [motion x period] [m/s^2], [-]
  std::vector<double> mean, geomean;               ///< [station x period] [m/s^2]
  std::vector<double> sigma;                       ///< sigma of ln Sa (variability) [-]
  bool variable = false;                           ///< random targets
  AchievedCoherency coherency;                     ///< every pair at curve_frequencies()
};

/// The frequencies at which the set's coherency is estimated [Hz]: 0.5 to 10 Hz (at most 0.8
/// Nyquist - 0.25 Hz) every 0.25 Hz, +- 0.25 Hz each; the report shows 1, 2, 4 and 6 Hz.
std::vector<double> curve_frequencies(double dt);
/// The report's frequencies among them [Hz].
std::vector<double> report_frequencies(double dt);

/// Generates the set of the request (one thread); request.enabled must be true.
StationSet generate_station_set(const StationSetRequest& request);

}  // namespace pound

#pragma once
// A Monte Carlo campaign study: the row of buildings and contact model of `pound simulate`,
// plus sampled parameters, the ground-motion source and the intensity measure. Parsed and
// validated completely before any rank simulates (errors name file, line and key).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "campaign/sampled_parameters.hpp"
#include "io/options.hpp"
#include "motion/design_spectrum.hpp"
#include "motion/ground_motion.hpp"
#include "motion/simqke.hpp"
#include "motion/spectral_variability.hpp"
#include "sears/sears_simulation.hpp"
#include "simulation/contact_spec.hpp"
#include "solver/integrator_settings.hpp"
#include "structure/building_row.hpp"
#include "study/row_study.hpp"

namespace pound {

enum class SamplingMethod { monte_carlo, latin_hypercube };
enum class IntensityMeasure { pga, sa };
enum class MotionSource { generated, records };

/// The row's keys are read by the study reader that `pound simulate` uses (study/row_study.hpp);
/// the sampled parameters override the fixed values per sample.
struct CampaignStudy : RowStudy {
  // Sampling.
  long samples = 100;  ///< number of samples of the campaign [-]
  /// The ids this run simulates, [range_lo, range_hi) (default: all). A part of a campaign
  /// split over independent jobs; each sample stays the same function of (study, samples,
  /// seed, id), Latin hypercube strata included. `pound merge` joins the parts.
  long range_lo = 0, range_hi = 0;
  long range_size() const { return range_hi - range_lo; }
  std::uint64_t seed = 1;  ///< study seed
  SamplingMethod sampling = SamplingMethod::latin_hypercube;
  /// Samples handed to a worker at a time, and outcomes it returns in one message; 0 =
  /// automatic (campaign_batch(): 1 on few ranks, more on many; docs/scaling.md).
  int batch = 0;
  std::vector<SampledParameter> parameters;

  // Ground motion.
  MotionSource source = MotionSource::generated;
  std::shared_ptr<const DesignSpectrum> spectrum;  ///< target (generated motions)
  double motion_duration = 20.0;                   ///< generated motion duration [s]
  SimqkeSettings generator;                        ///< generator settings
  /// Random target spectra of the generated motions ([generator] variability, ...).
  VariabilitySettings variability;
  std::vector<GroundMotion> records;  ///< record list (records source)

  // Intensity.
  IntensityMeasure measure = IntensityMeasure::pga;
  int im_building = 0;         ///< 0-based building whose T1 defines Sa(T1)
  double im_period = 0.0;      ///< T1 of that building, on its foundation [s]
  std::vector<double> levels;  ///< stripe levels [m/s^2]; empty: sampled scale factor
  bool has_scale = false;
  Distribution scale;  ///< sampled scale factor on the motion (continuous IM)

  std::string resolved;  ///< the resolved study text, stored in the result file

  int buildings() const { return static_cast<int>(row.buildings.size()); }
  int max_floors() const;
  int pairs() const { return buildings() - 1; }
  int max_levels() const;
};

/// Every key a campaign study may contain (for --help and the unknown-key check).
std::vector<OptionSpec> campaign_option_specs();
/// Builds and validates the study; `samples_override` > 0 replaces campaign.samples and
/// `seed_override` >= 0 replaces campaign.seed.
CampaignStudy campaign_from_options(const Options& opt, long samples_override, long seed_override);

}  // namespace pound

#pragma once
// One Monte Carlo sample as a pure function: (study, sample id) -> outcome. Every random draw
// comes from the counter-based generator keyed by (study seed, stream of the parameter,
// sample id), so the outcome does not depend on which rank runs it or when.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "campaign/campaign_study.hpp"
#include "ground/station_generator.hpp"
#include "sampling/latin_hypercube.hpp"

namespace pound {

enum class SampleStatus : int {
  ok = 0,
  numerical_failure = 1,  ///< non-finite response, step-size underflow, chatter
  input_failure = 2,      ///< a sampled combination the models reject
  not_run = -1,           ///< (result files only) not simulated yet
};

/// The drawn inputs of one sample.
struct SampleDraw {
  long id = 0;
  std::vector<double> values;  ///< per study parameter; the model as its index in the labels
  std::string model;           ///< contact model of this sample
  double level = 0.0;          ///< stripe level [m/s^2] (NaN with a sampled scale)
  double scale_draw = 0.0;     ///< sampled scale factor (NaN with stripes)
  std::uint64_t motion_seed = 0;
  /// eps of the generated motion's random target at the generator's matching periods [-]
  /// (empty without variability; spectral_variability.hpp).
  std::vector<double> spectral_epsilon;
  int record = -1;  ///< record index (records source)
};

/// The outcome; arrays are row-major [building][floor] (NaN where a building has fewer
/// floors or the sample failed; the per-floor arrays are listed in floor_arrays.hpp) and
/// [pair][level] (NaN where a pair has fewer colliding levels).
struct SampleOutcome {
  long id = 0;
  SampleStatus status = SampleStatus::ok;
  std::string message;
  double im = 0.0;                               ///< intensity measure of the scaled motion [m/s^2]
  double scale = 0.0;                            ///< factor applied to the motion [-]
  std::vector<double> values;                    ///< sampled parameter values (as in SampleDraw)
  std::vector<double> disp_pounding, disp_free;  ///< [m]
  std::vector<double> peak_drift_ratio_pounding, peak_drift_ratio_free;  ///< peak drift ratios [-]
  std::vector<double> accel_pounding, accel_free;  ///< peak absolute accelerations [m/s^2]
  /// |storey drift| at the end of the run / storey height [-]
  std::vector<double> residual_drift_pounding, residual_drift_free;
  /// Peak storey drift / yield drift [-]; NaN for a building without yield_shears.
  std::vector<double> ductility_pounding, ductility_free;
  /// Hysteretic energy dissipated by the storey below the floor [J].
  std::vector<double> hysteretic_energy_pounding, hysteretic_energy_free;
  /// Per building (building_arrays.hpp): collapsed (1) or standing (0) in each run, and when
  /// [s] (NaN while standing); NaN for a failed sample.
  std::vector<double> collapsed_pounding, collapsed_free;
  /// Per building: the largest column-shear demand over strength of its struck storeys, with
  /// and without pounding (issue 36) [-]; NaN: no strength, or no storey struck.
  std::vector<double> column_shear_ratio_pounding, column_shear_ratio_free;
  std::vector<double> collapse_time_pounding, collapse_time_free;
  std::vector<double> peak_force;  ///< [N]
  /// Contact phases started in the pounding run, as doubles [-]: every phase, so > 0 exactly
  /// when the faces touched (the damped Sears model's raw count, SiteResult::impacts, not its
  /// thresholded SiteContacts::impacts).
  std::vector<double> impacts;
  /// Peak relative approach u_L - u_R of the facing floors in the free run [m]
  /// (SiteResponse::approach_free): the smallest gap at that level this motion would not close.
  std::vector<double> approach_free;
  /// Per site (issue 36): the peak shear demand on the struck columns in the pounding run [N]
  /// (SiteResponse::column_shear_pounding; NaN at slab sites) and the face's permanent
  /// indentation at its end [m] (SiteResponse::crush; 0 without contact.force_cap).
  std::vector<double> peak_column_shear, crush;
  /// Per pair: the peak relative ground displacement of its two buildings over the run [m]
  /// (RowSimulation::ground_relative; 0 on one motion).
  std::vector<double> ground_relative;
  double wall_seconds = 0.0;  ///< run bookkeeping
  int rank = 0;               ///< run bookkeeping
};

/// Runs samples of one study; keeps per-worker caches (the motion generator's FFT plans,
/// the Latin hypercube permutations). One object per rank.
class SampleRunner {
 public:
  explicit SampleRunner(const CampaignStudy& study);
  ~SampleRunner();
  SampleDraw draw(long id);
  /// The row, contact and Sears model of a drawn sample: the study's with the sample's values
  /// applied (sampled_parameters.hpp).
  SampleModel model(const SampleDraw& d) const;
  /// Never throws for a failing simulation: the failure is the outcome's status and message.
  SampleOutcome run(long id) { return run(draw(id)); }
  /// The same for given draws (e.g. a sample of an earlier version of the sampling).
  SampleOutcome run(const SampleDraw& d);

 private:
  const CampaignStudy& st_;
  LatinHypercube lhs_;
  std::unique_ptr<StationGenerator> generator_;
  std::unique_ptr<TargetVariability> variability_;  ///< (generated motions)
};

}  // namespace pound

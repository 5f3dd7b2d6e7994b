#pragma once
// The fragility analysis of a campaign: engineering demand parameters (EDP) per sample and
// building, lognormal fragility curves with and without pounding for every damage-state limit
// (lognormal_fit.hpp), their bootstrap and asymptotic 90 % bands, the headline shift
// theta_pounding / theta_free, and the rank sensitivity of the pounding amplification to the
// sampled parameters (rank_correlation.hpp). Pure: data in, numbers out.
#include <cstddef>
#include <string>
#include <vector>

#include "fragility/bootstrap.hpp"
#include "fragility/campaign_reader.hpp"
#include "fragility/lognormal_fit.hpp"

namespace pound {

/// Engineering demand parameters, each the maximum over the building's floors (storeys).
enum class Edp {
  collapse,        ///< the building collapsed (issue 23): 1 or 0; its one "limit" is 1
  drift,           ///< peak inter-storey drift ratio [-]
  disp,            ///< peak floor displacement relative to the ground [m]
  accel,           ///< peak absolute floor acceleration [m/s^2]
  force,           ///< peak pounding force on the building, over its pairs and levels [N]
  residual_drift,  ///< residual inter-storey drift ratio at the end of the run [-]
  ductility,       ///< storey ductility demand, peak drift / yield drift [-] (NaN: no Fy)
  /// Issue 36: the largest shear demand over column_shear_strength of the building's storeys a
  /// neighbour's slab strikes [-] (NaN: no strength, or no storey struck); its one limit is 1,
  /// reached at a ratio of 1 or more (the struck column fails in shear)
  column_shear
};
const char* to_string(Edp e);  ///< "drift", "disp", "accel", "force", "residual_drift", ...
const char* unit_of(Edp e);
/// The per-floor dataset of the EDP under /response (campaign/floor_arrays.hpp), with or
/// without pounding; "" for the force (from /response/peak_force).
std::string dataset_of(Edp e, bool pounding);

struct FragilitySettings {
  std::vector<double> drift_limits{0.005, 0.01, 0.02, 0.025};  ///< [-] (ratio, not %)
  std::vector<double> disp_limits;                             ///< [m]; empty: no disp curves
  std::vector<double> accel_limits;                            ///< [m/s^2]; empty: no accel curves
  std::vector<double> force_limits;                            ///< [N]; empty: no force curves
  std::vector<double> residual_drift_limits;  ///< [-] (ratio); empty: no residual drift curves
  std::vector<double> ductility_limits;       ///< [-]; empty: no ductility curves
  /// Collapse curves (when the file holds the collapse arrays). Every other limit counts a
  /// collapsed building as exceeded.
  bool collapse = true;
  /// Where the study samples the contact model: the curves and shifts of each model's
  /// analyses beside the pooled ones.
  bool per_model = true;
  BootstrapSettings bootstrap;    ///< replicates and seed
  double confidence = 0.90;       ///< of the bands [-]
  std::size_t grid_points = 120;  ///< IM points of the curve bands [-]
  /// Keep every curve's bootstrap fits (FragilityCurve::replicates, FragilityShift::
  /// free_same_replicates), for estimators built on them (pound risk's damage bands).
  bool keep_replicates = false;
};

struct FragilityCurve {
  std::string model;         ///< the contact model of its analyses; "" for all (pooled)
  std::size_t building = 0;  ///< 0-based
  Edp edp = Edp::drift;
  double limit = 0.0;  ///< damage-state limit [unit_of(edp)]
  bool pounding = true;
  /// Analyses left out of this curve [-]: their EDP is not finite (the ductility of a building
  /// without yield_shears is NaN) or they are censored (below); the fit uses the others.
  std::size_t left_out = 0;
  /// Of those, the pounding run's analyses stopped at another building's collapse while this
  /// building stood (right-censored: its later response is unknown), all left out, also those
  /// in which it had exceeded the limit before the stop (docs/fragility.md, "Collapse") [-].
  std::size_t censored = 0;
  LognormalFit fit;
  Interval theta_ci, beta_ci;                   ///< bootstrap percentile bands
  double theta_asym_lo = 0, theta_asym_hi = 0;  ///< asymptotic: exp(ln theta -+ z sd)
  double beta_asym_lo = 0, beta_asym_hi = 0;    ///< asymptotic: beta -+ z sd
  std::vector<Observation> observed;            ///< per stripe (or per IM bin when continuous)
  std::vector<double> band_lo, band_hi;         ///< bootstrap band of P on the report's grid
  /// The fit of each bootstrap replicate, in replicate order (FragilitySettings::
  /// keep_replicates; empty otherwise). Replicate r of every curve of one set (pooled, or one
  /// model's) redraws the same analyses.
  std::vector<LognormalFit> replicates;
};

/// The headline: median ratio theta_pounding / theta_free for one building, EDP and limit.
struct FragilityShift {
  std::string model;  ///< as FragilityCurve::model
  std::size_t building = 0;
  Edp edp = Edp::drift;
  double limit = 0.0;
  double ratio = 0.0;  ///< NaN when either curve has no finite estimate
  Interval ci;         ///< bootstrap band of the ratio (paired replicates)
  /// The two medians of the ratio [unit of the IM]: the pounding curve's, and the free one's
  /// fitted on the same analyses. Where another building's collapse censored some pounding
  /// analyses (FragilityCurve::censored), the free median is fitted again without them
  /// (same_analyses), so that the ratio compares like with like: the censored samples are those
  /// whose records were strong enough to collapse the neighbour, and leaving them out of the
  /// pounding curve alone would bias the ratio. Otherwise it is the free curve's.
  double theta_pounding = 0.0, theta_free = 0.0;
  bool same_analyses = false;
  LognormalFit free_same;  ///< the free fit of theta_free (the free curve's when not same_analyses)
  /// free_same fitted to each bootstrap replicate, paired with the pounding curve's replicates
  /// (FragilitySettings::keep_replicates; empty otherwise).
  std::vector<LognormalFit> free_same_replicates;
};

struct SensitivityRow {
  std::size_t building = 0;
  std::string response;   ///< "disp_amplification" or "drift_amplification" (pounding / free)
  std::string parameter;  ///< sampled key, or "im" (intensity measure)
  double spearman = 0.0, prcc = 0.0;
  std::size_t samples = 0;
};

struct FragilityReport {
  std::size_t samples = 0, failed = 0, used = 0;  ///< analyses in the file, failed, fitted
  bool stripes = true;                            ///< multiple stripes (else continuous IM)
  std::vector<double> grid;                       ///< IM grid of the bands [m/s^2]
  std::vector<FragilityCurve> curves;             ///< the pooled curves first, then each model's
  std::vector<FragilityShift> shifts;             ///< in the order of the curves
  std::vector<std::string> models;          ///< the models with curves of their own (may be empty)
  bool collapse = false;                    ///< collapse curves (the file holds collapse arrays)
  std::vector<SensitivityRow> sensitivity;  ///< ranked by |PRCC| within building and response
  std::vector<std::string> unranked;        ///< sampled labels left out (e.g. model)
};

/// The damage-state limits of the study's [fragility] section stored in the campaign file
/// (drift_limits, disp_limits, accel_limits, force_limits, residual_drift_limits,
/// ductility_limits; SI units), each list absent from it keeping its FragilitySettings default.
/// Throws InputError naming the key when a limit is not > 0 or not a number; an unreadable
/// stored study only loses its limits.
FragilitySettings study_fragility_limits(const CampaignData& c);

/// The analyses that succeeded (their rows into `used`) and their design: each on the stripe
/// whose level matches its IM within 1e-5 (the stripe's IM is the mean of its analyses'), or
/// continuous intensities when the campaign has no stripes. Throws InputError naming the file
/// when a sample's IM lies on no stripe.
ExceedanceDesign exceedance_design(const CampaignData& c, std::vector<std::size_t>* used);

/// Observed fractions for reports and plots: per stripe, or (continuous intensities) about ten
/// equal-count IM bins at the geometric mean IM of each; analyses marked kLeftOut not counted.
/// With `bins_of`, the bins of those outcomes (a pounding curve's, for its free curve: the two
/// then share their bins, bin j of one beside bin j of the other) [-].
std::vector<Observation> observed_fractions(const ExceedanceDesign& d,
                                            const std::vector<char>& exceed,
                                            const std::vector<char>* bins_of = nullptr);

/// Throws InputError when no sample succeeded, the limits are not positive or the file lacks
/// the dataset of an EDP with limits (naming the file and the dataset).
FragilityReport analyse_fragility(const CampaignData& c, const FragilitySettings& s);

/// The EDP of sample s, building b (NaN where undefined; the collapse flag for
/// Edp::collapse). Throws InputError when the file lacks the EDP's dataset.
double edp_value(const CampaignData& c, Edp e, bool pounding, std::size_t s, std::size_t b);

}  // namespace pound

#pragma once
// Pounding risk of a campaign at every gap (docs/risk.md). Before its first contact a pounding
// run is the free run, so a pair with the at-rest gap g (the same at each of its levels)
// pounds in a sample exactly when the free-run approach of one of its levels exceeds g
// (/response/approach_free). For every gap of a grid this gives one pounding outcome per
// sample, fitted as pound fragility fits (lognormal, maximum likelihood, Baker 2015:
// fragility/lognormal_fit.hpp), and integrated over the site's hazard curve into the mean
// annual frequency of pounding nu(g) (risk_integral.hpp); then the probability in T years,
// the smallest gap whose probability is at most a target (with a bootstrap band:
// fragility/bootstrap.hpp), the code rules' gaps (code_rules.hpp, at each contact site:
// site_displacements.hpp) and their probabilities,
// and the mean annual frequencies of the damage limits with and without pounding with their
// bootstrap bands (damage_risk.hpp). Pure: data in, numbers out.
#include <string>
#include <vector>

#include "fragility/bootstrap.hpp"
#include "fragility/campaign_reader.hpp"
#include "fragility/fragility_analysis.hpp"
#include "fragility/lognormal_fit.hpp"
#include "risk/code_rules.hpp"
#include "risk/hazard_curve.hpp"
#include "structure/contact_geometry.hpp"

namespace pound {

struct RiskSettings {
  double years = 50.0;               ///< exposure time T [yr]
  double target_probability = 0.02;  ///< of pounding in T years, in (0, 1) [-]
  std::vector<double> gaps;          ///< gap grid [m], increasing; empty: the default grid
  int gap_points = 40;               ///< default grid: 0 to the largest approach [-]
  double design_im = 0.0;            ///< of the code rules [m/s^2]; 0: the 475-year intensity
  BootstrapSettings bootstrap;       ///< replicates and seed of the bands
  double confidence = 0.90;          ///< of the bands [-]
};

/// First mode of a building: period [s] and damping ratio [-] (for the DDC correlation).
struct BuildingMode {
  double period_s = 0.0;
  double damping = 0.05;
};

/// The first modes of the study's buildings with their nominal (not sampled) properties, as the
/// campaign file stores them (root attributes first_periods_s, damping_ratios); throws
/// InputError naming the file when it lacks them.
std::vector<BuildingMode> study_first_modes(const CampaignData& c);

/// Throws InputError (naming the hazard file) when its measure is not the campaign's: PGA
/// against PGA, sa(T) against Sa(T1) with T within 1 % of the campaign's im_period_s.
void check_hazard_measure(const CampaignData& c, const HazardCurve& h);

/// Pounding of one pair at one gap.
struct GapEstimate {
  double gap = 0.0;   ///< [m]
  long analyses = 0;  ///< samples with a free-run approach
  long pounding = 0;  ///< of them, samples whose approach exceeds the gap
  /// Of those, samples in which a building of the pair collapsed in the free run: the approach
  /// of a collapsing building's sway (issue 23) [-]
  long pounding_collapsed = 0;
  LognormalFit fit;          ///< P(pounding | IM) (Baker 2015)
  double maf = 0.0;          ///< nu [1/yr]; NaN without a finite fit
  double probability = 0.0;  ///< in T years; NaN without a finite fit
  /// Share of nu from intensities outside the campaign's (below its lowest stripe or above its
  /// highest): there the fitted fragility is extrapolated [-].
  double outside_share = 0.0;
  Interval probability_band;          ///< bootstrap percentile band
  std::vector<Observation> observed;  ///< per stripe (or IM bin) [m/s^2], n, pounding
};

/// How the gap for the target was found.
enum class TargetStatus {
  found,        ///< bracketed by the grid and refined on the samples' approaches
  at_most,      ///< the smallest gap with an estimate already meets the target: an upper bound
  not_reached,  ///< no gap with an estimate meets it
  no_estimate   ///< no gap of the grid has a finite fit
};
const char* to_string(TargetStatus s);

struct CodeRuleResult {
  SeparationRule rule = SeparationRule::abs;
  double gap = 0.0;      ///< the largest over the pair's levels [m]
  int level = 0;         ///< the level that gives it (1-based)
  GapEstimate estimate;  ///< pounding at that gap
};

struct PairRisk {
  std::size_t pair = 0;           ///< 0-based: buildings pair and pair + 1
  std::vector<GapEstimate> grid;  ///< increasing gaps
  double gap_for_target = 0.0;    ///< [m]; NaN unless found or at_most
  TargetStatus target_status = TargetStatus::no_estimate;
  Interval gap_band;  ///< bootstrap band of gap_for_target [m]
  int bootstrap_replicates = 0;
  // Code rules at the design intensity.
  bool rules_computed = false;
  std::string rules_note;  ///< why not, when not computed
  /// Per level (the pair's contact site, 1-based in CodeRuleResult::level; aligned floors: the
  /// floor), the median free peak displacement of each side's point there [m]
  /// (risk/site_displacements.hpp).
  std::vector<double> median_left, median_right;
  double rho = 0.0;  ///< Der Kiureghian correlation of the first modes [-]
  Ec8Case ec8_case = Ec8Case::floors_unknown;  ///< EN 1998-1 4.4.2.7(3), from the pair's sites
  std::vector<CodeRuleResult> rules;           ///< abs, srss, ddc, ec8
};

/// A damage limit's mean annual frequency of exceedance with and without pounding.
struct DamageRisk {
  std::string model;  ///< the contact model of its analyses; "" for all (FragilityCurve::model)
  std::size_t building = 0;
  Edp edp = Edp::drift;
  double limit = 0.0;                         ///< [unit_of(edp)]
  LognormalFit pounding, free;                ///< free: no_data for the force
  double maf_pounding = 0.0, maf_free = 0.0;  ///< [1/yr]; NaN without a finite fit
  double ratio = 0.0;                         ///< maf_pounding / maf_free; NaN when either is
  /// Where another building's collapse censored some of the pounding analyses (the pounding run
  /// stops at the row's first collapse; FragilityShift::same_analyses): the pounding fit
  /// describes the samples whose neighbour did not collapse first, the weaker records. Then
  /// ratio = nu(pounding) / nu(free_same), both fitted on those analyses (like for like), and
  /// maf_pounding = maf_free x ratio: the free rate of all analyses times the effect of pounding
  /// (maf_pounding_kept: nu of the pounding fit itself) [1/yr].
  bool same_analyses = false;
  LognormalFit free_same;
  double maf_pounding_kept = 0.0;
  /// Share of each nu from intensities outside the campaign's (GapEstimate::outside_share).
  double outside_pounding = 0.0, outside_free = 0.0;
  /// 1 - exp(-nu T) of maf_pounding and maf_free: in T = RiskSettings::years [-].
  double probability_pounding = 0.0, probability_free = 0.0;
  /// Bootstrap percentile bands (RiskSettings::confidence): the estimator above, like for like
  /// included, on the fits of each replicate of the fragility bootstrap (fragility/bootstrap.hpp:
  /// resampling within stripes, every curve of a set on the same redrawn analyses, so the
  /// pounding and free fits of a replicate are paired). Each band's `finite` counts the
  /// replicates with a finite value (a replicate's fit may have no finite estimate); NaN bounds
  /// when none has, or without replicates.
  Interval maf_pounding_band, maf_free_band, ratio_band;      ///< [1/yr], [1/yr], [-]
  Interval probability_pounding_band, probability_free_band;  ///< in T years [-]
  int bootstrap_replicates = 0;                               ///< replicates drawn [-]
};

/// Collapse of a building (issue 23): its damage limit Edp::collapse (the rates with and without
/// pounding, their ratio), its probability in T years, and with a design (MCE) intensity the
/// collapse margin ratio CMR = median collapse intensity / design intensity (FEMA P695, 6.3).
struct CollapseRisk : DamageRisk {
  /// Median collapse intensity with pounding [IM unit]: the pounding fit's, or where censored
  /// (same_analyses) the free median of all analyses times the like-for-like shift
  /// theta_pounding / theta_free_same (FragilityShift).
  double theta_pounding = 0.0;
  double cmr_pounding = 0.0, cmr_free = 0.0;  ///< [-]; NaN without a design intensity or fit
};

struct RiskReport {
  std::size_t samples = 0, failed = 0, used = 0;
  bool stripes = true;
  std::size_t groups = 0;        ///< stripes or IM bins
  double design_im = 0.0;        ///< [m/s^2]
  bool design_im_given = false;  ///< false: the hazard's 475-year intensity
  std::vector<PairRisk> pairs;
  std::vector<DamageRisk> damage;      ///< pooled first, then each sampled contact model's
  std::vector<CollapseRisk> collapse;  ///< the collapse limit of `damage`, pooled then per model
  std::vector<std::string> notes;      ///< what could not be estimated, and why
};

/// The collapse entries of `damage` (Edp::collapse) with their probability in s.years and, for
/// design_im > 0 [m/s^2], their collapse margin ratio theta / design_im.
std::vector<CollapseRisk> collapse_risks(const std::vector<DamageRisk>& damage,
                                         const RiskSettings& s, double design_im);

/// Each adjacent pair's contact sites (structure/contact_geometry.hpp; risk/study_sites.hpp);
/// empty where the study's floors could not be read.
using PairSites = std::vector<std::vector<SiteGeometry>>;

/// Throws InputError when the file has no /response/approach_free, no sample succeeded, the
/// settings are out of range, or a given design intensity lies outside the campaign's. The code
/// rules combine the displacements at each of a pair's `sites`; without them (sites shorter
/// than the pairs) floor l against floor l, and ec8 takes no reduction (Ec8Case::floors_unknown).
RiskReport analyse_risk(const CampaignData& c, const HazardCurve& h, const RiskSettings& s,
                        const std::vector<BuildingMode>& modes, const PairSites& sites,
                        const FragilitySettings& limits);

}  // namespace pound

#pragma once
// The damage limits of `pound risk` (docs/risk.md, "Damage limits"): for every limit of the
// study's [fragility] section, the fits of pound fragility with and without pounding
// (fragility/fragility_analysis.hpp) integrated over the hazard curve (risk_integral.hpp) into
// the mean annual frequency of exceedance nu, its probability in T years 1 - exp(-nu T), the
// ratio of the two rates, like for like where another building's collapse censored pounding
// analyses (DamageRisk::same_analyses), and the bootstrap band of each: the same estimator on
// the fits of every replicate of the fragility bootstrap (fragility/bootstrap.hpp; Efron &
// Tibshirani 1993, percentile method), whose replicates redraw the same analyses for every
// curve of a set, so a replicate's pounding and free fits are paired. Pure: data in, numbers
// out.
#include <string>
#include <vector>

#include "fragility/campaign_reader.hpp"
#include "fragility/fragility_analysis.hpp"
#include "fragility/lognormal_fit.hpp"
#include "risk/hazard_curve.hpp"
#include "risk/pounding_risk.hpp"

namespace pound {

/// The share of nu [1/yr] from intensities outside [lo, hi] [m/s^2]: 1 - integral_lo^hi P
/// |d lambda| / nu, with the boundary terms of the integration by parts (risk_integral.hpp).
/// NaN without a finite fit or without nu > 0.
double outside_share(const HazardCurve& h, const LognormalFit& f, double nu, double lo, double hi);

/// Every damage limit of `limits` (collapse and column shear first, as pound fragility orders
/// them), pooled and then per sampled contact model, with and without pounding at the
/// campaign's own gaps; bands from s.bootstrap (replicates, seed) at s.confidence, none with 0
/// replicates; probabilities in s.years. im_lo, im_hi: the campaign's lowest and highest
/// intensity [m/s^2] (the shares from outside them). Throws InputError as analyse_fragility.
std::vector<DamageRisk> damage_risks(const CampaignData& c, const HazardCurve& h,
                                     const FragilitySettings& limits, const RiskSettings& s,
                                     double im_lo, double im_hi);

/// Notes on the damage limits: those whose nu takes more than 25 % from intensities outside the
/// campaign's, and those whose band (with a finite point estimate) comes from fewer than all
/// the bootstrap replicates.
void add_damage_notes(const std::vector<DamageRisk>& damage, std::vector<std::string>& notes);

}  // namespace pound

#include "risk/damage_risk.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "risk/risk_integral.hpp"

namespace pound {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The rates of one damage limit from one set of fits: the point estimate's or one bootstrap
// replicate's (DamageRisk). free_same: the free fit on the pounding curve's analyses where
// another building's collapse censored some of them (like for like), else null.
struct DamageRates {
  double maf_pounding, maf_free, ratio, maf_pounding_kept;  // [1/yr], [1/yr], [-], [1/yr]
};

DamageRates damage_rates(const HazardCurve& h, const LognormalFit& pounding,
                         const LognormalFit& free, const LognormalFit* free_same) {
  auto nu = [&](const LognormalFit& f) {
    return f.finite() ? mean_annual_frequency(h, f.theta, f.beta) : kNaN;
  };
  DamageRates r;
  r.maf_pounding_kept = nu(pounding);
  r.maf_free = nu(free);
  if (free_same) {
    // Like for like: the ratio on the analyses the pounding curve keeps, applied to the free
    // rate of all the analyses.
    r.ratio = r.maf_pounding_kept / nu(*free_same);
    r.maf_pounding = r.maf_free * r.ratio;
  } else {
    r.maf_pounding = r.maf_pounding_kept;
    r.ratio = r.maf_pounding / r.maf_free;
  }
  return r;
}

// The bands of dr from the replicates' fits: pounding[r] and free[r] (empty: no free curve, as
// for the force) and free_same[r] (null unless like for like), replicate by replicate.
void add_bands(const HazardCurve& h, const RiskSettings& s,
               const std::vector<LognormalFit>& pounding, const std::vector<LognormalFit>& free,
               const std::vector<LognormalFit>* free_same, DamageRisk& dr) {
  const std::size_t n = pounding.size();
  std::vector<double> mp(n), mf(n), ratio(n), pp(n), pf(n);
  LognormalFit none;
  none.status = FitStatus::no_data;
  for (std::size_t r = 0; r < n; ++r) {
    const DamageRates x = damage_rates(h, pounding[r], r < free.size() ? free[r] : none,
                                       free_same ? &(*free_same)[r] : nullptr);
    mp[r] = x.maf_pounding;
    mf[r] = x.maf_free;
    ratio[r] = x.ratio;
    pp[r] = probability_in_years(x.maf_pounding, s.years);
    pf[r] = probability_in_years(x.maf_free, s.years);
  }
  dr.bootstrap_replicates = int(n);
  dr.maf_pounding_band = percentile_interval(mp, s.confidence);
  dr.maf_free_band = percentile_interval(mf, s.confidence);
  dr.ratio_band = percentile_interval(ratio, s.confidence);
  dr.probability_pounding_band = percentile_interval(pp, s.confidence);
  dr.probability_free_band = percentile_interval(pf, s.confidence);
}

// The free curve paired with the pounding curve k (the next one, of the same limit), or null
// (the force has none).
const FragilityCurve* free_curve(const FragilityReport& fr, std::size_t k) {
  const FragilityCurve& pc = fr.curves[k];
  if (k + 1 >= fr.curves.size()) return nullptr;
  const FragilityCurve& fc = fr.curves[k + 1];
  return !fc.pounding && fc.edp == pc.edp && fc.limit == pc.limit && fc.building == pc.building &&
                 fc.model == pc.model
             ? &fc
             : nullptr;
}

// The like-for-like shift of the pounding curve pc, or null where nothing was censored.
const FragilityShift* like_for_like(const FragilityReport& fr, const FragilityCurve& pc) {
  for (const FragilityShift& sh : fr.shifts)
    if (sh.same_analyses && sh.model == pc.model && sh.building == pc.building &&
        sh.edp == pc.edp && sh.limit == pc.limit)
      return &sh;
  return nullptr;
}

}  // namespace

double outside_share(const HazardCurve& h, const LognormalFit& f, double nu, double lo, double hi) {
  if (!f.finite() || !(nu > 0)) return kNaN;
  return std::max(0.0, 1.0 - mean_annual_frequency(h, f.theta, f.beta, lo, hi) / nu);
}

// The fits of pound fragility with its bootstrap at the risk's replicates, seed and confidence,
// every replicate's fits kept; no bands on an IM grid (grid_points 0), which risk does not use.
std::vector<DamageRisk> damage_risks(const CampaignData& c, const HazardCurve& h,
                                     const FragilitySettings& limits, const RiskSettings& s,
                                     double im_lo, double im_hi) {
  FragilitySettings fs = limits;
  fs.bootstrap = s.bootstrap;
  fs.bootstrap.replicates = std::max(0, s.bootstrap.replicates);
  fs.confidence = s.confidence;
  fs.grid_points = 0;
  fs.keep_replicates = true;
  const FragilityReport fr = analyse_fragility(c, fs);
  std::vector<DamageRisk> out;
  for (std::size_t k = 0; k < fr.curves.size(); ++k) {
    const FragilityCurve& pc = fr.curves[k];
    if (!pc.pounding) continue;
    DamageRisk dr;
    dr.model = pc.model;
    dr.building = pc.building;
    dr.edp = pc.edp;
    dr.limit = pc.limit;
    dr.pounding = pc.fit;
    dr.free.status = FitStatus::no_data;
    const FragilityCurve* fc = free_curve(fr, k);
    if (fc) dr.free = fc->fit;
    const FragilityShift* sh = like_for_like(fr, pc);
    dr.same_analyses = sh != nullptr;
    dr.free_same = sh ? sh->free_same : dr.free;
    const DamageRates x = damage_rates(h, dr.pounding, dr.free, sh ? &dr.free_same : nullptr);
    dr.maf_pounding = x.maf_pounding;
    dr.maf_free = x.maf_free;
    dr.ratio = x.ratio;
    dr.maf_pounding_kept = x.maf_pounding_kept;
    dr.probability_pounding = probability_in_years(dr.maf_pounding, s.years);
    dr.probability_free = probability_in_years(dr.maf_free, s.years);
    dr.outside_pounding = outside_share(h, dr.pounding, dr.maf_pounding_kept, im_lo, im_hi);
    dr.outside_free = outside_share(h, dr.free, dr.maf_free, im_lo, im_hi);
    add_bands(h, s, pc.replicates, fc ? fc->replicates : std::vector<LognormalFit>{},
              sh ? &sh->free_same_replicates : nullptr, dr);
    out.push_back(dr);
  }
  return out;
}

// Collapse from the damage limits: nu and P in T years, their ratio, and the collapse margin
// ratio theta / design intensity with a given design (MCE) intensity (FEMA P695, sec. 6.3).
std::vector<CollapseRisk> collapse_risks(const std::vector<DamageRisk>& damage,
                                         const RiskSettings& s, double design_im) {
  std::vector<CollapseRisk> out;
  for (const auto& d : damage) {
    if (d.edp != Edp::collapse) continue;
    CollapseRisk c;
    static_cast<DamageRisk&>(c) = d;
    c.theta_pounding = !d.pounding.finite() ? kNaN
                       : !d.same_analyses
                           ? d.pounding.theta
                           : (d.free.finite() && d.free_same.finite()
                                  ? d.free.theta * d.pounding.theta / d.free_same.theta
                                  : kNaN);
    c.probability_pounding = probability_in_years(d.maf_pounding, s.years);
    c.probability_free = probability_in_years(d.maf_free, s.years);
    c.cmr_pounding = design_im > 0 ? c.theta_pounding / design_im : kNaN;
    c.cmr_free = design_im > 0 && d.free.finite() ? d.free.theta / design_im : kNaN;
    out.push_back(c);
  }
  return out;
}

namespace {

// "drift 0.04 - (building 2, hc-linear alone)": a damage limit in a note.
std::string limit_name(const DamageRisk& dr) {
  char limit[32];
  std::snprintf(limit, sizeof limit, "%g", dr.limit);
  return std::string(to_string(dr.edp)) +
         (dr.edp == Edp::collapse ? "" : " " + std::string(limit) + " " + unit_of(dr.edp)) +
         " (building " + std::to_string(dr.building + 1) +
         (dr.model.empty() ? "" : ", " + dr.model + " alone");
}

}  // namespace

void add_damage_notes(const std::vector<DamageRisk>& damage, std::vector<std::string>& notes) {
  // The limits whose nu comes by more than a quarter from extrapolated intensities.
  std::string outside, partial;
  for (const auto& dr : damage)
    for (double share : {dr.outside_pounding, dr.outside_free})
      if (share > 0.25) {
        outside += (outside.empty() ? "" : ", ") + limit_name(dr) + ")";
        break;
      }
  if (!outside.empty())
    notes.push_back(
        "damage limits whose nu takes more than 25 % from intensities outside the "
        "campaign's (an extrapolated fit; a large beta puts weight on the frequent "
        "weak motions): " +
        outside);
  // The limits whose band rests on fewer than all replicates (as the gap's band; only where
  // the point estimate is finite: elsewhere the table gives the fit's status).
  int replicates = 0;
  for (const auto& dr : damage) {
    const int n = dr.bootstrap_replicates;
    const bool pounding = std::isfinite(dr.maf_pounding) && dr.maf_pounding_band.finite < n;
    const bool free = std::isfinite(dr.maf_free) && dr.maf_free_band.finite < n;
    if (!pounding && !free) continue;
    replicates = n;
    partial += (partial.empty() ? "" : ", ") + limit_name(dr) + ": " +
               (pounding ? std::to_string(dr.maf_pounding_band.finite) + " with pounding" : "") +
               (pounding && free ? ", " : "") +
               (free ? std::to_string(dr.maf_free_band.finite) + " without" : "") + ")";
  }
  if (!partial.empty())
    notes.push_back("damage limits whose band comes from fewer than all " +
                    std::to_string(replicates) +
                    " bootstrap replicates (the others' fits have no finite estimate): " + partial);
}

}  // namespace pound

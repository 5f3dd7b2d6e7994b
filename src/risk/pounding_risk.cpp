#include "risk/pounding_risk.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "campaign/amplification.hpp"
#include "core/error.hpp"
#include "motion/ground_motion.hpp"
#include "risk/damage_risk.hpp"
#include "risk/risk_integral.hpp"
#include "risk/site_displacements.hpp"

namespace pound {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDesignReturnPeriod = 475.0;  // years: 10 % in 50 years (EN 1998-1 2.1)

// The pounding analysis of one pair: the free-run approach of each used sample (the largest
// over the pair's levels) and everything fitted from it.
class PairAnalysis {
 public:
  PairAnalysis(const CampaignData& c, const std::vector<std::size_t>& used,
               const ExceedanceDesign& d, const HazardCurve& h, const RiskSettings& s,
               std::size_t pair)
      : d_(d), h_(h), s_(s) {
    im_lo_ = *std::min_element(d.im.begin(), d.im.end());
    im_hi_ = *std::max_element(d.im.begin(), d.im.end());
    const FloorArray& a = c.approach_free;
    for (std::size_t s2 : used) {
      double m = kNaN;
      for (std::size_t l = 0; l < a.floors; ++l) {
        const double x = a.at(s2, pair, l);
        if (std::isfinite(x) && !(x <= m)) m = x;
      }
      approach_.push_back(m);
      if (std::isfinite(m)) sorted_.push_back(m);
      collapsed_.push_back(c.collapsed(s2, pair, false) || c.collapsed(s2, pair + 1, false));
    }
    std::sort(sorted_.begin(), sorted_.end());
    sorted_.erase(std::unique(sorted_.begin(), sorted_.end()), sorted_.end());
  }

  double largest_approach() const { return sorted_.empty() ? kNaN : sorted_.back(); }

  // Pounding outcomes at gap g: 1 when the approach exceeds it (left out: no approach).
  std::vector<char> outcomes(double g) const {
    std::vector<char> z(approach_.size());
    for (std::size_t k = 0; k < z.size(); ++k)
      z[k] = !std::isfinite(approach_[k]) ? kLeftOut : approach_[k] > g ? 1 : 0;
    return z;
  }

  // Fit, nu and probability at gap g on the analyses `rows` (all when empty).
  GapEstimate estimate(double g, const std::vector<std::size_t>& rows = {}) const {
    GapEstimate e;
    e.gap = g;
    const std::vector<char> z = outcomes(g);
    const auto obs = observations(d_, z, rows);
    for (const auto& o : obs) e.analyses += o.n, e.pounding += o.z;
    e.fit = fit_lognormal(obs);
    e.maf = e.fit.finite() ? mean_annual_frequency(h_, e.fit.theta, e.fit.beta) : kNaN;
    e.probability = probability_in_years(e.maf, s_.years);
    if (rows.empty()) {  // (not needed by the bootstrap)
      e.outside_share = outside_share(h_, e.fit, e.maf, im_lo_, im_hi_);
      for (std::size_t k = 0; k < z.size(); ++k) e.pounding_collapsed += z[k] == 1 && collapsed_[k];
    }
    return e;
  }

  // The smallest gap whose probability is at most the target: the first gap of the grid
  // (probabilities p) that meets it, refined between it and the previous gap with an estimate
  // on the samples' approaches (where the outcomes change) by bisection.
  double gap_for_target(const std::vector<double>& grid, const std::vector<double>& p,
                        const std::vector<std::size_t>& rows, TargetStatus* status) const {
    int first = -1, prev = -1;
    for (int i = 0; i < int(grid.size()); ++i) {
      if (!std::isfinite(p[std::size_t(i)])) continue;
      if (p[std::size_t(i)] <= s_.target_probability) {
        first = i;
        break;
      }
      prev = i;
    }
    bool any = false;
    for (double x : p) any |= std::isfinite(x);
    if (!any) {
      *status = TargetStatus::no_estimate;
      return kNaN;
    }
    if (first < 0) {
      *status = TargetStatus::not_reached;
      return kNaN;
    }
    if (prev < 0) {
      *status = first == 0 ? TargetStatus::found : TargetStatus::at_most;
      return grid[std::size_t(first)];
    }
    *status = TargetStatus::found;
    const double lo = grid[std::size_t(prev)], hi = grid[std::size_t(first)];
    std::vector<double> cand;
    for (double x : sorted_)
      if (x > lo && x < hi) cand.push_back(x);
    cand.push_back(hi);
    std::size_t a = 0, b = cand.size() - 1;  // cand[b] meets the target; search [a, b]
    while (a < b) {
      const std::size_t mid = (a + b) / 2;
      const double q = estimate(cand[mid], rows).probability;
      if (std::isfinite(q) && q <= s_.target_probability)
        b = mid;
      else
        a = mid + 1;
    }
    return cand[b];
  }

 private:
  const ExceedanceDesign& d_;
  const HazardCurve& h_;
  const RiskSettings& s_;
  double im_lo_ = 0.0, im_hi_ = 0.0;  // the campaign's intensities [m/s^2]
  std::vector<double> approach_;      // per used analysis [m]
  std::vector<double> sorted_;        // distinct finite approaches, increasing [m]
  std::vector<char> collapsed_;       // per used analysis: a building of the pair collapsed
};

// Medians of the free-run peak floor displacement [building][floor] per intensity group, and
// the groups' intensities, for the code rules.
struct GroupMedians {
  std::vector<double> im;                              // [m/s^2], increasing
  std::vector<std::vector<std::vector<double>>> disp;  // [group][building][floor] [m]
};

GroupMedians group_medians(const CampaignData& c, const std::vector<std::size_t>& used,
                           const ExceedanceDesign& d) {
  // Groups: the design's stripes, or equal-count IM bins (campaign/amplification.hpp).
  std::vector<int> group(used.size());
  std::vector<double> im;
  if (d.stripes()) {
    for (std::size_t k = 0; k < used.size(); ++k) group[k] = d.stripe[k];
    im = d.levels;
  } else {
    std::vector<long> id(used.size());
    std::vector<char> ok(used.size(), 1);
    std::vector<double> x;
    for (std::size_t k = 0; k < used.size(); ++k) id[k] = long(k), x.push_back(d.im[k]);
    const IntensityGroups g = intensity_groups({}, id, ok, x);
    group = g.of_sample;
    im = g.im;
  }
  const FloorArray& u = c.floor_array("peak_disp_free");
  GroupMedians m;
  std::vector<std::size_t> order(im.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return im[a] < im[b]; });
  for (std::size_t gi : order) {
    std::vector<std::vector<double>> per_b(u.buildings, std::vector<double>(u.floors, kNaN));
    bool any = false;
    for (std::size_t b = 0; b < u.buildings; ++b)
      for (std::size_t f = 0; f < u.floors; ++f) {
        std::vector<double> v;
        for (std::size_t k = 0; k < used.size(); ++k)
          if (group[k] == int(gi) && std::isfinite(u.at(used[k], b, f)))
            v.push_back(u.at(used[k], b, f));
        if (!v.empty()) {
          per_b[b][f] = summarize(v).median;
          any = true;
        }
      }
    if (!any) continue;
    m.im.push_back(im[gi]);
    m.disp.push_back(per_b);
  }
  return m;
}

// The median at intensity x, interpolated linearly in ln(median) against ln(IM) between the
// groups either side; NaN outside their range.
double median_at(const GroupMedians& m, double x, std::size_t b, std::size_t f) {
  for (std::size_t k = 0; k < m.im.size(); ++k) {
    if (std::abs(x - m.im[k]) <= 1e-9 * m.im[k]) return m.disp[k][b][f];
    if (k + 1 < m.im.size() && x > m.im[k] && x < m.im[k + 1]) {
      const double w = std::log(x / m.im[k]) / std::log(m.im[k + 1] / m.im[k]);
      return std::exp((1 - w) * std::log(m.disp[k][b][f]) + w * std::log(m.disp[k + 1][b][f]));
    }
  }
  return kNaN;
}

}  // namespace

const char* to_string(TargetStatus s) {
  switch (s) {
    case TargetStatus::found:
      return "found";
    case TargetStatus::at_most:
      return "at_most";
    case TargetStatus::not_reached:
      return "not_reached";
    case TargetStatus::no_estimate:
      return "no_estimate";
  }
  return "?";
}

std::vector<BuildingMode> study_first_modes(const CampaignData& c) {
  if (c.first_periods.size() != c.buildings || c.damping_ratios.size() != c.buildings)
    throw InputError(c.path +
                     ": no root attributes first_periods_s and damping_ratios (one per "
                     "building); the file was written by a pound without them: run the "
                     "campaign again with this version to get them");
  std::vector<BuildingMode> modes;
  for (std::size_t b = 0; b < c.buildings; ++b)
    modes.push_back({c.first_periods[b], c.damping_ratios[b]});
  return modes;
}

void check_hazard_measure(const CampaignData& c, const HazardCurve& h) {
  const std::string want = c.intensity_measure == "sa" ? "sa" : "pga";
  if (h.measure != want)
    throw InputError(h.source + ": the hazard curve is of " + h.measure +
                     (h.measure == "sa" ? "(" + std::to_string(h.period_s) + ")" : "") +
                     ", the campaign's intensity measure is " +
                     (want == "sa" ? "Sa(T1) at " + std::to_string(c.im_period) + " s" : "PGA") +
                     "; give a hazard curve of " +
                     (want == "sa" ? "sa(" + std::to_string(c.im_period) + ") [g]" : "pga [g]"));
  if (want == "sa" && std::abs(h.period_s - c.im_period) > 0.01 * c.im_period)
    throw InputError(h.source + ": the hazard curve is of sa(" + std::to_string(h.period_s) +
                     "), the campaign's Sa(T1) is at " + std::to_string(c.im_period) +
                     " s; valid: a period within 1 %");
}

namespace {

void check_risk_inputs(const CampaignData& c, const RiskSettings& s) {
  if (!c.has_approach())
    throw InputError(c.path +
                     ": no dataset /response/approach_free; the file was written by a pound "
                     "without it: run the campaign again with this version to get it");
  if (!(s.years > 0 && std::isfinite(s.years)))
    throw InputError("years " + std::to_string(s.years) + ": valid: a number of years > 0");
  if (!(s.target_probability > 0 && s.target_probability < 1))
    throw InputError("target probability " + std::to_string(s.target_probability) +
                     ": valid: a probability in (0, 1)");
  for (std::size_t i = 0; i < s.gaps.size(); ++i)
    if (!(s.gaps[i] >= 0 && std::isfinite(s.gaps[i])) || (i > 0 && !(s.gaps[i] > s.gaps[i - 1])))
      throw InputError("gaps: valid: increasing gaps >= 0 in m");
}

// The design intensity of the code rules and the median free-run displacements around it.
struct DesignPoint {
  GroupMedians medians;
  double im = 0.0;        ///< [m/s^2]
  bool in_range = false;  ///< inside the groups' intensities
};

// The gaps of a pair's table: the given ones, or gap_points from 0 to its largest approach.
std::vector<double> gap_grid(const PairAnalysis& pa, const RiskSettings& s) {
  std::vector<double> grid = s.gaps;
  if (!grid.empty()) return grid;
  const double top = pa.largest_approach();
  const int n = std::max(2, s.gap_points);
  for (int i = 0; i < n; ++i)
    grid.push_back(std::isfinite(top) ? top * double(i) / double(n - 1) : 0.0);
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

// Bootstrap: every replicate refits every gap and searches again; the bands go into pr.
void bootstrap_bands(const PairAnalysis& pa, const std::vector<double>& grid,
                     const BootstrapResampler& resampler, const RiskSettings& s, PairRisk& pr) {
  std::vector<std::vector<double>> rep_prob(grid.size());
  std::vector<double> rep_gap;
  std::vector<std::size_t> rows;
  for (int rep = 0; rep < s.bootstrap.replicates; ++rep) {
    resampler.rows(rep, rows);
    std::vector<double> q;
    for (std::size_t i = 0; i < grid.size(); ++i) {
      q.push_back(pa.estimate(grid[i], rows).probability);
      rep_prob[i].push_back(q.back());
    }
    TargetStatus st;
    rep_gap.push_back(pa.gap_for_target(grid, q, rows, &st));
  }
  pr.bootstrap_replicates = s.bootstrap.replicates;
  for (std::size_t i = 0; i < grid.size(); ++i)
    pr.grid[i].probability_band = percentile_interval(rep_prob[i], s.confidence);
  pr.gap_band = percentile_interval(rep_gap, s.confidence);
}

// Code rules at the design intensity, from the median free-run peak displacements at each of
// the pair's sites (sites: null where the study's floors are unknown).
void code_rules(const PairAnalysis& pa, const CampaignData& c, const DesignPoint& design,
                const std::vector<BuildingMode>& modes, const std::vector<SiteGeometry>* sites,
                PairRisk& pr) {
  const std::size_t bl = pr.pair, br = pr.pair + 1;
  if (!design.in_range) {
    pr.rules_note = "the design intensity " + std::to_string(design.im / kGravity) +
                    " g lies outside the campaign's intensities";
    return;
  }
  if (modes.size() <= br) {
    pr.rules_note = "the study's buildings could not be read";
    return;
  }
  pr.rho =
      cqc_correlation(modes[bl].period_s, modes[bl].damping, modes[br].period_s, modes[br].damping);
  const FloorArray& u = c.floor_array("peak_disp_free");
  std::vector<double> floors_l, floors_r;  // the median at each floor
  for (std::size_t f = 0; f < u.floors; ++f) {
    floors_l.push_back(median_at(design.medians, design.im, bl, f));
    floors_r.push_back(median_at(design.medians, design.im, br, f));
  }
  // EN 1998-1 4.4.2.7: the displacements at the level of each potential contact (issue 36);
  // without the study's floors, floor l against floor l as before.
  pr.ec8_case = sites ? ec8_case(*sites) : Ec8Case::floors_unknown;
  for (const SiteGeometry& g :
       sites ? *sites : same_index_sites(std::min(c.approach_free.floors, u.floors))) {
    const SiteDisplacements d = site_displacements(g, floors_l, floors_r);
    if (!std::isfinite(d.left) || !std::isfinite(d.right)) break;  // the lower building's roof
    pr.median_left.push_back(d.left);
    pr.median_right.push_back(d.right);
  }
  pr.rules_computed = !pr.median_left.empty();
  if (!pr.rules_computed) {
    pr.rules_note = "no median free-run displacements at that intensity";
    return;
  }
  for (const SeparationRule rule : kSeparationRules) {
    CodeRuleResult cr;
    cr.rule = rule;
    cr.gap = -1.0;
    for (std::size_t l = 0; l < pr.median_left.size(); ++l) {
      const double g =
          separation_gap(rule, pr.median_left[l], pr.median_right[l], pr.rho, pr.ec8_case);
      if (g > cr.gap) cr.gap = g, cr.level = int(l + 1);
    }
    cr.estimate = pa.estimate(cr.gap);
    pr.rules.push_back(cr);
  }
}

// Pair p: the probability of pounding at every gap of its grid with bootstrap bands, the gap
// for the target, and the code rules.
PairRisk analyse_pair(const PairAnalysis& pa, std::size_t p, const CampaignData& c,
                      const ExceedanceDesign& d, const RiskSettings& s,
                      const BootstrapResampler& resampler, const DesignPoint& design,
                      const std::vector<BuildingMode>& modes, const PairSites& sites) {
  PairRisk pr;
  pr.pair = p;
  const std::vector<double> grid = gap_grid(pa, s);
  std::vector<double> prob;
  for (double g : grid) {
    pr.grid.push_back(pa.estimate(g));
    pr.grid.back().observed = observed_fractions(d, pa.outcomes(g));
    prob.push_back(pr.grid.back().probability);
  }
  pr.gap_for_target = pa.gap_for_target(grid, prob, {}, &pr.target_status);
  bootstrap_bands(pa, grid, resampler, s, pr);
  code_rules(pa, c, design, modes, p < sites.size() ? &sites[p] : nullptr, pr);
  return pr;
}

// One pair's notes on what could not be estimated.
void add_pair_notes(const PairRisk& pr, const PairAnalysis& pa, std::vector<std::string>& notes) {
  const std::string pair = "pair " + std::to_string(pr.pair + 1) + ": ";
  long finite = 0;
  for (const auto& e : pr.grid) finite += e.fit.finite();
  if (finite < long(pr.grid.size()))
    notes.push_back(pair + std::to_string(pr.grid.size() - std::size_t(finite)) + " of " +
                    std::to_string(pr.grid.size()) +
                    " gaps have no finite pounding fragility (status in the table and "
                    "risk_gaps.csv): there nu and the probability are not estimated");
  if (pr.target_status == TargetStatus::no_estimate)
    notes.push_back(pair +
                    "the gap for the target is not estimated: no gap has a finite "
                    "pounding fragility");
  else if (pr.target_status == TargetStatus::not_reached)
    notes.push_back(pair +
                    "the gap for the target is not estimated: no gap with a finite "
                    "fit has a probability at or below the target (the larger gaps are "
                    "closed by too few samples to fit)");
  else if (pr.target_status == TargetStatus::at_most)
    notes.push_back(pair +
                    "the smallest gap with a finite fit already meets the target: the "
                    "gap for the target is at most that");
  if (pr.gap_band.finite < pr.bootstrap_replicates)
    notes.push_back(pair + "the band of the gap comes from the " +
                    std::to_string(pr.gap_band.finite) + " of " +
                    std::to_string(pr.bootstrap_replicates) +
                    " bootstrap replicates in which the gap could be estimated");
  if (!pr.rules_computed)
    notes.push_back(pair + "code rules not computed: " + pr.rules_note);
  else if (pr.ec8_case == Ec8Case::floors_unknown)
    notes.push_back(pair +
                    "the study's floor elevations could not be read from the campaign file: "
                    "the code rules pair floor l with floor l, and ec8 takes no reduction");
  if (std::isfinite(pr.gap_for_target)) {
    const GapEstimate at = pa.estimate(pr.gap_for_target);
    if (at.pounding > 0 && 2 * at.pounding_collapsed > at.pounding)
      notes.push_back(pair + std::to_string(at.pounding_collapsed) + " of the " +
                      std::to_string(at.pounding) +
                      " samples that pound at the gap for the target are ones in which a "
                      "building of the pair collapsed: the gap is set by collapsing sways, which "
                      "no gap prevents (docs/risk.md, \"Pounding and collapse\")");
    const double share = at.outside_share;
    if (share > 0.1)
      notes.push_back(pair + std::to_string(int(std::lround(100 * share))) +
                      " % of nu at the gap for the target comes from intensities outside the "
                      "campaign's, where the fitted fragility is extrapolated");
  }
}

}  // namespace

RiskReport analyse_risk(const CampaignData& c, const HazardCurve& h, const RiskSettings& s,
                        const std::vector<BuildingMode>& modes, const PairSites& sites,
                        const FragilitySettings& limits) {
  check_risk_inputs(c, s);
  RiskReport r;
  r.samples = c.samples;
  for (int st : c.status) r.failed += st != 0;
  std::vector<std::size_t> used;
  const ExceedanceDesign d = exceedance_design(c, &used);
  r.used = used.size();
  r.stripes = d.stripes();
  if (used.empty()) throw InputError(c.path + ": no successful sample to fit");

  // Design intensity of the code rules.
  r.design_im_given = s.design_im > 0;
  r.design_im = r.design_im_given ? s.design_im : h.im_at_rate(1.0 / kDesignReturnPeriod);
  DesignPoint design;
  design.medians = group_medians(c, used, d);
  design.im = r.design_im;
  const std::vector<double>& group_im = design.medians.im;
  r.groups = group_im.size();
  design.in_range = !group_im.empty() && r.design_im >= group_im.front() * (1 - 1e-9) &&
                    r.design_im <= group_im.back() * (1 + 1e-9);
  if (r.design_im_given && !design.in_range)
    throw InputError("design-im " + std::to_string(r.design_im / kGravity) +
                     " g: outside the campaign's intensities " +
                     std::to_string(group_im.empty() ? 0.0 : group_im.front() / kGravity) + " to " +
                     std::to_string(group_im.empty() ? 0.0 : group_im.back() / kGravity) +
                     " g; valid: an intensity inside them");

  const double im_lo = *std::min_element(d.im.begin(), d.im.end());
  const double im_hi = *std::max_element(d.im.begin(), d.im.end());
  const BootstrapResampler resampler(d, s.bootstrap);
  const std::size_t npairs = c.approach_free.buildings;
  for (std::size_t p = 0; p < npairs; ++p)
    r.pairs.push_back(analyse_pair(PairAnalysis(c, used, d, h, s, p), p, c, d, s, resampler, design,
                                   modes, sites));
  r.damage = damage_risks(c, h, limits, s, im_lo, im_hi);
  r.collapse = collapse_risks(r.damage, s, r.design_im_given ? r.design_im : 0.0);

  // What could not be estimated.
  const double per_group = double(r.used) / double(std::max<std::size_t>(1, r.groups));
  if (per_group < 20)
    r.notes.push_back("only " + std::to_string(r.used) + " successful samples in " +
                      std::to_string(r.groups) + (r.stripes ? " stripes" : " intensity bins") +
                      " (about " + std::to_string(int(std::lround(per_group))) +
                      " each): most fits have no finite estimate and the bands are wide; run "
                      "the campaign with more samples");
  for (const auto& pr : r.pairs)
    add_pair_notes(pr, PairAnalysis(c, used, d, h, s, pr.pair), r.notes);
  add_damage_notes(r.damage, r.notes);
  return r;
}

}  // namespace pound

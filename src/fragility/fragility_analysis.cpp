#include "fragility/fragility_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "core/error.hpp"
#include "fragility/rank_correlation.hpp"
#include "io/ini.hpp"
#include "io/options.hpp"
#include "sampling/normal.hpp"

namespace pound {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// The EDPs: name, unit and the per-floor datasets they come from (with the suffix _pounding
// or _free; "" for the force, from /response/peak_force).
struct EdpInfo {
  Edp edp;
  const char* name;
  const char* unit;
  const char* dataset;
};
constexpr EdpInfo kEdps[] = {
    {Edp::collapse, "collapse", "-", ""},
    {Edp::drift, "drift", "-", "peak_drift_ratio"},
    {Edp::disp, "disp", "m", "peak_disp"},
    {Edp::accel, "accel", "m/s^2", "peak_accel"},
    {Edp::force, "force", "N", ""},
    {Edp::residual_drift, "residual_drift", "-", "residual_drift"},
    {Edp::ductility, "ductility", "-", "ductility"},
    {Edp::column_shear, "column_shear", "-", ""},
};

const EdpInfo& info(Edp e) {
  for (const auto& i : kEdps)
    if (i.edp == e) return i;
  throw std::logic_error("unknown EDP");
}

}  // namespace

FragilitySettings study_fragility_limits(const CampaignData& c) {
  FragilitySettings s;
  std::vector<IniEntry> study;
  try {
    study = parse_ini(c.study, c.path + " (stored study)");
  } catch (const InputError&) {
    return s;  // an unreadable stored study only loses its limits
  }
  const std::pair<const char*, std::vector<double>*> lists[] = {
      {"fragility.drift_limits", &s.drift_limits},
      {"fragility.disp_limits", &s.disp_limits},
      {"fragility.accel_limits", &s.accel_limits},
      {"fragility.force_limits", &s.force_limits},
      {"fragility.residual_drift_limits", &s.residual_drift_limits},
      {"fragility.ductility_limits", &s.ductility_limits}};
  for (const auto& e : study)
    for (const auto& [key, list] : lists)
      if (e.key == key) {
        *list = parse_number_list(e.value,
                                  e.file + ":" + std::to_string(e.line) + ": key '" + e.key + "'");
        for (double x : *list)
          if (!(x > 0))
            throw InputError(e.file + ": key '" + e.key + "': valid: limits > 0 in SI units");
      }
  return s;
}

// Analyses that succeeded, with their stripe (nearest level within 1e-5 relative: the file
// stores the levels as text with six decimals, the samples' IM in full precision).
ExceedanceDesign exceedance_design(const CampaignData& c, std::vector<std::size_t>* used) {
  ExceedanceDesign d;
  std::vector<double> sum(c.levels.size(), 0.0);
  std::vector<long> count(c.levels.size(), 0);
  for (std::size_t s = 0; s < c.samples; ++s) {
    if (c.status[s] != 0 || !(c.im[s] > 0)) continue;
    int stripe = -1;
    for (std::size_t l = 0; l < c.levels.size(); ++l)
      if (std::abs(c.im[s] - c.levels[l]) <= 1e-5 * c.levels[l]) stripe = int(l);
    if (!c.levels.empty() && stripe < 0)
      throw InputError(c.path + ": sample " + std::to_string(s) + " has IM " +
                       std::to_string(c.im[s]) + " m/s^2, on none of the stripes im_levels_mps2");
    used->push_back(s);
    d.im.push_back(c.im[s]);
    d.stripe.push_back(stripe);
    if (stripe >= 0) sum[std::size_t(stripe)] += c.im[s], ++count[std::size_t(stripe)];
  }
  for (std::size_t l = 0; l < c.levels.size(); ++l)
    d.levels.push_back(count[l] ? sum[l] / double(count[l]) : c.levels[l]);
  return d;
}

// Observed fractions for the plots: the stripes, or about ten equal-count IM bins (geometric
// mean IM of each bin) when the intensity is continuous. With `bins_of` (the pounding curve's
// outcomes, for its free curve) the bins are those of its analyses, each from its smallest IM
// up to the next bin's, so that observations.csv pairs the two curves bin by bin.
std::vector<Observation> observed_fractions(const ExceedanceDesign& d,
                                            const std::vector<char>& exceed,
                                            const std::vector<char>* bins_of) {
  if (d.stripes()) return observations(d, exceed);
  if (bins_of) {
    const std::vector<Observation> ref = observed_fractions(d, *bins_of);
    std::vector<double> first;  // the smallest IM of each reference bin after the first
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < d.im.size(); ++i)
      if ((*bins_of)[i] != kLeftOut) order.push_back(i);
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return d.im[a] < d.im[b]; });
    const std::size_t bins = ref.size();
    if (bins == 0) return {};  // the reference curve kept no analysis
    for (std::size_t k = 1; k < bins; ++k) first.push_back(d.im[order[k * order.size() / bins]]);
    std::vector<Observation> out(bins);
    std::vector<double> log_sum(bins, 0.0);
    for (std::size_t i = 0; i < d.im.size(); ++i) {
      if (exceed[i] == kLeftOut) continue;
      const std::size_t k =
          std::size_t(std::upper_bound(first.begin(), first.end(), d.im[i]) - first.begin());
      ++out[k].n;
      out[k].z += exceed[i] ? 1 : 0;
      log_sum[k] += std::log(d.im[i]);
    }
    for (std::size_t k = 0; k < bins; ++k)
      out[k].im = out[k].n ? std::exp(log_sum[k] / double(out[k].n)) : ref[k].im;
    return out;
  }
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < d.im.size(); ++i)
    if (exceed[i] != kLeftOut) order.push_back(i);
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return d.im[a] < d.im[b]; });
  const std::size_t bins = std::max<std::size_t>(1, std::min<std::size_t>(10, order.size() / 20));
  std::vector<Observation> out;
  for (std::size_t k = 0; k < bins; ++k) {
    const std::size_t lo = k * order.size() / bins, hi = (k + 1) * order.size() / bins;
    Observation o;
    double log_sum = 0.0;
    for (std::size_t i = lo; i < hi; ++i) {
      log_sum += std::log(d.im[order[i]]);
      ++o.n;
      o.z += exceed[order[i]] ? 1 : 0;
    }
    if (o.n == 0) continue;
    o.im = std::exp(log_sum / double(o.n));
    out.push_back(o);
  }
  return out;
}

namespace {

void rank_sensitivity(const CampaignData& c, const std::vector<std::size_t>& used,
                      FragilityReport* r) {
  // The candidate columns: numeric sampled parameters and the intensity measure.
  std::vector<std::string> names;
  std::vector<std::vector<double>> all;
  for (const auto& p : c.parameters) {
    names.push_back(p.key);
    std::vector<double> v;
    for (std::size_t s : used) v.push_back(p.values[s]);
    all.push_back(v);
  }
  names.push_back("im");
  {
    std::vector<double> v;
    for (std::size_t s : used) v.push_back(c.im[s]);
    all.push_back(v);
  }
  for (std::size_t b = 0; b < c.buildings; ++b)
    for (const Edp e : {Edp::disp, Edp::drift}) {
      if (!c.has(dataset_of(e, true)) || !c.has(dataset_of(e, false))) continue;
      // Amplification = pounding / free, on the samples where both are finite and free > 0 and
      // the pounding run was not stopped by another building's collapse (CampaignData::
      // censored: its pounding peak would cover only part of the record).
      std::vector<std::size_t> rows;
      std::vector<double> y;
      for (std::size_t k = 0; k < used.size(); ++k) {
        if (c.censored(used[k], b)) continue;
        const double p = edp_value(c, e, true, used[k], b), f = edp_value(c, e, false, used[k], b);
        if (std::isfinite(p) && std::isfinite(f) && f > 0) rows.push_back(k), y.push_back(p / f);
      }
      // Keep the columns that vary and are finite on those rows.
      std::vector<std::vector<double>> cols;
      std::vector<std::string> keep;
      for (std::size_t j = 0; j < all.size(); ++j) {
        std::vector<double> v;
        bool ok = true;
        for (std::size_t k : rows) ok &= std::isfinite(all[j][k]), v.push_back(all[j][k]);
        if (!ok || v.empty() ||
            *std::min_element(v.begin(), v.end()) == *std::max_element(v.begin(), v.end()))
          continue;
        cols.push_back(v);
        keep.push_back(names[j]);
      }
      const std::size_t first = r->sensitivity.size();
      for (std::size_t j = 0; j < cols.size(); ++j)
        r->sensitivity.push_back({b, std::string(to_string(e)) + "_amplification", keep[j],
                                  spearman(cols[j], y), partial_rank_correlation(cols, y, j),
                                  y.size()});
      std::stable_sort(r->sensitivity.begin() + long(first), r->sensitivity.end(),
                       [](const SensitivityRow& a, const SensitivityRow& b2) {
                         const double x = std::isfinite(a.prcc) ? std::abs(a.prcc) : -1;
                         const double y2 = std::isfinite(b2.prcc) ? std::abs(b2.prcc) : -1;
                         return x > y2;
                       });
    }
}

}  // namespace

const char* to_string(Edp e) {
  return info(e).name;
}

const char* unit_of(Edp e) {
  return info(e).unit;
}

std::string dataset_of(Edp e, bool pounding) {
  const std::string base = info(e).dataset;
  return base.empty() ? base : base + (pounding ? "_pounding" : "_free");
}

double edp_value(const CampaignData& c, Edp e, bool pounding, std::size_t s, std::size_t b) {
  if (e == Edp::collapse) return c.collapsed(s, b, pounding) ? 1.0 : 0.0;
  if (e == Edp::column_shear) {
    const auto it = c.building_arrays.find(pounding ? "column_shear_ratio_pounding"
                                                    : "column_shear_ratio_free");
    return it == c.building_arrays.end() ? kNan : it->second[s * c.buildings + b];
  }
  if (e != Edp::force) return c.floor_array(dataset_of(e, pounding)).max_over_floors(s, b);
  if (!pounding) return 0.0;
  double m = kNan;
  const std::size_t pairs = c.peak_force.buildings;  // [samples][pairs][levels]
  for (std::size_t p = 0; p < pairs; ++p)
    if (p == b || p + 1 == b) {
      const double f = c.peak_force.max_over_floors(s, p);
      if (std::isfinite(f) && !(f <= m)) m = f;
    }
  return std::isfinite(m) ? m : 0.0;  // a building without a neighbour: no force
}

namespace {

// One set of analyses fitted together: all of them, or one contact model's.
struct AnalysisSet {
  std::string model;              // "" for all
  std::vector<std::size_t> used;  // their rows
  ExceedanceDesign d;
};

// The curves' EDPs and limits, collapse first (the limit state that decides life safety).
std::vector<std::pair<Edp, std::vector<double>>> curve_limits(const CampaignData& c,
                                                              const FragilitySettings& s) {
  std::vector<std::pair<Edp, std::vector<double>>> out;
  if (s.collapse && c.has_collapse()) out.push_back({Edp::collapse, {1.0}});
  // Column shear (issue 36) where the study gives column_shear_strength and a slab strikes a
  // column: one limit, a demand of 1 times the strength.
  const auto shear = c.building_arrays.find("column_shear_ratio_pounding");
  if (shear != c.building_arrays.end() && std::any_of(shear->second.begin(), shear->second.end(),
                                                      [](double v) { return std::isfinite(v); }))
    out.push_back({Edp::column_shear, {1.0}});
  out.push_back({Edp::drift, s.drift_limits});
  out.push_back({Edp::disp, s.disp_limits});
  out.push_back({Edp::accel, s.accel_limits});
  out.push_back({Edp::force, s.force_limits});
  out.push_back({Edp::residual_drift, s.residual_drift_limits});
  out.push_back({Edp::ductility, s.ductility_limits});
  return out;
}

// Outcome of analysis `row` for a curve: 1 exceeded (a collapsed building exceeds every limit),
// 0 not, kLeftOut when the EDP is not finite, or in the pounding run when it stopped at another
// building's collapse while this one stood (censored: its outcome over the rest of the record
// is unknown). The pounding curves are thus those of the records in which no other building
// collapsed first; an exceedance before the stop is left out with the rest, since keeping the
// known exceedances and not the unknown ones would select the censored analyses on this
// building's own outcome (and the shift compares the free runs of the same analyses).
char outcome(const CampaignData& c, Edp edp, double limit, bool pounding, std::size_t row,
             std::size_t b) {
  if (c.collapsed(row, b, pounding)) return 1;
  if (pounding && c.censored(row, b)) return kLeftOut;
  const double v = edp_value(c, edp, pounding, row, b);
  if (!std::isfinite(v)) return kLeftOut;
  if (edp == Edp::column_shear) return v >= limit ? 1 : 0;  // a ratio of 1 or more fails
  return edp != Edp::collapse && v > limit ? 1 : 0;
}

// A free curve fitted again on the analyses of its pounding curve, when another building's
// collapse censored some of those (FragilityShift::same_analyses).
struct PairedFree {
  std::size_t pounding = 0;  // index of the pounding curve in the report
  LognormalFit fit;
  std::vector<char> z;
};

// The curves of one set (without bands), appended to r, their outcomes to `outcomes`; the free
// curves fitted on their pounding curve's analyses to `paired`.
void fit_set(const CampaignData& c, const FragilitySettings& s, const AnalysisSet& set,
             FragilityReport& r, std::vector<std::vector<char>>& outcomes,
             std::vector<PairedFree>& paired) {
  for (std::size_t b = 0; b < c.buildings; ++b)
    for (const auto& [edp, limits] : curve_limits(c, s))
      for (double limit : limits) {
        if (!(limit > 0))
          throw InputError(std::string(to_string(edp)) + " limit " + std::to_string(limit) +
                           ": limits must be > 0");
        for (const bool pounding : {true, false}) {
          if (edp == Edp::force && !pounding) continue;  // no force without pounding
          FragilityCurve fc;
          fc.model = set.model;
          fc.building = b;
          fc.edp = edp;
          fc.limit = limit;
          fc.pounding = pounding;
          std::vector<char> z(set.used.size());
          for (std::size_t k = 0; k < set.used.size(); ++k) {
            z[k] = outcome(c, edp, limit, pounding, set.used[k], b);
            fc.left_out += z[k] == kLeftOut;
            fc.censored += z[k] == kLeftOut && pounding && c.censored(set.used[k], b);
          }
          fc.fit = fit_lognormal(observations(set.d, z));
          // A free curve's bins are its pounding curve's (pushed just before it).
          fc.observed = observed_fractions(set.d, z, pounding ? nullptr : &outcomes.back());
          r.curves.push_back(fc);
          if (!pounding && r.curves.size() >= 2 && r.curves[r.curves.size() - 2].censored > 0) {
            // The pounding curve just before: its censored analyses left out here too.
            PairedFree pf{r.curves.size() - 2, {}, z};
            for (std::size_t k = 0; k < set.used.size(); ++k)
              if (outcomes.back()[k] == kLeftOut && c.censored(set.used[k], b)) pf.z[k] = kLeftOut;
            pf.fit = fit_lognormal(observations(set.d, pf.z));
            paired.push_back(std::move(pf));
          }
          outcomes.push_back(z);
        }
      }
}

// Bands of the curves [first, first + n) from their bootstrap fits reps[0, n), and their
// shifts; reps[n + i] are those of paired[i].
void add_bands_and_shifts(const FragilitySettings& s, std::size_t first,
                          const std::vector<std::vector<LognormalFit>>& reps,
                          const std::vector<PairedFree>& paired, FragilityReport& r) {
  const std::size_t n = reps.size() - paired.size();
  const double zq = normal_quantile(0.5 * (1.0 + s.confidence));
  for (std::size_t j = 0; j < n; ++j) {
    FragilityCurve& fc = r.curves[first + j];
    std::vector<double> th, be;
    for (const auto& f : reps[j]) {
      th.push_back(f.finite() ? f.theta : kNan);
      be.push_back(f.finite() ? f.beta : kNan);
    }
    fc.theta_ci = percentile_interval(th, s.confidence);
    fc.beta_ci = percentile_interval(be, s.confidence);
    if (fc.fit.finite()) {
      const double sl = std::sqrt(fc.fit.var_ln_theta), sb = std::sqrt(fc.fit.var_beta);
      fc.theta_asym_lo = fc.fit.theta * std::exp(-zq * sl);
      fc.theta_asym_hi = fc.fit.theta * std::exp(zq * sl);
      fc.beta_asym_lo = fc.fit.beta - zq * sb;
      fc.beta_asym_hi = fc.fit.beta + zq * sb;
    } else {
      fc.theta_asym_lo = fc.theta_asym_hi = fc.beta_asym_lo = fc.beta_asym_hi = kNan;
    }
    for (double x : r.grid) {
      std::vector<double> p;
      for (const auto& f : reps[j]) p.push_back(f.probability(x));
      const Interval iv = percentile_interval(p, s.confidence);
      fc.band_lo.push_back(iv.lo);
      fc.band_hi.push_back(iv.hi);
    }
    if (s.keep_replicates) fc.replicates = reps[j];
  }
  // The shift: curves come in (pounding, free) pairs except force.
  for (std::size_t j = 0; j + 1 < n; ++j) {
    const FragilityCurve &p = r.curves[first + j], &f = r.curves[first + j + 1];
    if (!p.pounding || f.pounding || p.edp != f.edp || p.limit != f.limit ||
        p.building != f.building)
      continue;
    FragilityShift sh;
    sh.model = p.model;
    sh.building = p.building;
    sh.edp = p.edp;
    sh.limit = p.limit;
    sh.ratio = kNan;
    const LognormalFit* free_fit = &f.fit;
    const std::vector<LognormalFit>* free_reps = &reps[j + 1];
    for (std::size_t i = 0; i < paired.size(); ++i)
      if (paired[i].pounding == first + j) {
        free_fit = &paired[i].fit;
        free_reps = &reps[n + i];
        sh.same_analyses = true;
      }
    sh.free_same = *free_fit;
    sh.theta_pounding = p.fit.finite() ? p.fit.theta : kNan;
    sh.theta_free = free_fit->finite() ? free_fit->theta : kNan;
    if (p.fit.finite() && free_fit->finite()) sh.ratio = p.fit.theta / free_fit->theta;
    std::vector<double> ratio;
    for (std::size_t i = 0; i < reps[j].size(); ++i)
      ratio.push_back(reps[j][i].finite() && (*free_reps)[i].finite()
                          ? reps[j][i].theta / (*free_reps)[i].theta
                          : kNan);
    sh.ci = percentile_interval(ratio, s.confidence);
    if (s.keep_replicates) sh.free_same_replicates = *free_reps;
    r.shifts.push_back(sh);
  }
}

// The pooled set and, where the study samples the contact model, each model's.
std::vector<AnalysisSet> analysis_sets(const CampaignData& c, const FragilitySettings& s,
                                       const std::vector<std::size_t>& used,
                                       const ExceedanceDesign& d) {
  std::vector<AnalysisSet> sets{{"", used, d}};
  const std::vector<std::string> models = c.models();
  if (!s.per_model || models.size() < 2) return sets;
  for (const auto& m : models) {
    AnalysisSet set{m, {}, {}};
    set.d.levels = d.levels;
    for (std::size_t k = 0; k < used.size(); ++k)
      if (c.model[used[k]] == m) {
        set.used.push_back(used[k]);
        set.d.im.push_back(d.im[k]);
        set.d.stripe.push_back(d.stripe[k]);
      }
    if (!set.used.empty()) sets.push_back(std::move(set));
  }
  return sets;
}

}  // namespace

FragilityReport analyse_fragility(const CampaignData& c, const FragilitySettings& s) {
  FragilityReport r;
  r.samples = c.samples;
  std::vector<std::size_t> used;
  const ExceedanceDesign d = exceedance_design(c, &used);
  r.used = used.size();
  for (int st : c.status) r.failed += st != 0;
  r.stripes = d.stripes();
  r.collapse = s.collapse && c.has_collapse();
  if (used.empty()) throw InputError(c.path + ": no successful sample to fit");
  // A file without an EDP's datasets (written before they existed) is an error only when
  // that EDP's curves are asked for.
  for (const auto& [edp, limits] : curve_limits(c, s))
    if (!limits.empty() && edp != Edp::force && edp != Edp::collapse && edp != Edp::column_shear)
      for (const bool pounding : {true, false}) c.floor_array(dataset_of(edp, pounding));

  // IM grid of the bands: log-spaced over [min / 2, 2 max] of the analysed intensities.
  const double lo = *std::min_element(d.im.begin(), d.im.end()) / 2;
  const double hi = *std::max_element(d.im.begin(), d.im.end()) * 2;
  for (std::size_t i = 0; i < s.grid_points; ++i)
    r.grid.push_back(
        lo * std::pow(hi / lo, double(i) / double(std::max<std::size_t>(1, s.grid_points - 1))));

  for (const AnalysisSet& set : analysis_sets(c, s, used, d)) {
    if (!set.model.empty()) r.models.push_back(set.model);
    std::vector<std::vector<char>> outcomes;
    std::vector<PairedFree> paired;
    const std::size_t first = r.curves.size();
    fit_set(c, s, set, r, outcomes, paired);
    for (const auto& pf : paired) outcomes.push_back(pf.z);
    add_bands_and_shifts(s, first, bootstrap_fits(set.d, outcomes, s.bootstrap), paired, r);
  }
  rank_sensitivity(c, used, &r);
  r.unranked = c.text_parameters;
  return r;
}

}  // namespace pound

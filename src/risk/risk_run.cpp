#include "risk/risk_run.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fragility/fragility_run.hpp"
#include "io/json.hpp"
#include "io/output_folder.hpp"
#include "motion/ground_motion.hpp"
#include "risk/risk_files.hpp"
#include "risk/study_sites.hpp"

namespace pound {

const char* const kRiskSummary =
    "Pounding risk at every gap from a campaign and a site's hazard curve: mean annual "
    "frequency, probability in T years, the gap for a target, code rules, damage limits.";

std::vector<OptionSpec> risk_option_specs() {
  std::vector<OptionSpec> s = {
      {"input", "", "", "campaign result file (HDF5) of 'pound campaign' or 'pound merge'"},
      {"hazard", "", "",
       "hazard curve CSV: header 'pga [g], annual_rate [1/yr]' (or sa(T), m/s2), then points"},
      {"gaps", "m", "",
       "gaps to evaluate, increasing, >= 0 (default: 40 from 0 to the largest "
       "free-run approach of the pair)"},
      {"years", "yr", "50", "exposure time T of the probabilities 1 - exp(-nu T)"},
      {"target-probability", "-", "0.02",
       "probability of pounding in T years that the gap for the target may not exceed, in (0, 1)"},
      {"design-im", "g", "",
       "intensity of the code rules (default: the hazard's 475-year intensity, 10 % in 50 years)"},
      {"out", "", "", "output folder (default: RUN-risk/ beside RUN.h5)"},
  };
  const std::vector<OptionSpec> b = bootstrap_option_specs();
  s.insert(s.end(), b.begin(), b.end());
  return s;
}

RiskRun run_risk_analysis(const Options& opt, bool write_files) {
  if (!opt.given("input") || !opt.given("hazard"))
    throw InputError("command line: --input RUN.h5 and --hazard HAZARD.csv are required");
  RiskRun run;
  RiskSettings& s = run.settings;
  s.years = opt.get_double("years");
  if (!(s.years > 0)) throw opt.invalid("years", "valid: a number of years > 0");
  s.target_probability = opt.get_double("target-probability");
  if (!(s.target_probability > 0 && s.target_probability < 1))
    throw opt.invalid("target-probability", "valid: a probability in (0, 1)");
  if (opt.given("gaps")) {
    s.gaps = opt.get_doubles("gaps");
    for (std::size_t i = 0; i < s.gaps.size(); ++i)
      if (!(s.gaps[i] >= 0) || (i > 0 && !(s.gaps[i] > s.gaps[i - 1])))
        throw opt.invalid("gaps", "valid: increasing gaps >= 0 in m");
    if (s.gaps.empty()) throw opt.invalid("gaps", "valid: at least one gap >= 0 in m");
  }
  if (opt.given("design-im")) {
    s.design_im = opt.get_double("design-im") * kGravity;
    if (!(s.design_im > 0)) throw opt.invalid("design-im", "valid: an intensity > 0 in g");
  }
  s.bootstrap = bootstrap_from_options(opt);

  // Everything is read and computed before any file is written.
  const std::string input = opt.get_path("input");
  run.data = read_campaign(input);
  run.hazard = read_hazard_curve(opt.get_path("hazard"));
  const CampaignData& c = run.data;
  const HazardCurve& h = run.hazard;
  check_hazard_measure(c, h);
  try {
    run.modes = study_first_modes(c);
  } catch (const InputError&) {
    run.modes.clear();  // the code rules say they could not be computed
  }
  try {
    run.sites = study_pair_sites(c);
  } catch (const InputError&) {
    run.sites.clear();  // the code rules pair floor l with floor l and say so
  }
  run.report = analyse_risk(c, h, s, run.modes, run.sites, study_fragility_limits(c));
  if (!write_files) return run;

  const std::string dir = output_folder(opt, input, "risk");
  make_output_folder(opt, dir, input,
                     {"risk_gaps.csv", "code_rules.csv", "damage_maf.csv", "risk.h5"});
  run.dir = dir;
  run.files = write_risk_files(dir, c, h, run.report, RiskRunInfo{input, opt.resolved_text(), s});
  return run;
}

namespace {

// NAME_pounding and NAME_free.
template <class T>
void with_and_without(JsonWriter& w, const std::string& name, const T& pounding, const T& free) {
  w.field(name + "_pounding", pounding).field(name + "_free", free);
}

void band(JsonWriter& w, const std::string& name, const Interval& iv) {
  w.key(name);
  if (std::isfinite(iv.lo) && std::isfinite(iv.hi))
    w.array({iv.lo, iv.hi});
  else
    w.null();
}

// The fields of a damage limit, a collapse's too (CollapseRisk is a DamageRisk).
void damage_fields(JsonWriter& w, const DamageRisk& d) {
  w.field("model", d.model.empty() ? std::string("all") : d.model)
      .field("building", long(d.building))
      .field("edp", to_string(d.edp))
      .field("limit", d.limit);
  with_and_without(w, "status", std::string(to_string(d.pounding.status)),
                   std::string(to_string(d.free.status)));
  with_and_without(w, "maf", d.maf_pounding, d.maf_free);
  w.field("ratio", d.ratio)
      .field("free_same_analyses", d.same_analyses)
      .field("maf_pounding_kept", d.maf_pounding_kept);
  // The bootstrap bands: [lo, hi], or null where no replicate gave a finite value.
  band(w, "maf_pounding_band", d.maf_pounding_band);
  band(w, "maf_free_band", d.maf_free_band);
  band(w, "ratio_band", d.ratio_band);
  band(w, "probability_pounding_band", d.probability_pounding_band);
  band(w, "probability_free_band", d.probability_free_band);
  w.field("band_finite_pounding", long(d.maf_pounding_band.finite))
      .field("band_finite_free", long(d.maf_free_band.finite));
}

}  // namespace

std::string risk_json(const RiskRun& run) {
  const CampaignData& c = run.data;
  const HazardCurve& h = run.hazard;
  const RiskReport& r = run.report;
  const RiskSettings& s = run.settings;
  JsonWriter w;
  w.begin_object();
  w.field("input", c.path).field("hazard", h.source).field("out", run.dir);
  w.field("intensity_measure", c.intensity_measure).field("im_units", "m/s^2");
  w.field("hazard_rule", h.extrapolation_rule());
  w.field("years", s.years).field("target_probability", s.target_probability);
  w.field("design_im", r.design_im)
      .field("design_im_source", r.design_im_given ? "--design-im" : "hazard 475-year");
  w.field("samples", long(r.samples)).field("failed", long(r.failed)).field("used", long(r.used));
  w.field("bootstrap_replicates", s.bootstrap.replicates);
  w.key("pairs").begin_array();
  for (const auto& p : r.pairs) {
    w.begin_object().field("pair", long(p.pair + 1));
    std::vector<double> gaps, maf, prob;
    w.key("status").begin_array();
    for (const auto& e : p.grid) {
      gaps.push_back(e.gap);
      maf.push_back(e.maf);
      prob.push_back(e.probability);
      w.value(to_string(e.fit.status));
    }
    w.end_array();
    w.key("gaps_m").array(gaps);
    w.key("maf_pounding").array(maf);
    w.key("probability_pounding").array(prob);
    w.key("gap_for_target_m");
    std::isfinite(p.gap_for_target) ? w.value(p.gap_for_target) : w.null();
    w.field("gap_for_target_status", to_string(p.target_status));
    w.key("gap_for_target_band_m");
    if (std::isfinite(p.gap_band.lo) && std::isfinite(p.gap_band.hi))
      w.array({p.gap_band.lo, p.gap_band.hi});
    else
      w.null();
    w.field("gap_band_finite", long(p.gap_band.finite));
    w.field("rho", p.rho);
    w.field("ec8_case", to_string(p.ec8_case));
    w.objects("code_rules", p.rules, [&](const CodeRuleResult& k) {
      w.field("rule", to_string(k.rule))
          .field("gap_m", k.gap)
          .field("level", long(k.level))
          .field("status", to_string(k.estimate.fit.status))
          .field("maf_pounding", k.estimate.maf)
          .field("probability_pounding", k.estimate.probability);
    });
    w.end_object();
  }
  w.end_array();
  w.objects("damage", r.damage, [&](const DamageRisk& d) {
    damage_fields(w, d);
    with_and_without(w, "probability", d.probability_pounding, d.probability_free);
  });
  w.objects("collapse", r.collapse, [&](const CollapseRisk& k) {
    damage_fields(w, k);
    with_and_without(w, "theta", k.theta_pounding, k.free.finite() ? k.free.theta : NAN);
    with_and_without(w, "probability", k.probability_pounding, k.probability_free);
    with_and_without(w, "cmr", k.cmr_pounding, k.cmr_free);
  });
  w.key("notes").array(r.notes);
  w.key("files").array(run.files);
  w.end_object();
  return w.str();
}

}  // namespace pound

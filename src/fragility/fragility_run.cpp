#include "fragility/fragility_run.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "io/json.hpp"
#include "io/output_folder.hpp"

namespace pound {

const char* const kFragilitySummary =
    "Lognormal fragility curves with and without pounding from a campaign result file "
    "(maximum likelihood, Baker 2015), bootstrap bands, rank sensitivity.";

std::vector<OptionSpec> bootstrap_option_specs() {
  return {
      {"replicates", "-", "1000", "bootstrap replicates of the 90 % bands"},
      {"seed", "-", "1", "seed of the bootstrap draws"},
      {"json", "", "", "print one JSON object instead of the tables", true},
  };
}

std::vector<OptionSpec> fragility_option_specs() {
  std::vector<OptionSpec> s = {
      {"input", "", "", "campaign result file (HDF5) of 'pound campaign --out'"},
      {"out", "", "", "output folder (default: RUN-fragility/ beside RUN.h5)"},
      {"drift-limits", "-", "0.005, 0.01, 0.02, 0.025",
       "damage-state limits of the peak inter-storey drift ratio (0.01 = 1 %)"},
      {"disp-limits", "m", "", "limits of the peak floor displacement (none: no curves)"},
      {"accel-limits", "m/s^2", "",
       "limits of the peak absolute floor acceleration (none: no curves)"},
      {"force-limits", "N", "", "limits of the peak pounding force (none: no curves)"},
      {"residual-drift-limits", "-", "",
       "limits of the residual inter-storey drift ratio at the end of the run (0.005 = 0.5 %; "
       "none: no curves)"},
      {"ductility-limits", "-", "",
       "limits of the storey ductility demand, peak drift / yield drift (none: no curves; "
       "buildings without yield_shears have none and are left out)"},
  };
  const std::vector<OptionSpec> b = bootstrap_option_specs();
  s.insert(s.end(), b.begin(), b.end());
  return s;
}

namespace {

std::vector<double> limits(const Options& o, const std::string& key) {
  if (!o.has(key)) return {};
  const auto v = o.get_doubles(key);
  for (double x : v)
    if (!(x > 0)) throw o.invalid(key, "valid: a list of limits > 0 in SI units");
  return v;
}

void interval(JsonWriter& w, const std::string& key, double lo, double hi, bool finite) {
  w.key(key);
  if (!finite || !std::isfinite(lo) || !std::isfinite(hi)) {
    w.null();
    return;
  }
  w.array({lo, hi});
}

}  // namespace

BootstrapSettings bootstrap_from_options(const Options& opt) {
  const long reps = opt.get_int("replicates");
  if (reps < 10 || reps > 100000) throw opt.invalid("replicates", "valid: 10 to 100000");
  const long seed = opt.get_int("seed");
  if (seed < 0) throw opt.invalid("seed", "valid: a whole number >= 0");
  BootstrapSettings b;
  b.replicates = int(reps);
  b.seed = std::uint64_t(seed);
  return b;
}

FragilityRun run_fragility_analysis(const Options& opt, bool write_files) {
  if (!opt.given("input")) throw InputError("command line: --input RUN.h5 is required");
  FragilityRun run;
  const std::string input = opt.get_path("input");
  // Limits: the command line first, then the study's [fragility] section stored in the
  // campaign file, then the defaults (drift only).
  run.data = read_campaign(input);
  const CampaignData& c = run.data;
  FragilitySettings s = study_fragility_limits(c);
  for (auto [cli, list] : {std::pair{"drift-limits", &s.drift_limits},
                           {"disp-limits", &s.disp_limits},
                           {"accel-limits", &s.accel_limits},
                           {"force-limits", &s.force_limits},
                           {"residual-drift-limits", &s.residual_drift_limits},
                           {"ductility-limits", &s.ductility_limits}})
    if (opt.given(cli)) *list = limits(opt, cli);
  s.bootstrap = bootstrap_from_options(opt);
  if (s.drift_limits.empty() && s.disp_limits.empty() && s.accel_limits.empty() &&
      s.force_limits.empty() && s.residual_drift_limits.empty() && s.ductility_limits.empty())
    throw opt.invalid("drift-limits", "give at least one list of limits");

  const std::string dir = output_folder(opt, input, "fragility");
  run.report = analyse_fragility(c, s);
  run.info = FragilityRunInfo{input, s.bootstrap.replicates, std::to_string(s.bootstrap.seed),
                              opt.resolved_text()};
  if (!write_files) return run;

  make_output_folder(
      opt, dir, input,
      {"curves.csv", "shift.csv", "observations.csv", "sensitivity.csv", "fragility.h5"});
  run.dir = dir;
  run.files = write_fragility_files(dir, c, run.report, run.info);
  return run;
}

std::string fragility_json(const FragilityRun& run) {
  const CampaignData& c = run.data;
  const FragilityReport& r = run.report;
  const FragilityRunInfo& info = run.info;
  JsonWriter w;
  w.begin_object();
  w.field("input", info.input).field("out", run.dir);
  w.field("intensity_measure", c.intensity_measure).field("im_units", "m/s^2");
  w.field("design", r.stripes ? "stripes" : "continuous");
  w.field("samples", long(r.samples)).field("failed", long(r.failed)).field("used", long(r.used));
  w.field("bootstrap_replicates", info.replicates).field("bootstrap_seed", info.seed);
  w.key("building_names").array(c.building_names);
  w.field("collapse", r.collapse);
  w.key("models").array(r.models);
  w.key("shift").begin_array();
  for (const auto& s : r.shifts) {
    w.begin_object()
        .field("model", s.model.empty() ? std::string("all") : s.model)
        .field("building", long(s.building))
        .field("edp", to_string(s.edp));
    w.field("limit", s.limit).field("theta_ratio", s.ratio);
    interval(w, "theta_ratio_ci90", s.ci.lo, s.ci.hi, std::isfinite(s.ratio));
    w.field("theta_pounding", s.theta_pounding).field("theta_free", s.theta_free);
    w.field("free_same_analyses", s.same_analyses);
    w.field("beta_free", s.free_same.finite() ? s.free_same.beta : NAN);
    w.end_object();
  }
  w.end_array();
  w.key("curves").begin_array();
  for (const auto& k : r.curves) {
    const bool f = k.fit.finite();
    long n = 0, z = 0;
    for (const auto& o : k.observed) n += o.n, z += o.z;
    w.begin_object()
        .field("model", k.model.empty() ? std::string("all") : k.model)
        .field("building", long(k.building))
        .field("edp", to_string(k.edp));
    w.field("limit", k.limit)
        .field("pounding", k.pounding)
        .field("status", to_string(k.fit.status));
    w.key("theta");
    f ? w.value(k.fit.theta) : w.null();
    w.key("beta");
    f ? w.value(k.fit.beta) : w.null();
    interval(w, "theta_ci90", k.theta_ci.lo, k.theta_ci.hi, f);
    interval(w, "beta_ci90", k.beta_ci.lo, k.beta_ci.hi, f);
    interval(w, "theta_asymptotic90", k.theta_asym_lo, k.theta_asym_hi, f);
    interval(w, "beta_asymptotic90", k.beta_asym_lo, k.beta_asym_hi, f);
    // Without a finite estimate, the interval the data put theta in (null: no bound).
    w.key("theta_bound_lo");
    w.value(k.fit.bracketed() ? k.fit.theta_lo : NAN);
    w.key("theta_bound_hi");
    w.value(k.fit.bracketed() ? k.fit.theta_hi : NAN);
    w.field("bootstrap_finite", long(k.theta_ci.finite))
        .field("analyses", n)
        .field("exceedances", z)
        .field("left_out", long(k.left_out))
        .field("censored", long(k.censored));
    w.end_object();
  }
  w.end_array();
  w.key("sensitivity").begin_array();
  for (const auto& s : r.sensitivity)
    w.begin_object()
        .field("building", long(s.building))
        .field("response", s.response)
        .field("parameter", s.parameter)
        .field("spearman", s.spearman)
        .field("prcc", s.prcc)
        .field("samples", long(s.samples))
        .end_object();
  w.end_array();
  w.key("files").array(run.files);
  w.end_object();
  return w.str();
}

}  // namespace pound

// pound fragility --input RUN.h5 [--out DIR] [--json]: lognormal fragility curves with and
// without pounding from a campaign result file, their bootstrap bands, the shift of the median
// capacity by pounding (printed first) and the rank sensitivity of the amplification. Parses
// options, calls src/fragility, reports; the campaign file is opened read-only and the results
// go to DIR (default RUN-fragility/ beside the input), each file written atomically.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "app/table_number.hpp"
#include "core/error.hpp"
#include "fragility/campaign_reader.hpp"
#include "fragility/fragility_analysis.hpp"
#include "fragility/report_files.hpp"
#include "io/ini.hpp"
#include "io/json.hpp"
#include "io/options.hpp"
#include "motion/ground_motion.hpp"

namespace pound::app {
namespace {

namespace fs = std::filesystem;

std::vector<OptionSpec> specs() {
  return {
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
      {"replicates", "-", "1000", "bootstrap replicates of the 90 % bands"},
      {"seed", "-", "1", "seed of the bootstrap draws"},
      {"json", "", "", "print one JSON object instead of the tables", true},
  };
}

std::vector<double> limits(const Options& o, const std::string& key) {
  if (!o.has(key)) return {};
  const auto v = o.get_doubles(key);
  for (double x : v)
    if (!(x > 0)) throw o.invalid(key, "valid: a list of limits > 0 in SI units");
  return v;
}

// A limit for people: drift ratios in %, ductility as a number, the others in their SI unit.
std::string limit_text(Edp e, double x) {
  if (e == Edp::collapse) return "-";
  if (e == Edp::drift || e == Edp::residual_drift) return fmt("%.3g %%", 100 * x);
  if (e == Edp::ductility) return fmt("%.4g", x);
  return fmt("%.4g ", x) + unit_of(e);
}

// Width of the edp column: the longest name shown (at least that of "drift" and "disp").
int edp_width(const FragilityReport& r) {
  std::size_t w = 6;
  for (const auto& k : r.curves) w = std::max(w, std::string(to_string(k.edp)).size());
  return int(w);
}

// Where the data put theta when there is no finite estimate, in g: "> 1.5", "< 0.05",
// "1.25-1.5", else "-".
std::string bound_text(const LognormalFit& fit) {
  if (!fit.bracketed()) return "-";
  const double lo = fit.theta_lo / kGravity, hi = fit.theta_hi / kGravity;
  if (!(lo > 0.0) && std::isinf(hi)) return "-";
  if (std::isinf(hi)) return fmt("> %.3g", lo);
  if (!(lo > 0.0)) return fmt("< %.3g", hi);
  return fmt("%.3g", lo) + "-" + fmt("%.3g", hi);
}

// The shifts of one model ("" pooled) with the medians of their two curves (the free one
// fitted on the pounding curve's analyses where censoring left some out: marked *).
void print_shifts(const CampaignData& c, const FragilityReport& r, const std::string& model) {
  const int we = edp_width(r);
  std::printf("  %-12s %-*s %-10s %8s  %-17s %12s %12s\n", "building", we, "edp", "limit", "ratio",
              "band", "pounding [g]", "free [g]");
  bool marked = false;
  for (const auto& s : r.shifts) {
    if (s.model != model) continue;
    marked = marked || s.same_analyses;
    std::printf("  %-12s %-*s %-10s %8s  [%6s, %6s] %12s %12s%s\n",
                c.building_names[s.building].c_str(), we, to_string(s.edp),
                limit_text(s.edp, s.limit).c_str(), fmt("%.3f", s.ratio).c_str(),
                fmt("%.3f", s.ci.lo).c_str(), fmt("%.3f", s.ci.hi).c_str(),
                fmt("%.4f", s.theta_pounding / kGravity).c_str(),
                fmt("%.4f", s.theta_free / kGravity).c_str(), s.same_analyses ? " *" : "");
  }
  if (marked)
    std::printf(
        "  (* the free median of the analyses the pounding curve keeps: another building's "
        "collapse stopped some pounding runs while this one stood, and the ratio compares the "
        "same samples; the free curve of all the analyses is in the curves)\n");
}

void print_text(const CampaignData& c, const FragilityReport& r,
                const std::vector<std::string>& files) {
  const std::string im = c.intensity_measure == "sa" ? "Sa(T1)" : "PGA";
  std::printf(
      "Shift of the median capacity by pounding: theta_pounding / theta_free (%s, 90 %% bootstrap "
      "band)\n",
      im.c_str());
  const int we = edp_width(r);
  print_shifts(c, r, "");
  if (r.collapse)
    std::printf(
        "  (collapse: the building collapsed in the run; a collapsed building counts as "
        "exceeding every other limit)\n");
  for (const auto& m : r.models) {
    std::printf(
        "\nThe same for the analyses of contact model %s alone (the study samples the "
        "model)\n",
        m.c_str());
    print_shifts(c, r, m);
  }
  std::printf(
      "\nCurves: P(EDP > limit | %s = x) = Phi(ln(x / theta) / beta), maximum likelihood "
      "(Baker 2015)\n",
      im.c_str());
  std::printf("  %-12s %-*s %-10s %-5s %-16s %10s %19s %7s %17s %9s\n", "building", we, "edp",
              "limit", "pound", "status", "theta [g]", "90 % band [g]", "beta", "90 % band",
              "exceed");
  for (const auto& k : r.curves) {
    if (!k.model.empty()) continue;  // the models' curves: curves.csv and --json
    long n = 0, z = 0;
    for (const auto& o : k.observed) n += o.n, z += o.z;
    const bool f = k.fit.finite();
    std::printf(
        "  %-12s %-*s %-10s %-5s %-16s %10s [%7s, %7s] %7s [%6s, %6s] %4ld/%-4ld\n",
        c.building_names[k.building].c_str(), we, to_string(k.edp),
        limit_text(k.edp, k.limit).c_str(), k.pounding ? "yes" : "no", to_string(k.fit.status),
        f ? fmt("%.4f", k.fit.theta / kGravity).c_str() : bound_text(k.fit).c_str(),
        f ? fmt("%.4f", k.theta_ci.lo / kGravity).c_str() : "-",
        f ? fmt("%.4f", k.theta_ci.hi / kGravity).c_str() : "-",
        f ? fmt("%.3f", k.fit.beta).c_str() : "-", f ? fmt("%.3f", k.beta_ci.lo).c_str() : "-",
        f ? fmt("%.3f", k.beta_ci.hi).c_str() : "-", z, n);
  }
  if (!r.models.empty())
    std::printf("  (the curves of each contact model alone: curves.csv and --json)\n");
  for (const auto& k : r.curves) {
    if (!k.left_out || !k.model.empty()) continue;
    const std::size_t nonfinite = k.left_out - k.censored;
    std::string why;
    if (k.censored)
      why += std::to_string(k.censored) +
             " censored: the pounding run stopped at another building's collapse while this "
             "one stood";
    if (nonfinite)
      why += (why.empty() ? "" : "; ") + std::to_string(nonfinite) + " not finite" +
             (k.edp == Edp::ductility ? ": the building has no yield_shears" : "");
    std::printf("  (%s %s %s, %s: %zu analyses left out, %s)\n",
                c.building_names[k.building].c_str(), to_string(k.edp),
                limit_text(k.edp, k.limit).c_str(), k.pounding ? "pounding" : "no pounding",
                k.left_out, why.c_str());
  }
  std::printf(
      "\nSensitivity of the amplification (pounding / free) to the sampled parameters, "
      "ranked by |PRCC|\n");
  std::printf("  %-12s %-20s %-24s %9s %9s %8s\n", "building", "response", "parameter", "Spearman",
              "PRCC", "samples");
  for (const auto& s : r.sensitivity)
    std::printf("  %-12s %-20s %-24s %9s %9s %8zu\n", c.building_names[s.building].c_str(),
                s.response.c_str(), s.parameter.c_str(), fmt("%+.3f", s.spearman).c_str(),
                fmt("%+.3f", s.prcc).c_str(), s.samples);
  if (!r.unranked.empty()) {
    std::printf("  (not ranked, labels:");
    for (const auto& u : r.unranked) std::printf(" %s", u.c_str());
    std::printf(")\n");
  }
  std::printf("\nFiles:");
  for (const auto& f : files) std::printf(" %s", f.c_str());
  std::printf("\n");
}

void interval(JsonWriter& w, const std::string& key, double lo, double hi, bool finite) {
  w.key(key);
  if (!finite || !std::isfinite(lo) || !std::isfinite(hi)) {
    w.null();
    return;
  }
  w.array({lo, hi});
}

void print_json(const CampaignData& c, const FragilityReport& r, const FragilityRunInfo& info,
                const std::string& dir, const std::vector<std::string>& files) {
  JsonWriter w;
  w.begin_object();
  w.field("input", info.input).field("out", dir);
  w.field("intensity_measure", c.intensity_measure).field("im_units", "m/s^2");
  w.field("design", r.stripes ? "stripes" : "continuous");
  w.field("samples", long(r.samples)).field("failed", long(r.failed)).field("used", long(r.used));
  w.field("bootstrap_replicates", info.replicates).field("bootstrap_seed", info.seed);
  w.key("building_names").begin_array();
  for (const auto& n : c.building_names) w.value(n);
  w.end_array();
  w.field("collapse", r.collapse);
  w.key("models").begin_array();
  for (const auto& m : r.models) w.value(m);
  w.end_array();
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
  w.key("files").begin_array();
  for (const auto& f : files) w.value(f);
  w.end_array();
  w.end_object();
  std::cout << w.str() << "\n";
}

}  // namespace

int run_fragility(int argc, const char* const* argv) {
  Options opt("fragility",
              "Lognormal fragility curves with and without pounding from a campaign result file "
              "(maximum likelihood, Baker 2015), bootstrap bands, rank sensitivity.",
              specs());
  if (help_asked(opt, argc, argv)) return 0;
  if (!opt.given("input")) throw InputError("command line: --input RUN.h5 is required");
  const std::string input = opt.get_path("input");
  // Limits: the command line first, then the study's [fragility] section stored in the
  // campaign file, then the defaults (drift only).
  const CampaignData c = read_campaign(input);
  FragilitySettings s = study_fragility_limits(c);
  for (auto [cli, list] : {std::pair{"drift-limits", &s.drift_limits},
                           {"disp-limits", &s.disp_limits},
                           {"accel-limits", &s.accel_limits},
                           {"force-limits", &s.force_limits},
                           {"residual-drift-limits", &s.residual_drift_limits},
                           {"ductility-limits", &s.ductility_limits}})
    if (opt.given(cli)) *list = limits(opt, cli);
  const long reps = opt.get_int("replicates");
  if (reps < 10 || reps > 100000) throw opt.invalid("replicates", "valid: 10 to 100000");
  const long seed = opt.get_int("seed");
  if (seed < 0) throw opt.invalid("seed", "valid: a whole number >= 0");
  s.bootstrap.replicates = int(reps);
  s.bootstrap.seed = std::uint64_t(seed);
  if (s.drift_limits.empty() && s.disp_limits.empty() && s.accel_limits.empty() &&
      s.force_limits.empty() && s.residual_drift_limits.empty() && s.ductility_limits.empty())
    throw opt.invalid("drift-limits", "give at least one list of limits");

  std::string dir;
  if (opt.given("out")) {
    dir = opt.get_path("out");
  } else {
    fs::path p(input);
    dir = (p.parent_path() / (p.stem().string() + "-fragility")).string();
  }
  const FragilityReport r = analyse_fragility(c, s);

  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError(opt.where("out") + ": cannot create the folder " + dir);
  for (const char* name :
       {"curves.csv", "shift.csv", "observations.csv", "sensitivity.csv", "fragility.h5"})
    if (fs::equivalent(fs::path(dir) / name, input, ec))
      throw InputError(opt.where("out") + ": " + dir + "/" + name +
                       " is the campaign file; choose another output folder");
  FragilityRunInfo info{input, int(reps), std::to_string(seed), opt.resolved_text()};
  const auto files = write_fragility_files(dir, c, r, info);
  if (opt.flag("json"))
    print_json(c, r, info, dir, files);
  else
    print_text(c, r, files);
  if (r.failed)
    std::fprintf(stderr, "fragility: %zu of %zu samples failed and are excluded\n", r.failed,
                 r.samples);
  return 0;
}

}  // namespace pound::app

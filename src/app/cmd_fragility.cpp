// pound fragility --input RUN.h5 [--out DIR] [--json]: lognormal fragility curves with and
// without pounding from a campaign result file, their bootstrap bands, the shift of the median
// capacity by pounding (printed first) and the rank sensitivity of the amplification. Parses
// options, calls src/fragility, reports; the campaign file is opened read-only and the results
// go to DIR (default RUN-fragility/ beside the input), each file written atomically.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "app/analysis_command.hpp"
#include "app/commands.hpp"
#include "app/limit_text.hpp"
#include "app/table_number.hpp"
#include "core/error.hpp"
#include "fragility/campaign_reader.hpp"
#include "fragility/fragility_analysis.hpp"
#include "fragility/fragility_run.hpp"
#include "fragility/report_files.hpp"
#include "io/options.hpp"
#include "motion/ground_motion.hpp"

namespace pound::app {
namespace {

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
             (k.edp == Edp::ductility      ? ": the building has no yield_shears"
              : k.edp == Edp::column_shear ? ": no column_shear_strength or no storey struck"
                                           : "");
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
  print_files(files);
}

void print_run(const FragilityRun& run) {
  print_text(run.data, run.report, run.files);
}

}  // namespace

int run_fragility(int argc, const char* const* argv) {
  return run_analysis_command<FragilityRun>("fragility", kFragilitySummary,
                                            fragility_option_specs(), argc, argv,
                                            run_fragility_analysis, fragility_json, print_run);
}

}  // namespace pound::app

// pound risk --input RUN.h5 --hazard HAZARD.csv [--gaps LIST] [--years 50]
//            [--target-probability 0.02] [--design-im G] [--out DIR] [--json]
// The pounding risk of every gap from one campaign and a site's hazard curve: the mean annual
// frequency of pounding and its probability in T years per gap, the smallest gap meeting a
// target (bootstrap band), the code rules' gaps and their probabilities, and the damage
// limits' mean annual frequencies with and without pounding. Parses options, calls src/risk,
// reports; the campaign file is opened read-only, the results go to DIR (default RUN-risk/).
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
#include "io/json.hpp"
#include "io/options.hpp"
#include "motion/ground_motion.hpp"
#include "risk/hazard_curve.hpp"
#include "risk/pounding_risk.hpp"
#include "risk/risk_files.hpp"
#include "risk/risk_run.hpp"

namespace pound::app {
namespace {

std::string pair_name(const CampaignData& c, std::size_t p) {
  return c.building_name(p) + " | " + c.building_name(p + 1);
}

constexpr const char* kLikeForLike =
    "(* another building's collapse stopped some pounding runs while this one stood, its fate "
    "unknown: the ratio compares pounding and free on the analyses the pounding curve keeps, and "
    "nu pounding is nu free times that ratio; docs/risk.md, \"Pounding and collapse\")";

// A probability in T years and its bootstrap band: "0.0310 [0.0270, 0.0355]"; the band left
// out where it or the point is not finite.
std::string with_band(double p, const Interval& band, const char* format) {
  std::string s = fmt(format, p);
  if (std::isfinite(p) && std::isfinite(band.lo) && std::isfinite(band.hi))
    s += " [" + fmt(format, band.lo) + ", " + fmt(format, band.hi) + "]";
  return s;
}

// Collapse per building, pooled and per sampled contact model (issue 23).
void print_collapse(const CampaignData& c, const RiskReport& r, const RiskSettings& s) {
  if (r.collapse.empty()) return;
  const std::string T = fmt("%g", s.years);
  std::printf(
      "\nCollapse: mean annual frequency and probability in %s years with and without pounding%s\n",
      T.c_str(),
      r.design_im_given ? ", collapse margin ratio CMR = median collapse intensity / design-im "
                          "(FEMA P695)"
                        : " (--design-im MCE gives the collapse margin ratio)");
  const std::string band = fmt(" [%g %% band]", 100 * s.confidence);
  std::printf("  %-12s %-10s %12s %12s %8s %27s %27s %8s %8s\n", "building", "model", "nu pounding",
              "nu free", "ratio", ("P" + T + " pound" + band).c_str(),
              ("P" + T + " free" + band).c_str(), "CMR pnd", "CMR free");
  bool marked = false;
  for (const auto& k : r.collapse) {
    marked = marked || k.same_analyses;
    std::printf(
        "  %-12s %-10s %12s %12s %8s %27s %27s %8s %8s%s\n", c.building_names[k.building].c_str(),
        k.model.empty() ? "all" : k.model.c_str(),
        k.pounding.finite() ? fmt("%.3e", k.maf_pounding).c_str() : to_string(k.pounding.status),
        k.free.finite() ? fmt("%.3e", k.maf_free).c_str() : to_string(k.free.status),
        fmt("%.3f", k.ratio).c_str(),
        with_band(k.probability_pounding, k.probability_pounding_band, "%.5f").c_str(),
        with_band(k.probability_free, k.probability_free_band, "%.5f").c_str(),
        fmt("%.2f", k.cmr_pounding).c_str(), fmt("%.2f", k.cmr_free).c_str(),
        k.same_analyses ? " *" : "");
  }
  if (marked) std::printf("  %s\n", kLikeForLike);
}

void print_text(const CampaignData& c, const HazardCurve& h, const RiskReport& r,
                const RiskSettings& s, const std::vector<BuildingMode>& modes,
                const std::vector<std::string>& files) {
  const std::string im = c.intensity_measure == "sa" ? "Sa(T1)" : "PGA";
  const std::string T = fmt("%g", s.years);
  std::printf("Pounding risk: %s on the hazard curve %s (%s, %zu points, %s-%s g)\n",
              c.path.c_str(), h.source.c_str(), im.c_str(), h.im.size(),
              fmt("%.4g", h.im.front() / kGravity).c_str(),
              fmt("%.4g", h.im.back() / kGravity).c_str());
  std::printf("  hazard: %s\n", h.extrapolation_rule().c_str());
  std::printf(
      "  %zu samples, %zu failed (not used), %zu %s; exposure %s years; target "
      "P(pounding in %s years) <= %g\n\n",
      r.samples, r.failed, r.groups, r.stripes ? "stripes" : "IM bins", T.c_str(), T.c_str(),
      s.target_probability);
  std::printf(
      "Gap needed for the target (the same gap at every level of a pair; %g %% "
      "bootstrap band, %d replicates)\n",
      100 * s.confidence, s.bootstrap.replicates);
  std::printf("  %-4s  %-24s %10s  %-22s %s\n", "pair", "buildings", "gap [m]", "band [m]",
              "status");
  for (const auto& p : r.pairs)
    std::printf(
        "  %-4zu  %-24s %10s  [%8s, %8s]  %s\n", p.pair + 1, pair_name(c, p.pair).c_str(),
        ((p.target_status == TargetStatus::at_most ? "<= " : "") + fmt("%.4f", p.gap_for_target))
            .c_str(),
        fmt("%.4f", p.gap_band.lo).c_str(), fmt("%.4f", p.gap_band.hi).c_str(),
        to_string(p.target_status));
  std::printf("\nCode rules at %s %s g (%s), from the median free-run peak displacements\n",
              im.c_str(), fmt("%.4g", r.design_im / kGravity).c_str(),
              r.design_im_given ? "--design-im" : "the hazard's 475-year intensity");
  std::printf(
      "  (the rules assume one ground motion under both buildings: they leave out the relative\n"
      "  ground displacement of spatially varying ground, which the gap above includes; "
      "docs/ground.md)\n");
  std::printf("  %-4s  %-5s %10s %6s %10s %14s %22s\n", "pair", "rule", "gap [m]", "level",
              "pounding", "nu [1/yr]", ("P(pounding in " + T + " y)").c_str());
  for (const auto& p : r.pairs) {
    if (!p.rules_computed) {
      std::printf("  %-4zu  not computed: %s\n", p.pair + 1, p.rules_note.c_str());
      continue;
    }
    for (const auto& k : p.rules)
      std::printf("  %-4zu  %-5s %10s %6d %10ld %14s %22s\n", p.pair + 1, to_string(k.rule),
                  fmt("%.4f", k.gap).c_str(), k.level, k.estimate.pounding,
                  k.estimate.fit.finite() ? fmt("%.3e", k.estimate.maf).c_str()
                                          : to_string(k.estimate.fit.status),
                  fmt("%.4f", k.estimate.probability).c_str());
    const std::size_t bl = p.pair, br = p.pair + 1;
    std::printf("        rho = %s (Der Kiureghian 1981; T1 %s / %s s, damping %s / %s)\n",
                fmt("%.4f", p.rho).c_str(), fmt("%.3f", modes[bl].period_s).c_str(),
                fmt("%.3f", modes[br].period_s).c_str(), fmt("%.3f", modes[bl].damping).c_str(),
                fmt("%.3f", modes[br].damping).c_str());
    std::string ml, mr;
    for (std::size_t l = 0; l < p.median_left.size(); ++l) {
      ml += (l ? ", " : "") + fmt("%.4f", p.median_left[l]);
      mr += (l ? ", " : "") + fmt("%.4f", p.median_right[l]);
    }
    std::printf("        median free peak displacements by level [m]: %s | %s\n", ml.c_str(),
                mr.c_str());
    std::printf("        ec8 (EN 1998-1 4.4.2.7(3)): %s\n", describe(p.ec8_case));
  }
  for (const auto& p : r.pairs) {
    std::printf(
        "\nPounding at each gap, pair %zu (%s): P(pounding | %s) = Phi(ln(x / theta) / "
        "beta)\n",
        p.pair + 1, pair_name(c, p.pair).c_str(), im.c_str());
    std::printf("  %9s %9s %9s  %-16s %10s %7s %12s %12s  %-20s\n", "gap [m]", "pounding",
                "collapsed", "status", "theta [g]", "beta", "nu [1/yr]", ("P(" + T + " y)").c_str(),
                "90 % band");
    for (const auto& e : p.grid)
      std::printf("  %9s %4ld/%-4ld %9ld  %-16s %10s %7s %12s %12s  [%7s, %7s]\n",
                  fmt("%.4f", e.gap).c_str(), e.pounding, e.analyses, e.pounding_collapsed,
                  to_string(e.fit.status),
                  e.fit.finite() ? fmt("%.4f", e.fit.theta / kGravity).c_str() : "-",
                  e.fit.finite() ? fmt("%.3f", e.fit.beta).c_str() : "-",
                  fmt("%.3e", e.maf).c_str(), fmt("%.4f", e.probability).c_str(),
                  fmt("%.4f", e.probability_band.lo).c_str(),
                  fmt("%.4f", e.probability_band.hi).c_str());
  }
  std::printf(
      "\nDamage limits: mean annual frequency of exceedance with and without pounding "
      "(at the campaign's own gaps), probability in %s years with its %g %% bootstrap band (%d "
      "replicates)\n",
      T.c_str(), 100 * s.confidence, s.bootstrap.replicates);
  std::printf("  %-12s %-15s %-10s %12s %12s %8s %24s %24s\n", "building", "edp", "limit",
              "nu pounding", "nu free", "ratio", ("P" + T + " pound [band]").c_str(),
              ("P" + T + " free [band]").c_str());
  bool marked = false;
  for (const auto& d : r.damage)
    if (d.model.empty()) {
      marked = marked || d.same_analyses;
      std::printf(
          "  %-12s %-15s %-10s %12s %12s %8s %24s %24s%s\n", c.building_names[d.building].c_str(),
          to_string(d.edp), limit_text(d.edp, d.limit).c_str(),
          d.pounding.finite() ? fmt("%.3e", d.maf_pounding).c_str() : to_string(d.pounding.status),
          d.edp == Edp::force ? "-"
          : d.free.finite()   ? fmt("%.3e", d.maf_free).c_str()
                              : to_string(d.free.status),
          fmt("%.3f", d.ratio).c_str(),
          with_band(d.probability_pounding, d.probability_pounding_band, "%.4f").c_str(),
          with_band(d.probability_free, d.probability_free_band, "%.4f").c_str(),
          d.same_analyses ? " *" : "");
    }
  if (marked) std::printf("  %s\n", kLikeForLike);
  print_collapse(c, r, s);
  if (!r.notes.empty()) {
    std::printf("\nWhat could not be estimated:\n");
    for (const auto& n : r.notes) std::printf("  - %s\n", n.c_str());
  }
  print_files(files);
}

void print_run(const RiskRun& run) {
  print_text(run.data, run.hazard, run.report, run.settings, run.modes, run.files);
}

}  // namespace

int run_risk(int argc, const char* const* argv) {
  return run_analysis_command<RiskRun>("risk", kRiskSummary, risk_option_specs(), argc, argv,
                                       run_risk_analysis, risk_json, print_run);
}

}  // namespace pound::app

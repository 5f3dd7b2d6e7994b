// Case 6 of bench_speed, the collapse benchmark of issue 23 (docs/speed.md, "Deteriorating
// storeys and the stop at collapse"): on one core, samples of
// studies/fragility-default.ini as it is (imk storeys with P-Delta and tangent damping; a run
// stops at collapse) against
//   1. the same samples with bilinear storeys (the same P-Delta, damping, collapse rule and
//      sampled values; the imk parameters then act on nothing): the cost of the imk law,
//      per contact model, over the samples that collapse in neither (like for like) and over all;
//   2. the first kNoStop samples of each contact model that collapsed, run again with no collapse
//      rule (collapse_drift_ratio infinite, so the run goes on to the end of the record): the
//      time the stop saves, and how many of those runs could not go on (a storey without
//      strength under P-Delta runs away until the solver gives up, which can take minutes).
// Each sample's time is the process CPU time of the whole sample (motion, run with pounding,
// run without), the smallest of REPEAT runs.
// Usage: bench_speed SOURCE collapse [N [REPEAT [imk|bilinear|both [--key value ...]]]]
// (defaults: 60 samples = four per stripe, 1 run each); with
// imk or bilinear, only the samples of that law are run, without the table (for profiling under
// callgrind); further arguments are study options (e.g. --building1.damping_stiffness initial).
#include "collapse_bench.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <string>
#include <vector>

#include "campaign/campaign_study.hpp"
#include "campaign/sample.hpp"
#include "contact/registry.hpp"
#include "io/options.hpp"

namespace {

using namespace pound;

constexpr int kNoStop = 3;  // collapsed samples per contact model run again without the stop

double cpu_time(SampleRunner& r, long id, int repeat, SampleOutcome& out) {
  double best = 1e300;
  for (int k = 0; k < repeat; ++k) {
    const std::clock_t c0 = std::clock();
    out = r.run(id);
    best = std::min(best, double(std::clock() - c0) / CLOCKS_PER_SEC);
  }
  return best;
}

bool collapsed(const SampleOutcome& o) {
  for (double c : o.collapsed_pounding)
    if (c == 1.0) return true;
  for (double c : o.collapsed_free)
    if (c == 1.0) return true;
  return false;
}

const char* status_text(const SampleOutcome& o) {
  return o.status == SampleStatus::ok ? "ok" : "failed";
}

}  // namespace

int collapse_case(const std::string& src, const std::vector<std::string>& arguments) {
  const auto arg = [&](std::size_t k) { return k < arguments.size() ? arguments[k] : ""; };
  const long samples = arguments.size() > 0 ? std::stol(arg(0)) : 60;
  const int repeat = arguments.size() > 1 ? std::stoi(arg(1)) : 1;
  Options oc("campaign", "collapse benchmark", campaign_option_specs());
  std::vector<std::string> args = {"--config", src + "/studies/fragility-default.ini"};
  if (arguments.size() > 3) args.insert(args.end(), arguments.begin() + 3, arguments.end());
  oc.parse(args);
  const CampaignStudy study = campaign_from_options(oc, samples, -1);
  CampaignStudy bilinear = study, no_stop = study;
  for (auto& b : bilinear.row.buildings) b.hysteresis = "bilinear";
  no_stop.simulation.collapse_drift_ratio = std::numeric_limits<double>::infinity();
  SampleRunner run_imk(study), run_bil(bilinear), run_nostop(no_stop);
  if (arguments.size() > 2 && arg(2) != "both") {  // profiling: one law's samples alone
    const std::string law = arg(2);
    if (law != "imk" && law != "bilinear") {
      std::fprintf(stderr, "bench_speed collapse: law '%s': valid: imk, bilinear, both\n",
                   law.c_str());
      return 2;
    }
    SampleOutcome o;
    double t = 0.0;
    for (long id = 0; id < samples; ++id)
      t += cpu_time(law == "imk" ? run_imk : run_bil, id, repeat, o);
    std::printf("%s: %ld samples, %.4f s per sample\n", law.c_str(), samples, t / samples);
    return 0;
  }

  std::printf(
      "\n6. collapse (issue 23): studies/fragility-default.ini, samples 0-%ld, storeys %s, "
      "P-Delta %s, collapse at drift ratio %g; process CPU time per sample, the smallest of %d\n",
      samples - 1, study.row.buildings[0].hysteresis.c_str(),
      study.row.buildings[0].p_delta ? "on" : "off", study.simulation.collapse_drift_ratio, repeat);
  std::printf("%4s %-10s %7s %9s %9s %6s %9s %9s %10s\n", "id", "model", "PGA[g]", "imk[s]",
              "bilin[s]", "ratio", "collapse", "bilinear", "no-stop[s]");
  struct Sum {
    int n = 0, n_standing = 0, collapsed = 0, n_collapsed = 0, nostop_failed = 0;
    double imk = 0, bil = 0, imk_standing = 0, bil_standing = 0, imk_collapsed = 0, stop = 0,
           nostop = 0;
  } sums[2];  // 0 sears, 1 lumped
  for (long id = 0; id < samples; ++id) {
    SampleOutcome oi, ob, on;
    const double ti = cpu_time(run_imk, id, repeat, oi);
    const double tb = cpu_time(run_bil, id, repeat, ob);
    const std::string model = run_imk.draw(id).model;
    Sum& m = sums[is_sears_model(model) ? 0 : 1];
    ++m.n;
    m.imk += ti;
    m.bil += tb;
    const bool ci = collapsed(oi), cb = collapsed(ob);
    m.collapsed += ci;
    if (ci) m.imk_collapsed += ti;
    if (!ci && !cb && oi.status == SampleStatus::ok && ob.status == SampleStatus::ok) {
      ++m.n_standing;
      m.imk_standing += ti;
      m.bil_standing += tb;
    }
    double tn = NAN;
    if (ci && m.n_collapsed < kNoStop) {
      tn = cpu_time(run_nostop, id, 1, on);
      ++m.n_collapsed;
      m.stop += ti;
      m.nostop += tn;
      m.nostop_failed += on.status != SampleStatus::ok;
    }
    std::printf(
        "%4ld %-10s %7.3f %9.4f %9.4f %6.2f %9s %9s %10s%s\n", id, model.c_str(), oi.im / 9.80665,
        ti, tb, ti / tb, ci ? "yes" : "no", cb ? "collapsed" : "standing",
        std::isfinite(tn) ? (std::to_string(tn).substr(0, 8) + " " + status_text(on)).c_str() : "-",
        oi.status == SampleStatus::ok ? "" : "  (imk sample failed)");
  }
  {
    const Sum &a = sums[0], &b = sums[1];
    std::printf(
        "\nall %d samples (both contact models): imk %.4f s, bilinear %.4f s per sample, ratio "
        "%.2f; the %d that collapse in neither: ratio %.2f\n",
        a.n + b.n, (a.imk + b.imk) / (a.n + b.n), (a.bil + b.bil) / (a.n + b.n),
        (a.imk + b.imk) / (a.bil + b.bil), a.n_standing + b.n_standing,
        (a.imk_standing + b.imk_standing) / (a.bil_standing + b.bil_standing));
  }
  std::printf("per contact model:\n");
  for (int k = 0; k < 2; ++k) {
    const Sum& m = sums[k];
    if (!m.n) continue;
    std::printf(
        "  %-10s %3d samples: imk %.4f s, bilinear %.4f s per sample, ratio %.2f; the %d that "
        "collapse in neither: ratio %.2f (imk %.4f s, bilinear %.4f s)\n",
        k == 0 ? "sears" : "hc-linear", m.n, m.imk / m.n, m.bil / m.n, m.imk / m.bil, m.n_standing,
        m.imk_standing / m.bil_standing, m.imk_standing / std::max(1, m.n_standing),
        m.bil_standing / std::max(1, m.n_standing));
    if (m.collapsed)
      std::printf("  %-10s %3d samples collapsed (imk): %.4f s per sample\n", "", m.collapsed,
                  m.imk_collapsed / m.collapsed);
    if (m.n_collapsed)
      std::printf(
          "  %-10s %3d of them run again without the stop: %.4f s per sample with it, %.4f s "
          "without (saved %.1f %%); %d of the runs without the stop failed numerically\n",
          "", m.n_collapsed, m.stop / m.n_collapsed, m.nostop / m.n_collapsed,
          100.0 * (1.0 - m.stop / m.nostop), m.nostop_failed);
  }
  return 0;
}

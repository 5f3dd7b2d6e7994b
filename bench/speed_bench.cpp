// Speed benchmark of issue 8 (docs/speed.md): on one core, the default integrators (event-driven
// stepping of the damped Sears model, adaptive Dormand-Prince with event location of the
// lumped models) against the fixed-step reference at dt = 10 us, for
//   1. the thesis' chapter 8 example, `sears` N = 100, the full El Centro record (31.16 s);
//   2. the same 5 + 3 storey pair with the lumped hc-linear model (k = 50 x storey stiffness);
//   3. a 20-sample campaign of studies/fragility-default.ini (SampleRunner, no MPI).
// Prints the time per sample (with and without pounding: both runs), the speed-up of the
// default path over the reference, and the largest relative differences between the two in
// peak floor displacement, peak drift and peak pounding force, and the impact counts.
// Times are process CPU times (one thread), robust on a shared machine; wall times beside.
//   4. yielding buildings: samples of the default study against elastic storeys and the reference.
//   5. the cost of a default-study sample per contact model, its motion apart (issue 13).
//   6. imk storeys against bilinear ones on the default study, and the time the stop at
//      collapse saves (issue 23; bench/collapse_bench.cpp).
//   7. a sample on soil-structure interaction against the same sample on fixed bases
//      (issue 29; studies/ssi-soft-soil.ini).
//   8. a sample of two identical neighbours on spatially varying ground against one motion
//      under both (issue 28; studies/svgm-identical-pair.ini).
// Usage: bench_speed [source dir [quick | lumped [check] | sample ID | inelastic [N] |
// samples [N [REPEAT [MODEL [spectral|none]]]] | collapse [N [REPEAT [imk|bilinear|both
// [--key value ...]]]] | ssi|svgm|svgm-apart|svgm-default [N [REPEAT [MODEL|all [with|base]]]] |
// ch8 | fine-step | contact-steps | split STUDY [N [REPEAT [--key value ...]]]]] (default: the
// source tree it was built from; "quick": only the event-driven chapter 8 run, for profiling;
// "fine-step": the event path's fine step against the fixed path; "contact-steps": the longer steps
// through smooth contact forces at several sears.contact_step_tolerance values; "ch8": case 1
// alone; "lumped": only the adaptive run of case 2, for profiling, with "check" also its fixed-step
// reference and the case 2 line; "sample ID": peak forces of sample ID (0..19) of case 3's campaign
// on the default path, the fixed path at its automatic step and at 10 us)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "campaign/campaign_study.hpp"
#include "campaign/sample.hpp"
#include "collapse_bench.hpp"
#include "contact/registry.hpp"
#include "io/options.hpp"
#include "motion/simqke.hpp"
#include "motion/spectral_variability.hpp"
#include "sears/sears_row_layout.hpp"
#include "sears/sears_simulation.hpp"
#include "simulation/simulate_row.hpp"
#include "split_bench.hpp"
#include "study/row_options.hpp"
#include "study/sears_row_options.hpp"

namespace {

using namespace pound;

constexpr double kReferenceDt = 1e-5;  // the thesis' fixed step [s]

struct Timing {
  double cpu_s = 0.0, wall_s = 0.0;
};

// Runs f `repeat` times; the smallest CPU time (and its wall time).
Timing time_it(const std::function<void()>& f, int repeat) {
  Timing best{1e300, 0.0};
  for (int i = 0; i < repeat; ++i) {
    const std::clock_t c0 = std::clock();
    const auto w0 = std::chrono::steady_clock::now();
    f();
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    if (cpu < best.cpu_s) best = Timing{cpu, wall};
  }
  return best;
}

double rel(double a, double ref) {
  return ref != 0.0 ? std::fabs(a - ref) / std::fabs(ref) : std::fabs(a - ref);
}

struct Differences {
  double disp = 0.0, drift = 0.0, force = 0.0;  // largest relative difference [-]
  std::string impacts_default, impacts_reference;
  bool same_impacts = true;
};

// Pounding-run peaks of every floor and site.
Differences compare(const RowSimulation& d, const RowSimulation& r, const std::vector<int>& imp_d,
                    const std::vector<int>& imp_r) {
  Differences x;
  for (std::size_t i = 0; i < d.floors.size(); ++i) {
    x.disp = std::max(x.disp, rel(d.floors[i].disp_pounding, r.floors[i].disp_pounding));
    x.drift = std::max(
        x.drift, rel(d.floors[i].peak_drift_ratio_pounding, r.floors[i].peak_drift_ratio_pounding));
  }
  for (std::size_t s = 0; s < d.sites.size(); ++s)
    x.force = std::max(x.force, rel(d.sites[s].peak_force, r.sites[s].peak_force));
  for (std::size_t s = 0; s < imp_d.size(); ++s) {
    x.impacts_default += (s ? "/" : "") + std::to_string(imp_d[s]);
    x.impacts_reference += (s ? "/" : "") + std::to_string(imp_r[s]);
    x.same_impacts = x.same_impacts && imp_d[s] == imp_r[s];
  }
  return x;
}

void header() {
  std::printf("%-28s %10s %10s %10s %10s %8s %8s %8s %8s  %s\n", "case", "cpu/smp[s]",
              "wall/smp[s]", "ref cpu[s]", "speed-up", "d disp", "d drift", "d force", "same imp",
              "impacts default | reference");
}

void line(const char* name, Timing t, Timing ref, int samples, const Differences& x) {
  std::printf("%-28s %10.4f %10.4f %10.3f %10.1f %7.3f%% %7.3f%% %7.3f%% %8s  %s | %s\n", name,
              t.cpu_s / samples, t.wall_s / samples, ref.cpu_s / samples, ref.cpu_s / t.cpu_s,
              100.0 * x.disp, 100.0 * x.drift, 100.0 * x.force, x.same_impacts ? "yes" : "NO",
              x.impacts_default.c_str(), x.impacts_reference.c_str());
}

Options row_study(const std::string& file, std::vector<std::string> extra) {
  Options opt("simulate", "speed benchmark", row_and_sears_option_specs());
  extra.insert(extra.begin(), {"--config", file});
  opt.parse(extra);
  return opt;
}

// 2. The chapter 8 pair with the lumped hc-linear model (adaptive DP 5(4) with event location),
// timed over 5 runs; with `reference`, also the fixed-step run at 10 us and the comparison line.
void lumped_case(const std::string& ch8, const BuildingRow& row, const GroundMotion& motion,
                 bool reference) {
  const Options o2 = row_study(ch8, {"--motion.duration", "1e9", "--contact.model", "hc-linear",
                                     "--contact.k_factor", "50"});
  const ContactSpec contact = contact_from_options(o2, row, single_model_use(o2));
  IntegratorSettings ad = integrator_from_options(o2), fi = ad;
  ad.control = StepControl::adaptive;
  fi.control = StepControl::fixed;
  fi.dt = kReferenceDt;
  RowSimulation le, lf;
  const Timing t_le = time_it([&] { le = simulate_row(row, motion, contact, ad); }, 5);
  if (!reference) {
    std::printf(
        "2. lumped hc-linear, adaptive: %.4f s cpu per sample; pounding run %ld steps (%ld "
        "rejected, %ld events), free run %ld steps (%ld rejected)\n",
        t_le.cpu_s, le.pounding.steps, le.pounding.rejected, le.pounding.events, le.free.steps,
        le.free.rejected);
    return;
  }
  const Timing t_lf = time_it([&] { lf = simulate_row(row, motion, contact, fi); }, 1);
  std::vector<int> je, jf;
  for (const auto& s : le.sites) je.push_back(s.impacts);
  for (const auto& s : lf.sites) jf.push_back(s.impacts);
  std::printf(
      "\n2. the same pair, lumped hc-linear (k = 50 x 8.4e7 N/m, e = %g), full record; "
      "adaptive: %ld steps (%ld rejected), fixed: %ld steps\n",
      contact.params.e, le.pounding.steps, le.pounding.rejected, lf.pounding.steps);
  header();
  line("hc-linear 5+3 (adaptive)", t_le, t_lf, 1, compare(le, lf, je, jf));
}

constexpr long kSamples = 20;

CampaignStudy load_campaign(const std::string& src, long samples) {
  Options oc("campaign", "speed benchmark", campaign_option_specs());
  const std::string frag = src + "/studies/fragility-default.ini";
  // A fixed workload: the eight stripes the study had when docs/speed.md was measured (the
  // study now has twelve, up to 1.5 g), elastic storeys and no free vibration after the
  // record, as the study was before issue 16 (case 4 measures it as it is now).
  oc.parse({"--config", frag, "--intensity.levels", "0.05,0.1,0.15,0.2,0.3,0.4,0.5,0.6",
            "--simulation.extra_time", "0"});
  CampaignStudy study = campaign_from_options(oc, samples, -1);
  // Elastic storeys: without the deteriorating storeys' sampled parameters (each parameter
  // draws from its own stream, so the others' values are unchanged).
  for (auto& b : study.row.buildings) b.hysteresis = "elastic";
  auto& ps = study.parameters;
  ps.erase(
      std::remove_if(
          ps.begin(), ps.end(),
          [](const SampledParameter& p) {
            for (const char* k : {"plastic_drift_ratio", "post_cap_drift_ratio", "energy_capacity"})
              if (p.key.find(k) != std::string::npos) return true;
            return false;
          }),
      ps.end());
  return study;
}

// The same study on the fixed-step reference path.
CampaignStudy reference_of(const CampaignStudy& study) {
  CampaignStudy ref = study;
  ref.integrator.control = StepControl::fixed;
  ref.integrator.dt = kReferenceDt;
  ref.sears.stepping = sears::SearsStepping::fixed;
  ref.sears.dt_s = kReferenceDt;
  return ref;
}

// Largest relative differences of run e from run r: floor displacement, drift, floor
// acceleration, site force, slab face and centre acceleration (d[0..5]); the same impacts.
struct SearsDifferences {
  double d[6] = {0, 0, 0, 0, 0, 0};
  bool same_impacts = true;
};
SearsDifferences sears_differences(const sears::SearsRowSimulation& e,
                                   const sears::SearsRowSimulation& r) {
  SearsDifferences x;
  double* d = x.d;
  for (std::size_t i = 0; i < r.base.floors.size(); ++i) {
    d[0] = std::max(d[0], rel(e.base.floors[i].disp_pounding, r.base.floors[i].disp_pounding));
    d[1] = std::max(d[1], rel(e.base.floors[i].peak_drift_ratio_pounding,
                              r.base.floors[i].peak_drift_ratio_pounding));
    d[2] = std::max(d[2], rel(e.base.floors[i].accel_pounding, r.base.floors[i].accel_pounding));
  }
  for (std::size_t k = 0; k < r.base.sites.size(); ++k) {
    d[3] = std::max(d[3], rel(e.base.sites[k].peak_force, r.base.sites[k].peak_force));
    x.same_impacts = x.same_impacts && e.contacts[k].impacts == r.contacts[k].impacts;
  }
  for (std::size_t k = 0; k < r.slabs.size(); ++k) {
    d[4] = std::max(d[4], rel(e.slabs[k].face_accel, r.slabs[k].face_accel));
    d[5] = std::max(d[5], rel(e.slabs[k].centre_accel, r.slabs[k].centre_accel));
  }
  return x;
}

// The longer steps through smooth contact forces (docs/speed.md): the event path at several
// values of sears.contact_step_tolerance against the fixed 10 us path.
void contact_step_study(const BuildingRow& row, const GroundMotion& motion,
                        sears::SearsRowModel model) {
  sears::SearsRowModel ref = model;
  ref.stepping = sears::SearsStepping::fixed;
  ref.dt_s = kReferenceDt;
  sears::SearsRowSimulation r;
  const Timing t_ref = time_it([&] { r = sears::simulate_sears_row(row, motion, ref); }, 1);
  model.stepping = sears::SearsStepping::event;
  std::printf(
      "event path vs the fixed path at %g s (chapter 8, sears N = %d, %.2f s, %.3f s cpu); "
      "largest relative differences over floors, sites and slabs\n",
      kReferenceDt, model.modes, motion.duration(), t_ref.cpu_s);
  std::printf("%9s %9s %8s %8s %8s %8s %9s %9s %9s %9s %9s %9s %8s\n", "tolerance", "cpu[s]",
              "speed-up", "steps", "longer", "again", "disp", "drift", "floor acc", "force",
              "face acc", "centre acc", "same imp");
  for (double tol : {0.0, 3e-4, 1e-3, 3e-3}) {
    model.contact_step_tolerance = tol;
    sears::SearsRowSimulation e;
    const Timing t = time_it([&] { e = sears::simulate_sears_row(row, motion, model); }, 3);
    const SearsDifferences x = sears_differences(e, r);
    const double* d = x.d;
    const sears::SearsStepCounts& c = e.counts_pounding;
    std::printf(
        "%9g %9.4f %8.1f %8ld %8ld %8ld %8.3f%% %8.3f%% %8.3f%% %8.3f%% %8.3f%% %8.3f%% %8s\n", tol,
        t.cpu_s, t_ref.cpu_s / t.cpu_s, c.fine + c.coarse, c.long_steps, c.long_step_rejections,
        100 * d[0], 100 * d[1], 100 * d[2], 100 * d[3], 100 * d[4], 100 * d[5],
        x.same_impacts ? "yes" : "NO");
  }
}

// Convergence of the event path in its fine step (docs/speed.md, "Fine step"): chapter 8, full
// record, fine steps h_c / r for r = 11 (T_min / 20, the former automatic step) down to 3,
// against the fixed path at 10 us: the largest relative differences per quantity.
void fine_step_study(const BuildingRow& row, const GroundMotion& motion,
                     sears::SearsRowModel model) {
  sears::SearsRowModel ref = model;
  ref.stepping = sears::SearsStepping::fixed;
  ref.dt_s = kReferenceDt;
  const sears::SearsRowSimulation r = sears::simulate_sears_row(row, motion, ref);
  model.stepping = sears::SearsStepping::event;
  model.dt_s = 0.0;
  const sears::SearsSteps automatic = sears::sears_row_steps(row, motion.dt, model);
  std::printf(
      "fine step of the event path vs the fixed path at %g s (chapter 8, sears N = %d, %.2f s); "
      "coarse step %.4g s, automatic fine step %.4g s (ratio %ld); largest relative "
      "differences over floors, sites and slabs\n",
      kReferenceDt, model.modes, motion.duration(), automatic.coarse_s, automatic.fine_s,
      automatic.ratio);
  std::printf("%6s %11s %8s %9s %9s %9s %9s %9s %9s %9s %8s\n", "ratio", "fine dt[s]", "T_min/dt",
              "cpu[s]", "disp", "drift", "floor acc", "force", "face acc", "centre acc",
              "same imp");
  double w_max = 0.0;  // the highest modal frequency retained over the colliding floors
  for (const auto& f : sears::make_layout(row, assemble(row), model).floors)
    w_max =
        std::max(w_max, sears::floor_slab(row, model, f.building, f.floor - 1).omega(model.modes));
  const double t_min = 2.0 * M_PI / w_max;
  for (long ratio : {11L, 8L, 6L, 5L, 4L, 3L, 2L}) {
    model.dt_s = automatic.coarse_s / static_cast<double>(ratio);
    sears::SearsRowSimulation e;
    const Timing t = time_it([&] { e = sears::simulate_sears_row(row, motion, model); }, 1);
    const SearsDifferences x = sears_differences(e, r);
    const double* d = x.d;
    std::printf("%6ld %11.4g %8.1f %9.4f %8.3f%% %8.3f%% %8.3f%% %8.3f%% %8.3f%% %8.3f%% %8s\n",
                ratio, model.dt_s, t_min / model.dt_s, t.cpu_s, 100 * d[0], 100 * d[1], 100 * d[2],
                100 * d[3], 100 * d[4], 100 * d[5], x.same_impacts ? "yes" : "NO");
  }
}

// 4. Yielding buildings (issue 16): samples of the default study as it is (inelastic storeys),
// the same samples with every storey elastic, and the inelastic samples on the fixed-step
// reference; per contact model the cost ratio inelastic / elastic (whole sample, and without
// generating the motion) and the largest differences from the reference.
void inelastic_case(const std::string& src, long samples) {
  Options oc("campaign", "speed benchmark", campaign_option_specs());
  oc.parse({"--config", src + "/studies/fragility-default.ini"});
  const CampaignStudy study = campaign_from_options(oc, samples, -1);
  CampaignStudy elastic = study;
  for (auto& b : elastic.row.buildings) b.hysteresis = "elastic";
  const CampaignStudy ref = reference_of(study);
  SampleRunner run_i(study), run_e(elastic), run_f(ref);
  SimqkeGenerator gen(*study.spectrum, study.motion_duration, study.generator);
  std::printf(
      "\n4. yielding buildings: studies/fragility-default.ini as it is (storeys %s), %ld "
      "samples, against the same samples with elastic storeys and against the fixed step %g s\n",
      study.row.buildings[0].hysteresis.c_str(), samples, kReferenceDt);
  std::printf("%4s %-10s %8s %9s %10s %10s %10s %8s %8s %8s %8s %8s\n", "id", "model", "PGA[g]",
              "max duct", "cpu[s]", "elast[s]", "motion[s]", "ref[s]", "d disp", "d drift",
              "d force", "same imp");
  struct Sum {
    int n = 0;
    double inel = 0, el = 0, motion = 0;
    Differences worst;
  } sums[2];  // 0 sears, 1 lumped
  for (long id = 0; id < samples; ++id) {
    SampleOutcome oi, oe, of;
    const Timing ti = time_it([&] { oi = run_i.run(id); }, 3);
    const Timing te = time_it([&] { oe = run_e.run(id); }, 3);
    const Timing tf = time_it([&] { of = run_f.run(id); }, 1);
    const Timing tm = time_it([&] { gen.generate(run_i.draw(id).motion_seed, 0); }, 3);
    const std::string model = run_i.draw(id).model;
    Sum& sum = sums[is_sears_model(model) ? 0 : 1];
    ++sum.n;
    sum.inel += ti.cpu_s;
    sum.el += te.cpu_s;
    sum.motion += tm.cpu_s;
    Differences x;
    auto cmp = [&](const std::vector<double>& p, const std::vector<double>& q, double& out) {
      for (std::size_t i = 0; i < p.size(); ++i)
        if (std::isfinite(p[i]) && std::isfinite(q[i])) out = std::max(out, rel(p[i], q[i]));
    };
    cmp(oi.disp_pounding, of.disp_pounding, x.disp);
    cmp(oi.peak_drift_ratio_pounding, of.peak_drift_ratio_pounding, x.drift);
    cmp(oi.peak_force, of.peak_force, x.force);
    for (std::size_t k = 0; k < oi.impacts.size(); ++k)
      if (std::isfinite(oi.impacts[k])) x.same_impacts &= oi.impacts[k] == of.impacts[k];
    double duct = 0.0;
    for (std::size_t k = 0; k < oi.peak_drift_ratio_pounding.size(); ++k)
      if (std::isfinite(oi.peak_drift_ratio_pounding[k])) {
        const std::size_t b = k / static_cast<std::size_t>(study.max_floors()),
                          j = k % static_cast<std::size_t>(study.max_floors());
        const Building& bd = study.row.buildings[b];
        if (!bd.yield_shears.empty())
          duct = std::max(duct, oi.peak_drift_ratio_pounding[k] * bd.storey_heights[j] /
                                    bd.storey(static_cast<int>(j)).uy());
      }
    std::printf("%4ld %-10s %8.3f %9.2f %10.4f %10.4f %10.4f %8.3f %7.3f%% %7.3f%% %7.3f%% %8s%s\n",
                id, model.c_str(), oi.im / 9.80665, duct, ti.cpu_s, te.cpu_s, tm.cpu_s, tf.cpu_s,
                100 * x.disp, 100 * x.drift, 100 * x.force, x.same_impacts ? "yes" : "NO",
                oi.status == SampleStatus::ok && of.status == SampleStatus::ok ? "" : "  (failed)");
    sum.worst.disp = std::max(sum.worst.disp, x.disp);
    sum.worst.drift = std::max(sum.worst.drift, x.drift);
    sum.worst.force = std::max(sum.worst.force, x.force);
    sum.worst.same_impacts = sum.worst.same_impacts && x.same_impacts;
  }
  for (int k = 0; k < 2; ++k) {
    const Sum& m = sums[k];
    if (!m.n) continue;
    std::printf(
        "  %-10s %2d samples: inelastic %.4f s, elastic %.4f s per sample: ratio %.2f (%.2f "
        "without the motion, %.4f s); vs reference: disp %.3f%%, drift %.3f%%, force %.3f%%, "
        "same impacts %s\n",
        k == 0 ? "sears" : "hc-linear", m.n, m.inel / m.n, m.el / m.n, m.inel / m.el,
        (m.inel - m.motion) / (m.el - m.motion), m.motion / m.n, 100 * m.worst.disp,
        100 * m.worst.drift, 100 * m.worst.force, m.worst.same_impacts ? "yes" : "NO");
  }
}

// Issue 13: the cost of a sample of studies/fragility-default.ini as it is (spectral
// variability: each motion matched to its own random target) and with variability none, per
// contact model, split into generating the motion (timed apart, the same draws as the sample)
// and the rest (both simulations, with and without pounding). Process CPU times, the smallest
// of `repeat` runs per sample.
void samples_case(const std::string& src, long samples, int repeat, const std::string& only = "",
                  const std::string& variabilities = "spectral,none",
                  const std::vector<std::string>& overrides = {}) {
  std::printf(
      "\n5. sample cost: studies/fragility-default.ini, samples 0-%ld, process CPU time, the "
      "smallest of %d runs each\n",
      samples - 1, repeat);
  std::printf("%-10s %-10s %4s %10s %10s %10s %10s %10s %8s\n", "motions", "model", "n",
              "sample[ms]", "max[ms]", "motion[ms]", "rest[ms]", "rest max", "spectra");
  for (const std::string variability : {"spectral", "none"}) {
    if (variabilities.find(variability) == std::string::npos) continue;
    Options oc("campaign", "speed benchmark", campaign_option_specs());
    std::vector<std::string> args = {"--config", src + "/studies/fragility-default.ini",
                                     "--generator.variability", variability};
    args.insert(args.end(), overrides.begin(), overrides.end());
    oc.parse(args);
    const CampaignStudy study = campaign_from_options(oc, samples, -1);
    SampleRunner runner(study);
    SimqkeGenerator gen(*study.spectrum, study.motion_duration, study.generator);
    const TargetVariability var(study.variability, gen.match_periods());
    struct Sum {
      int n = 0;
      double sample = 0, motion = 0, max_sample = 0, max_rest = 0;
      long spectra = 0;
    } sums[2];  // 0 sears, 1 lumped
    for (long id = 0; id < samples; ++id) {
      const SampleDraw d = runner.draw(id);
      if (!only.empty() && d.model != only) continue;
      const Timing ts = time_it([&] { runner.run(d); }, repeat);
      GeneratedMotion g;
      const Timing tm = time_it(
          [&] {
            g = d.spectral_epsilon.empty()
                    ? gen.generate(d.motion_seed, 0)
                    : gen.generate(d.motion_seed, 0, var.ln_factor(d.spectral_epsilon));
          },
          repeat);
      Sum& m = sums[is_sears_model(d.model) ? 0 : 1];
      ++m.n;
      m.sample += ts.cpu_s;
      m.motion += tm.cpu_s;
      m.spectra += g.spectra;
      m.max_sample = std::max(m.max_sample, ts.cpu_s);
      m.max_rest = std::max(m.max_rest, ts.cpu_s - tm.cpu_s);
    }
    for (int k = 0; k < 2; ++k) {
      const Sum& m = sums[k];
      if (!m.n) continue;
      std::printf("%-10s %-10s %4d %10.3f %10.3f %10.3f %10.3f %10.3f %8.1f\n", variability.c_str(),
                  k == 0 ? "sears" : "hc-linear", m.n, 1e3 * m.sample / m.n, 1e3 * m.max_sample,
                  1e3 * m.motion / m.n, 1e3 * (m.sample - m.motion) / m.n, 1e3 * m.max_rest,
                  double(m.spectra) / m.n);
    }
  }
}

// Cases 7 and 8: the cost of a sample of `study` as it is against the same sample with
// `baseline` (the other keys' draws are the same: every parameter has its own stream), per
// contact model, process CPU time of SampleRunner::run (the motions' generation included) and
// the same without one motion's generation (SimqkeGenerator, the uniform case's motion).
//   7. ssi (issue 29): studies/ssi-soft-soil.ini (Gazetas footings since issue 38; cones before)
//   against fixed bases;
//   8. svgm (issue 28): studies/svgm-identical-pair.ini on spatially varying ground (two
//      coherent stations, wave passage) against one motion under both (which never pounds);
//      svgm-apart: the same two, and the default pair as in svgm-default, with a 1 m gap on
//      both sides (neither pounds: one run each, the price of the ground alone);
//      svgm-default: the default study's pair with v = 500 m/s and Harichandran-Vanmarcke
//      against the study as it is (both pound).
void compare_case(const char* title, const std::string& src, const std::string& study_file,
                  const std::vector<std::string>& extra, const std::vector<std::string>& baseline,
                  long samples, int repeat, const std::string& only, const std::string& which) {
  std::printf(
      "\n%s: %s, samples 0-%ld, process CPU time, the smallest of %d runs each; 'rest': without "
      "one motion's generation\n",
      title, study_file.c_str(), samples - 1, repeat);
  auto load = [&](const std::vector<std::string>& keys) {
    Options oc("campaign", "speed benchmark", campaign_option_specs());
    std::vector<std::string> args = {"--config", src + "/" + study_file};
    args.insert(args.end(), keys.begin(), keys.end());
    oc.parse(args);
    return campaign_from_options(oc, samples, -1);
  };
  const CampaignStudy with = load(extra), base = load(baseline);
  auto kinds = [](const CampaignStudy& c) {  // contact sites: slab-to-slab, slab-to-column
    int slab = 0, column = 0;
    for (const ContactSite& site : assemble(c.row).sites) ++(site.column() ? column : slab);
    return std::to_string(slab) + " slab + " + std::to_string(column) + " column sites";
  };
  std::printf("base: %s; with: %s\n", kinds(base).c_str(), kinds(with).c_str());
  std::printf("%-10s %4s %10s %10s %7s %10s %10s %7s %7s\n", "model", "n", "base[ms]", "with[ms]",
              "ratio", "base rest", "with rest", "ratio", "worst");
  SampleRunner rw(with), rb(base);
  SimqkeGenerator gen(*base.spectrum, base.motion_duration, base.generator);
  const TargetVariability var(base.variability, gen.match_periods());
  struct Sum {
    int n = 0;
    double base = 0, with = 0, motion = 0, worst = 0;
  } sums[2];  // 0 sears, 1 lumped
  for (long id = 0; id < samples; ++id) {
    const SampleDraw dw = rw.draw(id), db = rb.draw(id);
    if (!only.empty() && dw.model != only) continue;
    const Timing tm = time_it(
        [&] {
          db.spectral_epsilon.empty()
              ? gen.generate(db.motion_seed, 0)
              : gen.generate(db.motion_seed, 0, var.ln_factor(db.spectral_epsilon));
        },
        repeat);
    const double tw = which == "base" ? 0.0 : time_it([&] { rw.run(dw); }, repeat).cpu_s;
    const double tb = which == "with" ? 0.0 : time_it([&] { rb.run(db); }, repeat).cpu_s;
    Sum& m = sums[is_sears_model(dw.model) ? 0 : 1];
    ++m.n;
    m.with += tw;
    m.base += tb;
    m.motion += tm.cpu_s;
    m.worst = std::max(m.worst, (tw - tm.cpu_s) / std::max(tb - tm.cpu_s, 1e-6));
    if (std::getenv("POUND_BENCH_SAMPLES"))  // each sample's line, to find the slow ones
      std::printf("  sample %3ld %-10s base %8.3f ms, with %8.3f ms\n", id, dw.model.c_str(),
                  1e3 * tb, 1e3 * tw);
  }
  for (int k = 0; k < 2; ++k) {
    const Sum& m = sums[k];
    if (!m.n) continue;
    std::printf("%-10s %4d %10.3f %10.3f %7.2f %10.3f %10.3f %7.2f %7.2f\n",
                k == 0 ? "sears" : "lumped", m.n, 1e3 * m.base / m.n, 1e3 * m.with / m.n,
                m.with / m.base, 1e3 * (m.base - m.motion) / m.n, 1e3 * (m.with - m.motion) / m.n,
                (m.with - m.motion) / (m.base - m.motion), m.worst);
  }
}

}  // namespace

int run(int argc, char** argv) {
  const std::string src = argc > 1 ? argv[1] : POUND_SOURCE_DIR;
  const std::string ch8 = src + "/studies/ch8-five-three.ini";
  std::printf("speed benchmark (issue 8): default integrators vs fixed dt = %g s, one core\n",
              kReferenceDt);

  if (argc > 3 && std::string(argv[2]) == "sample") {  // diagnostics of one campaign sample
    const CampaignStudy study = load_campaign(src, kSamples);
    const CampaignStudy ref = reference_of(study);
    const long id = std::stol(argv[3]);
    if (id < 0 || id >= kSamples) {
      std::fprintf(stderr, "bench_speed: sample %ld: valid: 0..%ld (case 3's campaign)\n", id,
                   kSamples - 1);
      return 2;
    }
    CampaignStudy auto_fixed = study;
    auto_fixed.sears.stepping = sears::SearsStepping::fixed;
    auto_fixed.integrator = ref.integrator;
    const CampaignStudy* studies[] = {&study, &auto_fixed, &ref};
    const char* names[] = {"default", "fixed, automatic step", "fixed 1e-5"};
    for (int k = 0; k < 3; ++k) {
      SampleRunner runner(*studies[k]);
      const SampleOutcome o = runner.run(id);
      std::printf("%-22s force [N]:", names[k]);
      for (double f : o.peak_force) std::printf(" %.6g", f);
      std::printf("  impacts:");
      for (double f : o.impacts) std::printf(" %g", f);
      std::printf("\n");
    }
    const SampleDraw d = SampleRunner(study).draw(id);
    std::printf("model %s, values:", d.model.c_str());
    for (double v : d.values) std::printf(" %g", v);
    std::printf("\n");
    return 0;
  }
  if (argc > 2 && std::string(argv[2]) == "samples") {  // case 5 alone
    // Further arguments are study options (e.g. --integrator.h_max 0.01).
    samples_case(src, argc > 3 ? std::stol(argv[3]) : 48, argc > 4 ? std::stoi(argv[4]) : 3,
                 argc > 5 ? argv[5] : "", argc > 6 ? argv[6] : "spectral,none",
                 std::vector<std::string>(argv + std::min(argc, 7), argv + argc));
    return 0;
  }
  const std::string mode = argc > 2 ? argv[2] : "";
  if (mode == "ssi" || mode == "svgm" || mode == "svgm-apart" || mode == "svgm-default") {
    const std::vector<std::string> uniform = {
        "--ground.apparent_velocity",        "inf", "--ground.coherency", "none",
        "--sample.ground.apparent_velocity", "none"};
    const std::vector<std::string> fixed = {
        "--building1.foundation",       "fixed", "--building2.foundation", "fixed",
        "--sample.soil_shear_velocity", "none",  "--sample.soil_density",  "none",
        "--sample.soil_poisson",        "none"};
    const std::vector<std::string> varying = {"--ground.apparent_velocity", "500",
                                              "--ground.coherency", "harichandran-vanmarcke-1986"};
    const long n = argc > 3 ? std::stol(argv[3]) : 30;
    const int repeat = argc > 4 ? std::stoi(argv[4]) : 2;
    const std::string only = argc > 5 && std::string(argv[5]) != "all" ? argv[5] : "";
    const std::string which = argc > 6 ? argv[6] : "both";
    if (mode == "ssi")
      compare_case("7. SSI (Gazetas footings on soft soil) against fixed bases", src,
                   "studies/ssi-soft-soil.ini", {}, fixed, n, repeat, only, which);
    else if (mode == "svgm")
      compare_case("8. spatially varying ground against one motion under both", src,
                   "studies/svgm-identical-pair.ini", {}, uniform, n, repeat, only, which);
    else if (mode == "svgm-apart") {
      // The same work on both sides: a gap so wide (1 m) that neither ever pounds, so each
      // sample is one run, and what remains is the price of the ground itself.
      const std::vector<std::string> apart = {"--sample.gap", "none", "--pair1.gap", "1"};
      std::vector<std::string> uniform_apart = uniform;
      uniform_apart.insert(uniform_apart.end(), apart.begin(), apart.end());
      compare_case("8. spatially varying ground against one motion, neighbours 1 m apart", src,
                   "studies/svgm-identical-pair.ini", apart, uniform_apart, n, repeat, only, which);
      std::vector<std::string> varying_apart = varying;
      varying_apart.insert(varying_apart.end(), apart.begin(), apart.end());
      compare_case("8. the default pair on spatially varying ground against one motion, 1 m apart",
                   src, "studies/fragility-default.ini", varying_apart, apart, n, repeat, only,
                   which);
    } else
      compare_case("8. the default pair on spatially varying ground against one motion", src,
                   "studies/fragility-default.ini", varying, {}, n, repeat, only, which);
    return 0;
  }
  if (mode == "offset") {  // issue 36: slab-to-column sites against slab-to-slab ones
    const long n = argc > 3 ? std::stol(argv[3]) : 30;
    const int repeat = argc > 4 ? std::stoi(argv[4]) : 2;
    const std::string only = argc > 5 && std::string(argv[5]) != "all" ? argv[5] : "";
    compare_case(
        "9. offset floors (six slab-to-column sites) against the same pair with aligned floors "
        "(three slab-to-slab sites)",
        src, "studies/offset-floors.ini", {}, {"--building2.base_elevation", "0"}, n, repeat, only,
        "both");
    // The same pair with as many sites either way (issue 36's benchmark): on a 10.5 m terrace
    // the 3-storey's floors (13.5, 16.5, 19.5 m) meet the 5-storey's top storey once, and the
    // 5-storey's floors 4 and 5 (12, 15 m) meet the 3-storey's first two storeys: three
    // slab-to-column sites against the aligned pair's three slab-to-slab ones.
    compare_case(
        "10. the 3-storey on a 10.5 m terrace (three slab-to-column sites) against the aligned "
        "pair (three slab-to-slab sites)",
        src, "studies/offset-floors.ini", {"--building2.base_elevation", "10.5"},
        {"--building2.base_elevation", "0"}, n, repeat, only, "both");
    return 0;
  }
  if (mode == "split")  // case 10: buildings on their own steps (issue 38)
    return split_case(src, std::vector<std::string>(argv + 3, argv + argc));
  if (argc > 2 && std::string(argv[2]) == "collapse")  // case 6 alone
    return collapse_case(src, std::vector<std::string>(argv + 3, argv + argc));
  if (argc > 2 && std::string(argv[2]) == "inelastic") {  // case 4 alone
    inelastic_case(src, argc > 3 ? std::stol(argv[3]) : 24);
    return 0;
  }
  // 1. Chapter 8, sears, N = 100, the full record.
  const Options o1 = row_study(ch8, {"--motion.duration", "1e9"});
  const BuildingRow row = row_from_options(o1);
  const GroundMotion motion = motion_from_options(o1);
  if (argc > 2 && std::string(argv[2]) == "lumped") {  // case 2 alone
    lumped_case(ch8, row, motion, argc > 3 && std::string(argv[3]) == "check");
    return 0;
  }
  sears::SearsRowModel ev = sears_row_from_options(o1, row), fx = ev;
  ev.stepping = sears::SearsStepping::event;
  fx.stepping = sears::SearsStepping::fixed;
  fx.dt_s = kReferenceDt;
  if (argc > 2 && std::string(argv[2]) == "fine-step") {  // the step rule's evidence
    fine_step_study(row, motion, sears_row_from_options(o1, row));
    return 0;
  }
  if (argc > 2 && std::string(argv[2]) == "contact-steps") {
    contact_step_study(row, motion, sears_row_from_options(o1, row));
    return 0;
  }
  sears::SearsRowSimulation se, sf;
  const Timing t_se = time_it([&] { se = sears::simulate_sears_row(row, motion, ev); }, 3);
  if (argc > 2 && std::string(argv[2]) == "quick") {
    std::printf(
        "chapter 8, event: %.4f s cpu; pounding run %ld fine (%ld with a contact force) "
        "+ %ld coarse; slab sleeps %ld, wakes %ld; dormant runs %ld, slab steps skipped %ld, "
        "wakes %ld\n",
        t_se.cpu_s, se.counts_pounding.fine, se.counts_pounding.fine_in_contact,
        se.counts_pounding.coarse, se.counts_pounding.slab_sleeps, se.counts_pounding.slab_wakes,
        se.counts_pounding.dormant_runs, se.counts_pounding.dormant_slab_steps,
        se.counts_pounding.dormant_wakes);
    return 0;
  }
  const Timing t_sf = time_it([&] { sf = sears::simulate_sears_row(row, motion, fx); }, 1);
  std::vector<int> ie, ifx;
  for (const auto& c : se.contacts) ie.push_back(c.impacts);
  for (const auto& c : sf.contacts) ifx.push_back(c.impacts);
  std::printf(
      "\n1. chapter 8 example, sears N = 100, %s, %.2f s; event: fine %.3g s, coarse "
      "%.3g s; pounding run %ld fine (%ld with a contact force) + %ld coarse steps + %ld steps of "
      "the lumped solver's grid in %ld stretches without contact (%ld fine steps longer, %ld "
      "solved again shorter; bound violations %ld; slabs put to sleep %ld times, %ld woken early; "
      "%ld slab coarse steps skipped by dormant slabs); free run: the lumped solver's\n",
      motion.name.c_str(), motion.duration(), se.dt_s, se.coarse_dt_s, se.counts_pounding.fine,
      se.counts_pounding.fine_in_contact, se.counts_pounding.coarse, se.counts_pounding.lumped,
      se.counts_pounding.lumped_stretches, se.counts_pounding.long_steps,
      se.counts_pounding.long_step_rejections, se.counts_pounding.bound_violations,
      se.counts_pounding.slab_sleeps, se.counts_pounding.slab_wakes,
      se.counts_pounding.dormant_slab_steps);
  header();
  line("sears ch8 (event)", t_se, t_sf, 1, compare(se.base, sf.base, ie, ifx));
  std::printf(
      "  impacts: phases above %g of the site's peak force per floor; raw phases "
      "%d/%d/%d (event) vs %d/%d/%d (fixed)\n",
      ev.impact_force_fraction, se.base.sites[0].impacts, se.base.sites[1].impacts,
      se.base.sites[2].impacts, sf.base.sites[0].impacts, sf.base.sites[1].impacts,
      sf.base.sites[2].impacts);
  double d_face = 0.0, d_centre = 0.0;  // peak slab accelerations, largest relative difference
  for (std::size_t k = 0; k < se.slabs.size(); ++k) {
    d_face = std::max(d_face, rel(se.slabs[k].face_accel, sf.slabs[k].face_accel));
    d_centre = std::max(d_centre, rel(se.slabs[k].centre_accel, sf.slabs[k].centre_accel));
  }
  std::printf(
      "  peak slab accelerations (sampled at step ends): largest difference %.3f%% at the "
      "contact faces, %.3f%% at the slab centres\n",
      100.0 * d_face, 100.0 * d_centre);
  std::printf("  peak force per floor [kN]: event %.2f/%.2f/%.2f, fixed %.2f/%.2f/%.2f\n",
              se.base.sites[0].peak_force / 1e3, se.base.sites[1].peak_force / 1e3,
              se.base.sites[2].peak_force / 1e3, sf.base.sites[0].peak_force / 1e3,
              sf.base.sites[1].peak_force / 1e3, sf.base.sites[2].peak_force / 1e3);

  if (argc > 2 && std::string(argv[2]) == "ch8") return 0;  // case 1 alone
  lumped_case(ch8, row, motion, true);

  // 3. A 20-sample campaign of the default fragility study (half sears N = 40, half hc-linear).
  const CampaignStudy study = load_campaign(src, kSamples);
  const CampaignStudy ref = reference_of(study);
  std::vector<SampleOutcome> ce(kSamples), cf(kSamples);
  SampleRunner run_e(study), run_f(ref);
  std::printf(
      "\n3. campaign: studies/fragility-default.ini, %ld samples (SampleRunner, one "
      "core)\n",
      kSamples);
  // Each sample generates its own spectrum-compatible motion; timed apart here (same seeds).
  SimqkeGenerator gen(*study.spectrum, study.motion_duration, study.generator);
  double cpu_motion = 0.0;
  std::printf("%4s %-10s %8s %10s %10s %10s %8s %8s %8s %8s  %s\n", "id", "model", "PGA[g]",
              "cpu[s]", "motion[s]", "ref cpu[s]", "d disp", "d drift", "d force", "same imp",
              "impacts default | reference");
  Timing t_ce, t_cf;
  Differences worst;
  int models_sears = 0;
  double cpu_sears = 0.0, cpu_lumped = 0.0, max_sears = 0.0, max_lumped = 0.0;
  for (long id = 0; id < kSamples; ++id) {
    const Timing a = time_it([&] { ce[id] = run_e.run(id); }, 1);
    const Timing b = time_it([&] { cf[id] = run_f.run(id); }, 1);
    const Timing m = time_it([&] { gen.generate(run_e.draw(id).motion_seed, 0); }, 1);
    cpu_motion += m.cpu_s;
    t_ce.cpu_s += a.cpu_s;
    t_ce.wall_s += a.wall_s;
    t_cf.cpu_s += b.cpu_s;
    t_cf.wall_s += b.wall_s;
    const std::string model = run_e.draw(id).model;
    if (is_sears_model(model)) {
      ++models_sears;
      cpu_sears += a.cpu_s;
      max_sears = std::max(max_sears, a.cpu_s);
    } else {
      cpu_lumped += a.cpu_s;
      max_lumped = std::max(max_lumped, a.cpu_s);
    }
    Differences x;
    const SampleOutcome &e = ce[id], &f = cf[id];
    auto cmp = [&](const std::vector<double>& p, const std::vector<double>& q, double& out) {
      for (std::size_t i = 0; i < p.size(); ++i)
        if (std::isfinite(p[i]) && std::isfinite(q[i])) out = std::max(out, rel(p[i], q[i]));
    };
    cmp(e.disp_pounding, f.disp_pounding, x.disp);
    cmp(e.peak_drift_ratio_pounding, f.peak_drift_ratio_pounding, x.drift);
    cmp(e.peak_force, f.peak_force, x.force);
    for (std::size_t s = 0; s < e.impacts.size(); ++s) {
      if (!std::isfinite(e.impacts[s])) continue;
      x.impacts_default += (s ? "/" : "") + std::to_string(long(e.impacts[s]));
      x.impacts_reference += (s ? "/" : "") + std::to_string(long(f.impacts[s]));
      x.same_impacts = x.same_impacts && e.impacts[s] == f.impacts[s];
    }
    std::printf("%4ld %-10s %8.3f %10.4f %10.4f %10.3f %7.3f%% %7.3f%% %7.3f%% %8s  %s | %s%s\n",
                id, model.c_str(), e.im / 9.80665, a.cpu_s, m.cpu_s, b.cpu_s, 100 * x.disp,
                100 * x.drift, 100 * x.force, x.same_impacts ? "yes" : "NO",
                x.impacts_default.c_str(), x.impacts_reference.c_str(),
                e.status == SampleStatus::ok && f.status == SampleStatus::ok ? "" : "  (failed)");
    worst.disp = std::max(worst.disp, x.disp);
    worst.drift = std::max(worst.drift, x.drift);
    worst.force = std::max(worst.force, x.force);
    worst.same_impacts = worst.same_impacts && x.same_impacts;
  }
  worst.impacts_default = worst.impacts_reference = "(per sample above)";
  header();
  line("campaign, 20 samples", t_ce, t_cf, kSamples, worst);
  std::printf(
      "  per sample: sears (%d) mean %.4f s, max %.4f s; hc-linear (%ld) mean %.4f s, "
      "max %.4f s (cpu)\n",
      models_sears, models_sears ? cpu_sears / models_sears : 0.0, max_sears,
      kSamples - models_sears,
      kSamples > models_sears ? cpu_lumped / (kSamples - models_sears) : 0.0, max_lumped);
  std::printf(
      "  of which generating the sample's motion (SIMQKE, %g s at %g s): mean %.4f s "
      "(column motion[s])\n",
      study.motion_duration, study.generator.dt, cpu_motion / kSamples);
  inelastic_case(src, 24);
  samples_case(src, 48, 3);
  return collapse_case(src, {});
}

int main(int argc, char** argv) {
  if (argc > 1 && argv[1][0] == '-') {
    std::printf(
        "usage: bench_speed [SOURCE [quick | lumped [check] | sample ID | inelastic [N] | samples "
        "[N [REPEAT [MODEL [spectral|none]]]] | collapse ... | ssi|svgm|svgm-apart|svgm-default [N "
        "[REPEAT "
        "[MODEL|all [with|base]]]] | offset [N [REPEAT [MODEL|all]]] | ch8 | fine-step | "
        "contact-steps | split STUDY [N [REPEAT [--key value ...]]]]]\n(SOURCE: the source tree "
        "whose studies/ are timed; the cases are described at the top of bench/speed_bench.cpp)\n");
    return 0;
  }
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_speed: error: %s\n", e.what());
    return 2;
  }
}

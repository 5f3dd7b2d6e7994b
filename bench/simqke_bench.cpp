// Acceptance benchmark of the SIMQKE generator (issue 4): seven 20 s motions at dt = 0.01 s
// for Eurocode 8 Type 1, ground C, ag = 0.35 g, and for NZS 1170.5 class C, Z = 0.4, R = 1.
// Every motion's 5 %-damped spectrum must lie within 0.90-1.20 of the target at 100
// log-spaced periods from 0.05 to 4 s (sub-steps of T/20), the mean within 0.95-1.05, final
// velocity under 1 cm/s and final displacement under 1 cm. Prints the figures and the time
// per motion ("set" is the phase set of the returned motion, 0 = first draw; "iter" its
// correction iterations); exit code 0 when everything passes. Usage: bench_simqke [seed]
//
// Record-to-record variability (issue 12): bench_simqke variability [count] [none|spectral]
// generates `count` (default 40) motions of the default study's target (EC8 type 1, ground C,
// ag = 0.3 g; 10 s at 0.01 s; seed 2026), each once matched to the design spectrum and once to
// its random target (Boore-Atkinson 2008 sigma, Baker-Jayaram 2008 correlation), the two
// interleaved motion by motion so that a changing machine load hits both alike; it prints the
// time per motion, the correction iterations of the returned motion and how closely each
// motion matches its own target ("cpu ms": process CPU time, "spectra": spectrum evaluations
// per motion, every phase set counted). With none or spectral only that variant runs (for
// instruction counts: valgrind --tool=callgrind bench_simqke variability 20 spectral).
//
// Issue 13: bench_simqke kernel times the response-spectrum kernel alone per instruction set.
//
// Issue 28: bench_simqke stations [count] times StationGenerator for S = 2, 4 and 8 stations 20 m
// apart (Harichandran-Vanmarcke SMART-1 coherency; the default study's target, 10 s at 0.01 s,
// seed 2026, `count` motions, default 20) against SimqkeGenerator's one motion, and prints the
// ratio cost(S stations) / (S x cost(one motion)) in process CPU time and in spectrum
// evaluations (the target: at most 1.5); then the same for 2 stations with random targets
// (record-to-record variability, the campaigns' default), with each station's evaluations.
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <tuple>
#include <vector>

#include "ground/station_generator.hpp"
#include "motion/motion_processing.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/simqke.hpp"
#include "motion/spectral_variability.hpp"
#include "motion/spectrum_ec8.hpp"
#include "motion/spectrum_nzs1170.hpp"

namespace {

bool run(const pound::DesignSpectrum& target, std::uint64_t seed) {
  using namespace pound;
  constexpr int kMotions = 7;
  const double duration = 20.0;
  SimqkeSettings settings;
  settings.dt = 0.01;
  const std::vector<double> periods = log_spaced_periods(0.05, 4.0, 100);
  const std::vector<double> tgt = target.sample(periods);
  const SpectrumCalculator check(periods, 0.05, settings.dt);

  std::printf("\n%s\n", target.describe().c_str());
  std::printf("%-6s %6s %6s %6s %8s %10s %10s %4s %4s %8s\n", "motion", "min", "max", "mean",
              "PGA[g]", "vend[cm/s]", "dend[cm]", "set", "iter", "time[ms]");
  const auto t_plan = std::chrono::steady_clock::now();
  SimqkeGenerator gen(target, duration, settings);
  const double plan_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_plan).count();
  std::vector<double> mean(periods.size(), 0.0);
  bool ok = true;
  double total_ms = 0.0, max_ms = 0.0;
  for (int i = 0; i < kMotions; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const GeneratedMotion g = gen.generate(seed, std::uint64_t(i));
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    total_ms += ms;
    const ResponseSpectrum rs = check.compute(g.motion.accel);
    for (std::size_t j = 0; j < periods.size(); ++j) mean[j] += rs.psa[j] / kMotions;
    const SpectrumMatch m = compare_spectra(rs.psa, tgt);
    const bool pass = m.min_ratio >= 0.90 && m.max_ratio <= 1.20 &&
                      std::fabs(g.final_velocity) < 0.01 && std::fabs(g.final_displacement) < 0.01;
    ok = ok && pass;
    max_ms = std::max(max_ms, ms);
    std::printf("%-6d %6.3f %6.3f %6.3f %8.3f %10.2e %10.2e %4d %4d %8.1f %s\n", i, m.min_ratio,
                m.max_ratio, m.mean_ratio, g.motion.pga() / kGravity, 100 * g.final_velocity,
                100 * g.final_displacement, g.attempt, g.iterations, ms, pass ? "ok" : "FAIL");
  }
  const SpectrumMatch mm = compare_spectra(mean, tgt);
  const bool mean_ok = mm.min_ratio >= 0.95 && mm.max_ratio <= 1.05;
  ok = ok && mean_ok;
  std::printf("%-6s %6.3f %6.3f %6.3f %s\n", "mean", mm.min_ratio, mm.max_ratio, mm.mean_ratio,
              mean_ok ? "ok" : "FAIL");
  std::printf("time per motion %.1f ms mean, %.1f ms max (one core; generator set-up %.2f ms)\n",
              total_ms / kMotions, max_ms, plan_ms);
  return ok;
}

// Process CPU time [ms]: robust on a shared machine, where wall times also count the time the
// process waits for a core.
double cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

struct VariantStats {
  double ms = 0.0, max_ms = 0.0, cpu = 0.0;
  long spectra = 0;
  long iterations = 0;
  std::vector<double> max_dev, rms;  // max |ln q| and RMS ln q against the own target
};

void add(VariantStats& v, const pound::GeneratedMotion& g, const pound::SpectrumCalculator& check,
         double ms, double cpu) {
  v.ms += ms;
  v.cpu += cpu;
  v.spectra += g.spectra;
  v.max_ms = std::max(v.max_ms, ms);
  v.iterations += g.iterations;
  const std::vector<double> psa = check.compute(g.motion.accel).psa;
  double mx = 0.0, ss = 0.0;
  for (std::size_t j = 0; j < psa.size(); ++j) {
    const double lq = std::log(psa[j] / g.target_psa[j]);
    mx = std::max(mx, std::fabs(lq));
    ss += lq * lq;
  }
  v.max_dev.push_back(mx);
  v.rms.push_back(std::sqrt(ss / double(psa.size())));
}

double median(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x.empty() ? 0.0 : x[x.size() / 2];
}

double quantile90(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  return x.empty() ? 0.0 : x[std::min(x.size() - 1, x.size() * 9 / 10)];
}

int run_variability(int count, const std::string& only) {
  using namespace pound;
  const Ec8Spectrum target(Ec8Type::type1, Ec8Ground::C, 0.3 * kGravity);
  SimqkeSettings settings;
  SimqkeGenerator gen(target, 10.0, settings);
  VariabilitySettings vs;
  vs.mode = Variability::spectral;
  const TargetVariability var(vs, gen.match_periods());
  const CounterRng rng(2026, stream_id(kTargetStream));
  const SpectrumCalculator check(gen.match_periods(), 0.05, settings.dt);
  const bool run_none = only != "spectral", run_spectral = only != "none";
  VariantStats none, spectral;
  using clock = std::chrono::steady_clock;
  for (int i = 0; i < count; ++i) {
    if (run_none) {
      const auto t0 = clock::now();
      const double c0 = cpu_ms();
      const GeneratedMotion g = gen.generate(2026, std::uint64_t(i));
      const double c1 = cpu_ms();
      add(none, g, check, std::chrono::duration<double, std::milli>(clock::now() - t0).count(),
          c1 - c0);
    }
    if (run_spectral) {
      const auto t0 = clock::now();
      const double c0 = cpu_ms();
      const GeneratedMotion g =
          gen.generate(2026, std::uint64_t(i), var.ln_factor(var.epsilon(rng, std::uint64_t(i))));
      const double c1 = cpu_ms();
      add(spectral, g, check, std::chrono::duration<double, std::milli>(clock::now() - t0).count(),
          c1 - c0);
    }
  }
  std::printf("\n%s, 10 s at 0.01 s, %d motions, seed 2026\n", target.describe().c_str(), count);
  std::printf("%-9s %9s %9s %9s %10s %8s %21s %21s\n", "target", "cpu ms", "ms mean", "ms max",
              "iter mean", "spectra", "max|ln q| med / p90", "rms ln q med / p90");
  for (const auto& [name, v, on] :
       {std::tuple<const char*, const VariantStats&, bool>{"design", none, run_none},
        {"random", spectral, run_spectral}}) {
    if (!on) continue;
    std::printf("%-9s %9.2f %9.2f %9.2f %10.1f %8.1f %10.3f / %7.3f %10.3f / %7.3f\n", name,
                v.cpu / count, v.ms / count, v.max_ms, double(v.iterations) / count,
                double(v.spectra) / count, median(v.max_dev), quantile90(v.max_dev), median(v.rms),
                quantile90(v.rms));
  }
  if (run_none && run_spectral)
    std::printf("time with variability / without: %.3f (cpu %.3f)\n", spectral.ms / none.ms,
                spectral.cpu / none.cpu);
  return 0;
}

// The spectrum kernel alone (issue 13): the generator's 110 matching periods of a 10 s motion
// at 0.01 s, process CPU time per spectrum on each instruction set this CPU has (the smallest
// of 5 rounds of 200 spectra; every path gives the same bits).
int run_kernel() {
  using namespace pound;
  const Ec8Spectrum target(Ec8Type::type1, Ec8Ground::C, 0.3 * kGravity);
  SimqkeGenerator gen(target, 10.0);
  const GroundMotion g = gen.generate(2026, 0).motion;
  std::printf("spectrum kernel: %zu periods (%.3f-%.2f s, T/20 peaks), %zu samples\n",
              gen.match_periods().size(), gen.match_periods().front(), gen.match_periods().back(),
              g.accel.size());
  std::vector<double> psa;
  const std::pair<SimdPath, const char*> paths[] = {
      {SimdPath::avx512, "AVX-512"}, {SimdPath::avx2, "AVX2+FMA"}, {SimdPath::baseline, "SSE2"}};
  for (const auto& [path, name] : paths) {
    if (!simd_path_available(path)) {
      std::printf("%-9s not on this CPU\n", name);
      continue;
    }
    ResponseSpectrumOptions o;
    o.simd = path;
    const SpectrumCalculator calc(gen.match_periods(), 0.05, 0.01, o);
    double best = 1e300;
    for (int r = 0; r < 5; ++r) {
      const double c0 = cpu_ms();
      for (int i = 0; i < 200; ++i) calc.compute_psa(g.accel, psa);
      best = std::min(best, (cpu_ms() - c0) / 200.0);
    }
    std::printf("%-9s %8.1f us per spectrum\n", name, 1e3 * best);
  }
  return 0;
}

int run_stations(int count) {
  using namespace pound;
  const Ec8Spectrum target(Ec8Type::type1, Ec8Ground::C, 0.3 * kGravity);
  const SimqkeSettings settings;
  SimqkeGenerator one(target, 10.0, settings);
  double one_cpu = 0.0;
  long one_spectra = 0;
  for (int i = 0; i < count; ++i) {
    const double c0 = cpu_ms();
    const GeneratedMotion g = one.generate(2026, std::uint64_t(i));
    one_cpu += cpu_ms() - c0;
    one_spectra += g.spectra;
  }
  std::printf("\n%s, 10 s at 0.01 s, %d motions, seed 2026\n", target.describe().c_str(), count);
  std::printf("one motion: %.2f ms cpu, %.1f spectra\n", one_cpu / count,
              double(one_spectra) / count);
  std::printf("%-8s %12s %10s %16s %18s\n", "stations", "cpu ms/set", "spectra", "cpu / (S one)",
              "spectra / (S one)");
  for (int s : {2, 4, 8}) {
    StationSettings st;
    for (int j = 0; j < s; ++j) st.positions.push_back(20.0 * j);
    st.coherency = make_coherency("harichandran-vanmarcke-1986", {}, "bench");
    const double c_setup = cpu_ms();
    StationGenerator gen(target, 10.0, settings, st);
    const double setup = cpu_ms() - c_setup;
    double cpu = 0.0;
    long spectra = 0;
    for (int i = 0; i < count; ++i) {
      const double c0 = cpu_ms();
      const std::vector<GeneratedMotion> g = gen.generate(2026, std::uint64_t(i));
      cpu += cpu_ms() - c0;
      for (const GeneratedMotion& m : g) spectra += m.spectra;
    }
    std::printf("%-8d %12.2f %10.1f %16.3f %18.3f   (set-up %.1f ms)\n", s, cpu / count,
                double(spectra) / count, cpu / (s * one_cpu),
                double(spectra) / (double(s) * double(one_spectra)), setup);
  }
  // The campaign's case: every sample a random target (record-to-record variability, issue 12,
  // Boore-Atkinson 2008 sigma, Baker-Jayaram 2008 correlation), one motion against two stations
  // 20 m apart, with the spectrum evaluations of each station.
  VariabilitySettings vs;
  vs.mode = Variability::spectral;
  const TargetVariability var(vs, one.match_periods());
  const CounterRng rng(2026, stream_id(kTargetStream));
  StationSettings st;
  st.positions = {0.0, 20.0};
  st.coherency = make_coherency("harichandran-vanmarcke-1986", {}, "bench");
  StationGenerator two(target, 10.0, settings, st);
  double cpu1 = 0.0, cpu2 = 0.0;
  long spectra1 = 0, spectra2[2] = {0, 0};
  for (int i = 0; i < count; ++i) {
    const std::vector<double> ln = var.ln_factor(var.epsilon(rng, std::uint64_t(i)));
    double c0 = cpu_ms();
    spectra1 += one.generate(2026, std::uint64_t(i), ln).spectra;
    cpu1 += cpu_ms() - c0;
    c0 = cpu_ms();
    const std::vector<GeneratedMotion> g = two.generate(2026, std::uint64_t(i), ln);
    cpu2 += cpu_ms() - c0;
    for (int j = 0; j < 2; ++j) spectra2[j] += g[std::size_t(j)].spectra;
  }
  std::printf(
      "random targets: one motion %.2f ms cpu, %.1f spectra; 2 stations %.2f ms cpu (%.3f x 2 "
      "motions), spectra %.1f + %.1f\n",
      cpu1 / count, double(spectra1) / count, cpu2 / count, cpu2 / (2.0 * cpu1),
      double(spectra2[0]) / count, double(spectra2[1]) / count);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "stations")
    return run_stations(argc > 2 ? std::atoi(argv[2]) : 20);
  if (argc > 1 && std::string(argv[1]) == "kernel") return run_kernel();
  if (argc > 1 && std::string(argv[1]) == "variability")
    return run_variability(argc > 2 ? std::atoi(argv[2]) : 40, argc > 3 ? argv[3] : "");
  const std::uint64_t seed = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 2026;
  using namespace pound;
  const Ec8Spectrum ec8(Ec8Type::type1, Ec8Ground::C, 0.35 * kGravity);
  const Nzs1170Spectrum nzs(NzsSiteClass::C, 0.4, 1.0);
  const bool a = run(ec8, seed);
  const bool b = run(nzs, seed);
  std::printf("\nacceptance: %s\n", a && b ? "PASS" : "FAIL");
  return a && b ? 0 : 1;
}

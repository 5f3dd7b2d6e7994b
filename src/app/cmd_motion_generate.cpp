// pound motion generate: spectrum-compatible motions (SIMQKE) into a folder.
//   pound motion generate --spectrum ... --count N --duration S --dt DT --seed K --out DIR
//       [--variability spectral --sigma-lnsa S | --sigma-table F | --sigma-model M
//        --correlation baker-jayaram-2008|none|full]
// Writes motion-NNN.txt and target-NNN.txt per motion and motions.h5, each whole or not at
// all, then prints how each motion matches its target (a table, or --json).
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/h5.hpp"
#include "io/json.hpp"
#include "io/options.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/simqke.hpp"
#include "motion/spectral_variability.hpp"
#include "motion/spectrum_factory.hpp"
#include "pound/version.hpp"

namespace pound::app {
namespace {

struct MotionReport {
  SpectrumMatch match;
  double pga = 0.0, v_end = 0.0, d_end = 0.0;  // [m/s^2], [m/s], [m]
  int iterations = 0, attempt = 0;
};

std::vector<OptionSpec> generate_specs() {
  std::vector<OptionSpec> specs = design_spectrum_option_specs();
  const std::vector<OptionSpec> own_specs = {
      {"count", "-", "1", "number of motions"},
      {"duration", "s", "20", "length of each motion"},
      {"dt", "s", "0.01", "sample spacing"},
      {"seed", "-", "1", "seed of the random phases (motion i uses stream (seed, i))"},
      {"out", "", "", "output folder: motion-000.txt ... and motions.h5"},
      {"envelope", "", "jennings", "intensity envelope: jennings or saragoni-hart"},
      {"rise", "s", "", "Jennings: end of the quadratic rise (default 0.1 duration)"},
      {"strong-end", "s", "", "Jennings: end of the strong phase (default 0.5 duration)"},
      {"decay", "1/s", "", "Jennings: exponential decay rate (default: 0.05 at the end)"},
      {"sh-epsilon", "-", "0.2", "Saragoni-Hart: time of the peak / duration"},
      {"sh-eta", "-", "0.05", "Saragoni-Hart: envelope at the end"},
      {"t-min", "s", "0.05", "shortest period of the match (and of the report)"},
      {"t-max", "s", "4", "longest period of the match (and of the report)"},
      {"n-periods", "-", "100", "log-spaced periods of the match"},
      {"max-iterations", "-", "35", "correction iterations per phase set"},
      {"json", "", "", "print the match report as one JSON object", true},
  };
  specs.insert(specs.end(), own_specs.begin(), own_specs.end());
  const std::vector<OptionSpec> var_specs = variability_option_specs('-');
  specs.insert(specs.end(), var_specs.begin(), var_specs.end());
  return specs;
}

// The generator's settings: step, envelope, matching periods and iterations.
SimqkeSettings generator_settings(const Options& o, double duration) {
  SimqkeSettings s;
  s.dt = o.get_positive("dt");
  if (!(duration >= 10.0 * s.dt)) throw o.invalid("duration", "valid: at least 10 dt");
  const std::string env = o.get_string("envelope");
  if (env == "saragoni-hart") {
    s.envelope.shape = EnvelopeShape::saragoni_hart;
    s.envelope.epsilon = o.get_positive("sh-epsilon");
    s.envelope.eta = o.get_positive("sh-eta");
  } else if (env != "jennings") {
    throw o.invalid("envelope", "valid: jennings or saragoni-hart");
  }
  if (o.given("rise")) s.envelope.rise = o.get_nonnegative("rise");
  if (o.given("strong-end")) s.envelope.strong_end = o.get_positive("strong-end");
  if (o.given("decay")) s.envelope.decay = o.get_positive("decay");
  s.match_t_min = o.get_positive("t-min");
  s.match_t_max = o.get_positive("t-max");
  if (!(s.match_t_max > s.match_t_min)) throw o.invalid("t-max", "valid: t-max > t-min");
  s.match_periods = int(o.get_int("n-periods"));
  if (s.match_periods < 2) throw o.invalid("n-periods", "valid: 2 or more");
  s.max_iterations = int(o.get_int("max-iterations"));
  if (s.max_iterations < 0) throw o.invalid("max-iterations", "valid: 0 or more");
  return s;
}

void write_text(const std::string& path, const GroundMotion& m, const std::string& header) {
  AtomicPath out(path);
  {
    std::ofstream f(out.temp());
    if (!f) throw InputError(path + ": cannot write; give a writable --out folder");
    f << header << "# units: g\n# dt: " << m.dt << " s\n# columns: time [s], acceleration [g]\n";
    char line[64];
    for (std::size_t i = 0; i < m.accel.size(); ++i) {
      std::snprintf(line, sizeof line, "%.4f %.9e\n", m.dt * double(i), m.accel[i] / kGravity);
      f << line;
    }
    if (!f) throw InputError(path + ": write failed");
  }
  out.commit();
}

// A motion's own target: period [s], Sa [g].
void write_target(const std::string& path, const std::vector<double>& periods,
                  const std::vector<double>& sa, const std::string& header) {
  AtomicPath out(path);
  {
    std::ofstream f(out.temp());
    if (!f) throw InputError(path + ": cannot write; give a writable --out folder");
    f << header << "# columns: period [s], Sa [g] (5 % damping pseudo-acceleration)\n";
    char line[64];
    for (std::size_t j = 0; j < periods.size(); ++j) {
      std::snprintf(line, sizeof line, "%.6f %.9e\n", periods[j], sa[j] / kGravity);
      f << line;
    }
    if (!f) throw InputError(path + ": write failed");
  }
  out.commit();
}

// What one run generated, at the report periods (the matching periods without the
// match_extend on either side), rows by motion.
struct GeneratedMotions {
  std::vector<double> periods;            ///< report periods [s]
  std::vector<double> design;             ///< the design spectrum there [m/s^2]
  std::vector<GroundMotion> motions;      ///< the motions
  std::vector<std::string> files;         ///< their text files
  std::vector<MotionReport> reports;      ///< each against its own target
  std::vector<double> psa, targets, eps;  ///< [motions x periods]: PSA, own target, eps
  std::vector<double> mean, geomean;      ///< of the motions' PSA [m/s^2]
  std::vector<double> sigma;              ///< sigma of ln Sa (with variability)
  bool variable = false;                  ///< random targets (--variability spectral)
};

// Generates `count` motions of `duration` into the folder `dir` (motion-NNN.txt and
// target-NNN.txt, each whole or not at all).
GeneratedMotions generate_motions(const DesignSpectrum& target, const SimqkeSettings& s,
                                  double duration, long count, long seed,
                                  const VariabilitySettings& variability, const std::string& dir) {
  GeneratedMotions out;
  SimqkeGenerator gen(target, duration, s);
  out.periods = log_spaced_periods(s.match_t_min, s.match_t_max, s.match_periods);
  const std::vector<double>& periods = out.periods;
  out.design = target.sample(periods);
  const SpectrumCalculator calc(periods, target.damping(), s.dt);
  const std::size_t off = std::size_t(s.match_extend);
  for (std::size_t j = 0; j < periods.size(); ++j)
    if (std::fabs(gen.match_periods()[off + j] / periods[j] - 1.0) > 1e-12)
      throw NumericalError("motion generate: report and matching periods differ");
  // Random targets: motion i draws eps from the stream (seed, "motion.spectrum"), index i.
  const TargetVariability var(variability, gen.match_periods());
  out.variable = var.enabled();
  if (out.variable)
    out.sigma.assign(var.sigma().begin() + long(off),
                     var.sigma().begin() + long(off + periods.size()));
  const CounterRng target_rng(std::uint64_t(seed), stream_id(kTargetStream));
  out.mean.assign(periods.size(), 0.0);
  std::vector<double> log_mean(periods.size(), 0.0);
  std::string header = "# pound motion generate (" + std::string(kVersion) + " " + kGitRevision +
                       ")\n# target: " + target.describe() + "\n";
  if (var.enabled()) header += "# variability: " + variability.describe() + "\n";
  for (long i = 0; i < count; ++i) {
    GeneratedMotion g;
    if (var.enabled()) {
      const std::vector<double> eps = var.epsilon(target_rng, std::uint64_t(i));
      g = gen.generate(std::uint64_t(seed), std::uint64_t(i), var.ln_factor(eps));
      out.eps.insert(out.eps.end(), eps.begin() + long(off),
                     eps.begin() + long(off + periods.size()));
    } else {
      g = gen.generate(std::uint64_t(seed), std::uint64_t(i));
    }
    const std::vector<double> own(g.target_psa.begin() + long(off),
                                  g.target_psa.begin() + long(off + periods.size()));
    out.targets.insert(out.targets.end(), own.begin(), own.end());
    std::vector<double> psa;
    calc.compute_psa(g.motion.accel, psa);
    MotionReport r;
    r.match = compare_spectra(psa, own);  // against the motion's own target
    for (std::size_t j = 0; j < psa.size(); ++j) log_mean[j] += std::log(psa[j]) / double(count);
    r.pga = g.motion.pga();
    r.v_end = g.final_velocity;
    r.d_end = g.final_displacement;
    r.iterations = g.iterations;
    r.attempt = g.attempt;
    for (std::size_t j = 0; j < psa.size(); ++j) out.mean[j] += psa[j] / double(count);
    out.psa.insert(out.psa.end(), psa.begin(), psa.end());
    char number[24];
    std::snprintf(number, sizeof number, "%03ld", i);
    const std::string motion_name = std::string("motion-") + number + ".txt";
    out.files.push_back((std::filesystem::path(dir) / motion_name).string());
    const std::string id =
        "# seed: " + std::to_string(seed) + ", index: " + std::to_string(i) + "\n";
    write_text(out.files.back(), g.motion, header + id);
    write_target((std::filesystem::path(dir) / (std::string("target-") + number + ".txt")).string(),
                 periods, own, header + id + "# the spectrum " + motion_name + " was matched to\n");
    out.reports.push_back(r);
    out.motions.push_back(std::move(g.motion));
  }
  for (double& x : log_mean) x = std::exp(x);
  out.geomean = std::move(log_mean);
  return out;
}

// One HDF5 file with every motion, its spectrum and the target: DIR/motions.h5.
void write_motions_file(const std::string& dir, const GeneratedMotions& g, double dt,
                        const DesignSpectrum& target, const VariabilitySettings& variability,
                        long seed, const Options& o) {
  const std::string h5path = (std::filesystem::path(dir) / "motions.h5").string();
  AtomicPath out(h5path);
  {
    h5::File f(out.temp());
    const std::size_t n = g.motions.front().accel.size(), np = g.periods.size();
    std::vector<double> acc, t(n), pga, vend, dend;
    std::vector<int> iters;
    for (std::size_t i = 0; i < n; ++i) t[i] = dt * double(i);
    for (std::size_t i = 0; i < g.motions.size(); ++i) {
      acc.insert(acc.end(), g.motions[i].accel.begin(), g.motions[i].accel.end());
      iters.push_back(g.reports[i].iterations);
      pga.push_back(g.reports[i].pga);
      vend.push_back(g.reports[i].v_end);
      dend.push_back(g.reports[i].d_end);
    }
    h5::write(f.id(), "/motions/time", t, n, 0, "s");
    h5::write(f.id(), "/motions/acceleration", acc, g.motions.size(), n, "m/s^2");
    h5::write(f.id(), "/motions/psa", g.psa, g.motions.size(), np, "m/s^2");
    h5::write(f.id(), "/motions/pga", pga, pga.size(), 0, "m/s^2");
    h5::write(f.id(), "/motions/final_velocity", vend, vend.size(), 0, "m/s");
    h5::write(f.id(), "/motions/final_displacement", dend, dend.size(), 0, "m");
    h5::write(f.id(), "/motions/iterations", iters);
    h5::write(f.id(), "/target/period", g.periods, np, 0, "s");
    h5::write(f.id(), "/target/psa", g.design, g.design.size(), 0, "m/s^2");
    h5::write(f.id(), "/target/mean_psa", g.mean, g.mean.size(), 0, "m/s^2");
    h5::write(f.id(), "/target/geomean_psa", g.geomean, g.geomean.size(), 0, "m/s^2");
    h5::write(f.id(), "/motions/target_psa", g.targets, g.motions.size(), np, "m/s^2");
    if (g.variable) {
      h5::write(f.id(), "/motions/epsilon", g.eps, g.motions.size(), np, "-");
      h5::write(f.id(), "/target/sigma_lnsa", g.sigma, g.sigma.size(), 0, "-");
    }
    h5::attribute(f.id(), "/", "variability", variability.describe());
    h5::attribute(f.id(), "/", "design_pga_mps2", target.sa(0.0));
    h5::attribute(f.id(), "/", "target", target.describe());
    h5::attribute(f.id(), "/", "damping", target.damping());
    h5::attribute(f.id(), "/", "seed", double(seed));
    h5::attribute(f.id(), "/", "config", o.resolved_text());
    h5::attribute(f.id(), "/", "engine_version", kVersion);
    h5::attribute(f.id(), "/", "git_revision", kGitRevision);
    f.close();
  }
  out.commit();
}

void field_ratios(JsonWriter& w, const char* key, const SpectrumMatch& m) {
  w.key(key)
      .begin_object()
      .field("min_ratio", m.min_ratio)
      .field("max_ratio", m.max_ratio)
      .field("mean_ratio", m.mean_ratio)
      .end_object();
}

void print_json(const GeneratedMotions& g, const DesignSpectrum& target,
                const VariabilitySettings& variability, const std::string& dir) {
  JsonWriter w;
  w.begin_object().field("target", target.describe()).field("out", dir);
  w.field("variability", variability.describe());
  w.key("motions").begin_array();
  for (std::size_t i = 0; i < g.reports.size(); ++i) {
    const MotionReport& r = g.reports[i];
    w.begin_object()
        .field("file", g.files[i])
        .field("min_ratio", r.match.min_ratio)
        .field("max_ratio", r.match.max_ratio)
        .field("mean_ratio", r.match.mean_ratio)
        .field("pga_g", r.pga / kGravity)
        .field("final_velocity_mps", r.v_end)
        .field("final_displacement_m", r.d_end)
        .field("iterations", r.iterations)
        .field("phase_set", r.attempt)
        .end_object();
  }
  w.end_array();
  field_ratios(w, "mean", compare_spectra(g.mean, g.design));
  field_ratios(w, "geometric_mean", compare_spectra(g.geomean, g.design));
  w.end_object();
  std::cout << w.str() << "\n";
}

void print_table(const GeneratedMotions& g, const DesignSpectrum& target,
                 const VariabilitySettings& variability, const SimqkeSettings& s, double duration,
                 const std::string& dir) {
  std::printf("# target: %s\n# %zu motions of %g s at %g s into %s (motion-NNN.txt, motions.h5)\n",
              target.describe().c_str(), g.motions.size(), duration, s.dt, dir.c_str());
  if (g.variable)
    std::printf(
        "# variability: %s\n# each motion against its own target (target-NNN.txt); "
        "mean and geomean of the motions against the design spectrum\n",
        variability.describe().c_str());
  std::printf("# computed / target over %d periods %g-%g s\n", s.match_periods, s.match_t_min,
              s.match_t_max);
  std::printf("%-8s %7s %7s %7s %8s %12s %12s %5s\n", "motion", "min", "max", "mean", "PGA [g]",
              "v_end [m/s]", "d_end [m]", "iter");
  for (std::size_t i = 0; i < g.reports.size(); ++i) {
    const MotionReport& r = g.reports[i];
    std::printf("%-8zu %7.3f %7.3f %7.3f %8.4f %12.3e %12.3e %5d\n", i, r.match.min_ratio,
                r.match.max_ratio, r.match.mean_ratio, r.pga / kGravity, r.v_end, r.d_end,
                r.iterations);
  }
  const SpectrumMatch mean_match = compare_spectra(g.mean, g.design);
  std::printf("%-8s %7.3f %7.3f %7.3f\n", "mean", mean_match.min_ratio, mean_match.max_ratio,
              mean_match.mean_ratio);
  if (g.variable) {
    const SpectrumMatch geomean_match = compare_spectra(g.geomean, g.design);
    std::printf("%-8s %7.3f %7.3f %7.3f\n", "geomean", geomean_match.min_ratio,
                geomean_match.max_ratio, geomean_match.mean_ratio);
  }
}

}  // namespace

int run_motion_generate(int argc, const char* const* argv) {
  Options o("motion generate", "Spectrum-compatible motions (Gasparini & Vanmarcke 1976).",
            generate_specs());
  if (help_asked(o, argc, argv)) return 0;
  const auto target = make_design_spectrum(o);
  const long count = o.get_int("count");
  if (count < 1 || count > 100000) throw o.invalid("count", "valid: 1 to 100000");
  const double duration = o.get_positive("duration");
  const long seed = o.get_int("seed");
  if (seed < 0) throw o.invalid("seed", "valid: a whole number >= 0");
  const std::string dir = o.get_string("out");
  const SimqkeSettings s = generator_settings(o, duration);
  const VariabilitySettings variability = variability_from_options(o, '-');
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError(o.where("out") + ": cannot create folder '" + dir + "': " + ec.message());
  const GeneratedMotions g = generate_motions(*target, s, duration, count, seed, variability, dir);
  write_motions_file(dir, g, s.dt, *target, variability, seed, o);
  if (o.flag("json"))
    print_json(g, *target, variability, dir);
  else
    print_table(g, *target, variability, s, duration, dir);
  return 0;
}

}  // namespace pound::app

// pound motion: response spectra of records, design spectra, spectrum-compatible generation.
//   pound motion spectrum --input FILE [--units g|m/s2|cm/s2] [--periods ...] [--json]
//   pound motion target --spectrum ec8|nzs1170|asce7|japan|table ... [--json]
//   pound motion generate --spectrum ... --count N --duration S --dt DT --seed K --out DIR
//       [--variability spectral --sigma-lnsa S | --sigma-table F | --sigma-model M
//        --correlation baker-jayaram-2008|none|full]
// Parses options, calls the motion library, prints; the files are written whole or not at all.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/h5.hpp"
#include "io/json.hpp"
#include "io/options.hpp"
#include "motion/motion_processing.hpp"
#include "motion/motion_reader.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/simqke.hpp"
#include "motion/spectral_variability.hpp"
#include "motion/spectrum_factory.hpp"
#include "pound/version.hpp"

namespace pound::app {
namespace {

constexpr const char* kUsage =
    "Usage: pound motion spectrum|target|generate [options]\n"
    "  spectrum  response spectra of a record (exact piecewise-linear recurrence)\n"
    "  target    a design spectrum (EC8, NZS 1170.5, ASCE 7, Japan BSL 2000, table)\n"
    "  generate  spectrum-compatible motions (SIMQKE) into a folder\n"
    "'pound motion SUBCOMMAND --help' lists the options with units and defaults.\n";

std::vector<OptionSpec> period_specs() {
  return {
      {"periods", "s", "", "periods, a list (default: 100 log-spaced from t-min to t-max)"},
      {"t-min", "s", "0.05", "shortest period of the default list"},
      {"t-max", "s", "4", "longest period of the default list"},
      {"n-periods", "-", "100", "number of periods of the default list"},
      {"json", "", "", "print one JSON object", true},
  };
}

std::vector<double> periods_of(const Options& o) {
  if (o.given("periods")) {
    const auto p = o.get_doubles("periods");
    for (double t : p)
      if (!(t >= 0.0)) throw o.invalid("periods", "valid: periods >= 0 s");
    return p;
  }
  const long n = o.get_int("n-periods");
  if (n < 2) throw o.invalid("n-periods", "valid: 2 or more");
  const double a = o.get_positive("t-min"), b = o.get_positive("t-max");
  if (!(b > a)) throw o.invalid("t-max", "valid: t-max > t-min");
  return log_spaced_periods(a, b, int(n));
}

void print_spectrum(const ResponseSpectrum& r, JsonWriter* json) {
  std::vector<double> psa_g, sa_g;
  for (double x : r.psa) psa_g.push_back(x / kGravity);
  for (double x : r.sa_abs) sa_g.push_back(x / kGravity);
  if (json) {
    json->key("damping").value(r.damping);
    json->key("period_s").array(r.period);
    json->key("sd_m").array(r.sd);
    json->key("psv_mps").array(r.psv);
    json->key("psa_g").array(psa_g);
    json->key("sa_abs_g").array(sa_g);
    return;
  }
  std::printf("%10s %12s %12s %10s %10s\n", "T [s]", "SD [m]", "PSV [m/s]", "PSA [g]",
              "SA abs [g]");
  for (std::size_t i = 0; i < r.period.size(); ++i)
    std::printf("%10.4f %12.5e %12.5e %10.5f %10.5f\n", r.period[i], r.sd[i], r.psv[i], psa_g[i],
                sa_g[i]);
}

Options parse(const std::string& sub, const std::string& summary, std::vector<OptionSpec> specs,
              int argc, const char* const* argv) {
  Options o("motion " + sub, summary, std::move(specs));
  o.parse(argc, argv);
  return o;
}

// --- pound motion spectrum ------------------------------------------------------------------

int run_spectrum(int argc, const char* const* argv) {
  std::vector<OptionSpec> specs = {
      {"input", "", "", "record file (PEER .AT2, one or two columns, fixed-width El Centro)"},
      {"format", "", "automatic", "automatic, at2, columns or fixed-width"},
      {"units", "", "", "units of the record when its header does not say: g, m/s2, cm/s2"},
      {"dt", "s", "", "sample spacing of a one-column record"},
      {"accept-any-pga", "", "",
       "accept a record whose peak acceleration is above 10 g or below 1e-6 g (refused by "
       "default as wrong units or values)",
       true},
      {"truncate", "s", "", "use only the first seconds of the record"},
      {"scale", "-", "1", "factor applied to the record"},
      {"baseline", "", "", "baseline-correct the record first", true},
      {"damping", "-", "0.05", "damping ratio of the oscillators, in [0, 1)"},
      {"substep", "-", "0.05", "largest step as a fraction of T (0: no sub-stepping)"},
  };
  for (auto& s : period_specs()) specs.push_back(s);
  const Options o =
      parse("spectrum", "Elastic response spectra of a record (Nigam & Jennings 1969).", specs,
            argc, argv);
  if (o.help_requested()) {
    std::cout << o.help_text();
    return 0;
  }
  MotionFileSpec spec;
  spec.path = o.get_string("input");
  spec.format = parse_motion_format(o.get_string("format"), o.where("format"));
  if (o.given("units")) spec.units = parse_accel_units(o.get_string("units"), o.where("units"));
  if (o.given("dt")) spec.dt = o.get_positive("dt");
  spec.check_pga = !o.flag("accept-any-pga");
  spec.check_pga_key = "--accept-any-pga";
  GroundMotion m = read_motion(spec);
  if (o.given("truncate")) m = truncate(m, o.get_positive("truncate"));
  m = scale(m, o.get_double("scale"));
  if (o.flag("baseline")) m = baseline_correct(m);
  const double damping = o.get_double("damping");
  if (!(damping >= 0.0 && damping < 1.0)) throw o.invalid("damping", "valid: 0 <= damping < 1");
  ResponseSpectrumOptions ro;
  ro.max_step_fraction = o.get_nonnegative("substep");
  const ResponseSpectrum r = response_spectrum(m, periods_of(o), damping, ro);
  if (o.flag("json")) {
    JsonWriter w;
    w.begin_object().field("input", spec.path).field("dt_s", m.dt);
    w.field("samples", long(m.accel.size())).field("pga_g", m.pga() / kGravity);
    w.field("substep_fraction", ro.max_step_fraction);
    print_spectrum(r, &w);
    w.end_object();
    std::cout << w.str() << "\n";
  } else {
    std::printf("# %s: %zu samples at %g s, PGA %.5f g, damping %g, sub-steps <= %g T\n",
                spec.path.c_str(), m.accel.size(), m.dt, m.pga() / kGravity, damping,
                ro.max_step_fraction);
    print_spectrum(r, nullptr);
  }
  return 0;
}

// --- pound motion target ----------------------------------------------------------------------

int run_target(int argc, const char* const* argv) {
  std::vector<OptionSpec> specs = design_spectrum_option_specs();
  for (auto& s : period_specs()) specs.push_back(s);
  const Options o = parse("target", "A design spectrum at a list of periods.", specs, argc, argv);
  if (o.help_requested()) {
    std::cout << o.help_text();
    return 0;
  }
  const auto target = make_design_spectrum(o);
  ResponseSpectrum r;
  r.damping = target->damping();
  r.period = periods_of(o);
  // A design spectrum gives the pseudo-acceleration; SD = Sa / w^2, PSV = Sa / w, and the
  // absolute acceleration is taken equal to the pseudo-acceleration.
  for (double T : r.period) {
    const double sa = target->sa(T), w = T > 0.0 ? 2.0 * M_PI / T : 0.0;
    r.psa.push_back(sa);
    r.sa_abs.push_back(sa);
    r.sd.push_back(w > 0.0 ? sa / (w * w) : 0.0);
    r.psv.push_back(w > 0.0 ? sa / w : 0.0);
  }
  if (o.flag("json")) {
    JsonWriter w;
    w.begin_object().field("spectrum", target->describe());
    print_spectrum(r, &w);
    w.end_object();
    std::cout << w.str() << "\n";
  } else {
    std::printf("# %s\n", target->describe().c_str());
    print_spectrum(r, nullptr);
  }
  return 0;
}

// --- pound motion generate --------------------------------------------------------------------

struct MotionReport {
  SpectrumMatch match;
  double pga = 0.0, v_end = 0.0, d_end = 0.0;  // [m/s^2], [m/s], [m]
  int iterations = 0, attempt = 0;
};

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

int run_generate(int argc, const char* const* argv) {
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
  const Options o = parse("generate", "Spectrum-compatible motions (Gasparini & Vanmarcke 1976).",
                          specs, argc, argv);
  if (o.help_requested()) {
    std::cout << o.help_text();
    return 0;
  }
  const auto target = make_design_spectrum(o);
  const long count = o.get_int("count");
  if (count < 1 || count > 100000) throw o.invalid("count", "valid: 1 to 100000");
  const double duration = o.get_positive("duration");
  const long seed = o.get_int("seed");
  if (seed < 0) throw o.invalid("seed", "valid: a whole number >= 0");
  const std::string dir = o.get_string("out");
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
  const VariabilitySettings variability = variability_from_options(o, '-');

  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw InputError(o.where("out") + ": cannot create folder '" + dir + "': " + ec.message());

  SimqkeGenerator gen(*target, duration, s);
  const std::vector<double> periods =
      log_spaced_periods(s.match_t_min, s.match_t_max, s.match_periods);
  const std::vector<double> tgt = target->sample(periods);
  const SpectrumCalculator calc(periods, target->damping(), s.dt);
  // The report periods are the matching periods without the match_extend on either side.
  const std::size_t off = std::size_t(s.match_extend);
  for (std::size_t j = 0; j < periods.size(); ++j)
    if (std::fabs(gen.match_periods()[off + j] / periods[j] - 1.0) > 1e-12)
      throw NumericalError("motion generate: report and matching periods differ");
  // Random targets: motion i draws eps from the stream (seed, "motion.spectrum"), index i.
  const TargetVariability var(variability, gen.match_periods());
  const CounterRng target_rng(std::uint64_t(seed), stream_id(kTargetStream));
  std::vector<GroundMotion> motions;
  std::vector<std::string> files;
  std::vector<MotionReport> reports;
  std::vector<double> all_psa, all_target, all_eps, mean(periods.size(), 0.0),
      log_mean(periods.size(), 0.0);
  std::string header = "# pound motion generate (" + std::string(kVersion) + " " + kGitRevision +
                       ")\n# target: " + target->describe() + "\n";
  if (var.enabled()) header += "# variability: " + variability.describe() + "\n";
  for (long i = 0; i < count; ++i) {
    GeneratedMotion g;
    if (var.enabled()) {
      const std::vector<double> eps = var.epsilon(target_rng, std::uint64_t(i));
      g = gen.generate(std::uint64_t(seed), std::uint64_t(i), var.ln_factor(eps));
      all_eps.insert(all_eps.end(), eps.begin() + long(off),
                     eps.begin() + long(off + periods.size()));
    } else {
      g = gen.generate(std::uint64_t(seed), std::uint64_t(i));
    }
    const std::vector<double> own(g.target_psa.begin() + long(off),
                                  g.target_psa.begin() + long(off + periods.size()));
    all_target.insert(all_target.end(), own.begin(), own.end());
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
    for (std::size_t j = 0; j < psa.size(); ++j) mean[j] += psa[j] / double(count);
    all_psa.insert(all_psa.end(), psa.begin(), psa.end());
    char number[24];
    std::snprintf(number, sizeof number, "%03ld", i);
    const std::string motion_name = std::string("motion-") + number + ".txt";
    files.push_back((std::filesystem::path(dir) / motion_name).string());
    const std::string id =
        "# seed: " + std::to_string(seed) + ", index: " + std::to_string(i) + "\n";
    write_text(files.back(), g.motion, header + id);
    write_target((std::filesystem::path(dir) / (std::string("target-") + number + ".txt")).string(),
                 periods, own, header + id + "# the spectrum " + motion_name + " was matched to\n");
    reports.push_back(r);
    motions.push_back(std::move(g.motion));
  }
  const SpectrumMatch mean_match = compare_spectra(mean, tgt);
  for (double& x : log_mean) x = std::exp(x);
  const SpectrumMatch geomean_match = compare_spectra(log_mean, tgt);

  // One HDF5 file with every motion, its spectrum and the target.
  const std::string h5path = (std::filesystem::path(dir) / "motions.h5").string();
  AtomicPath out(h5path);
  {
    h5::File f(out.temp());
    const std::size_t n = motions.front().accel.size();
    std::vector<double> acc, t(n), pga, vend, dend;
    std::vector<int> iters;
    for (std::size_t i = 0; i < n; ++i) t[i] = s.dt * double(i);
    for (std::size_t i = 0; i < motions.size(); ++i) {
      acc.insert(acc.end(), motions[i].accel.begin(), motions[i].accel.end());
      iters.push_back(reports[i].iterations);
      pga.push_back(reports[i].pga);
      vend.push_back(reports[i].v_end);
      dend.push_back(reports[i].d_end);
    }
    h5::write(f.id(), "/motions/time", t, n, 0, "s");
    h5::write(f.id(), "/motions/acceleration", acc, motions.size(), n, "m/s^2");
    h5::write(f.id(), "/motions/psa", all_psa, motions.size(), periods.size(), "m/s^2");
    h5::write(f.id(), "/motions/pga", pga, pga.size(), 0, "m/s^2");
    h5::write(f.id(), "/motions/final_velocity", vend, vend.size(), 0, "m/s");
    h5::write(f.id(), "/motions/final_displacement", dend, dend.size(), 0, "m");
    h5::write(f.id(), "/motions/iterations", iters);
    h5::write(f.id(), "/target/period", periods, periods.size(), 0, "s");
    h5::write(f.id(), "/target/psa", tgt, tgt.size(), 0, "m/s^2");
    h5::write(f.id(), "/target/mean_psa", mean, mean.size(), 0, "m/s^2");
    h5::write(f.id(), "/target/geomean_psa", log_mean, log_mean.size(), 0, "m/s^2");
    h5::write(f.id(), "/motions/target_psa", all_target, motions.size(), periods.size(), "m/s^2");
    if (var.enabled()) {
      h5::write(f.id(), "/motions/epsilon", all_eps, motions.size(), periods.size(), "-");
      std::vector<double> sig(var.sigma().begin() + long(off),
                              var.sigma().begin() + long(off + periods.size()));
      h5::write(f.id(), "/target/sigma_lnsa", sig, sig.size(), 0, "-");
    }
    h5::attribute(f.id(), "/", "variability", variability.describe());
    h5::attribute(f.id(), "/", "design_pga_mps2", target->sa(0.0));
    h5::attribute(f.id(), "/", "target", target->describe());
    h5::attribute(f.id(), "/", "damping", target->damping());
    h5::attribute(f.id(), "/", "seed", double(seed));
    h5::attribute(f.id(), "/", "config", o.resolved_text());
    h5::attribute(f.id(), "/", "engine_version", kVersion);
    h5::attribute(f.id(), "/", "git_revision", kGitRevision);
    f.close();
  }
  out.commit();

  if (o.flag("json")) {
    JsonWriter w;
    w.begin_object().field("target", target->describe()).field("out", dir);
    w.field("variability", variability.describe());
    w.key("motions").begin_array();
    for (std::size_t i = 0; i < reports.size(); ++i) {
      const MotionReport& r = reports[i];
      w.begin_object()
          .field("file", files[i])
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
    w.key("mean")
        .begin_object()
        .field("min_ratio", mean_match.min_ratio)
        .field("max_ratio", mean_match.max_ratio)
        .field("mean_ratio", mean_match.mean_ratio)
        .end_object();
    w.key("geometric_mean")
        .begin_object()
        .field("min_ratio", geomean_match.min_ratio)
        .field("max_ratio", geomean_match.max_ratio)
        .field("mean_ratio", geomean_match.mean_ratio)
        .end_object();
    w.end_object();
    std::cout << w.str() << "\n";
    return 0;
  }
  std::printf("# target: %s\n# %ld motions of %g s at %g s into %s (motion-NNN.txt, motions.h5)\n",
              target->describe().c_str(), count, duration, s.dt, dir.c_str());
  if (var.enabled())
    std::printf(
        "# variability: %s\n# each motion against its own target (target-NNN.txt); "
        "mean and geomean of the motions against the design spectrum\n",
        variability.describe().c_str());
  std::printf("# computed / target over %d periods %g-%g s\n", s.match_periods, s.match_t_min,
              s.match_t_max);
  std::printf("%-8s %7s %7s %7s %8s %12s %12s %5s\n", "motion", "min", "max", "mean", "PGA [g]",
              "v_end [m/s]", "d_end [m]", "iter");
  for (std::size_t i = 0; i < reports.size(); ++i) {
    const MotionReport& r = reports[i];
    std::printf("%-8zu %7.3f %7.3f %7.3f %8.4f %12.3e %12.3e %5d\n", i, r.match.min_ratio,
                r.match.max_ratio, r.match.mean_ratio, r.pga / kGravity, r.v_end, r.d_end,
                r.iterations);
  }
  std::printf("%-8s %7.3f %7.3f %7.3f\n", "mean", mean_match.min_ratio, mean_match.max_ratio,
              mean_match.mean_ratio);
  if (var.enabled())
    std::printf("%-8s %7.3f %7.3f %7.3f\n", "geomean", geomean_match.min_ratio,
                geomean_match.max_ratio, geomean_match.mean_ratio);
  return 0;
}

}  // namespace

int run_motion(int argc, const char* const* argv) {
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  const std::string sub = argv[1];
  if (sub == "spectrum") return run_spectrum(argc - 1, argv + 1);
  if (sub == "target") return run_target(argc - 1, argv + 1);
  if (sub == "generate") return run_generate(argc - 1, argv + 1);
  throw InputError("unknown subcommand '" + sub + "'; valid: spectrum, target, generate");
}

}  // namespace pound::app

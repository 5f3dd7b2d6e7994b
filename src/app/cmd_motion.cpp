// pound motion: response spectra of records, design spectra, spectrum-compatible generation.
//   pound motion spectrum --input FILE [--units g|m/s2|cm/s2] [--periods ...] [--json]
//   pound motion target --spectrum ec8|nzs1170|asce7|japan|table ... [--json]
//   pound motion generate ... (cmd_motion_generate.cpp)
// Parses options, calls the motion library, prints.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "core/error.hpp"
#include "io/json.hpp"
#include "io/options.hpp"
#include "motion/motion_processing.hpp"
#include "motion/motion_reader.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/spectrum_factory.hpp"

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
  Options o("motion spectrum", "Elastic response spectra of a record (Nigam & Jennings 1969).",
            specs);
  if (help_asked(o, argc, argv)) return 0;
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
  Options o("motion target", "A design spectrum at a list of periods.", specs);
  if (help_asked(o, argc, argv)) return 0;
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

}  // namespace

int run_motion(int argc, const char* const* argv) {
  if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
    std::cout << kUsage;
    return argc < 2 ? 2 : 0;
  }
  const std::string sub = argv[1];
  if (sub == "spectrum") return run_spectrum(argc - 1, argv + 1);
  if (sub == "target") return run_target(argc - 1, argv + 1);
  if (sub == "generate") return run_motion_generate(argc - 1, argv + 1);
  throw InputError("unknown subcommand '" + sub + "'; valid: spectrum, target, generate");
}

}  // namespace pound::app

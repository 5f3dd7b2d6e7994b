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
#include "motion/spectrum_options.hpp"

namespace pound::app {
namespace {

constexpr const char* kUsage =
    "Usage: pound motion spectrum|target|generate [options]\n"
    "  spectrum  response spectra of a record (exact piecewise-linear recurrence)\n"
    "  target    a design spectrum (EC8, NZS 1170.5, ASCE 7, Japan BSL 2000, table)\n"
    "  generate  spectrum-compatible motions (SIMQKE) into a folder\n"
    "'pound motion SUBCOMMAND --help' lists the options with units and defaults.\n";

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
  Options o("motion spectrum", "Elastic response spectra of a record (Nigam & Jennings 1969).",
            record_spectrum_option_specs());
  if (help_asked(o, argc, argv)) return 0;
  const MotionFileSpec spec = record_file_spec(o, "--accept-any-pga");
  const GroundMotion m = processed_record(o, read_motion(spec));
  const SpectrumSettings ss = spectrum_settings_from_options(o);
  const ResponseSpectrumOptions& ro = ss.options;
  const ResponseSpectrum r = response_spectrum(m, periods_from_options(o), ss.damping, ro);
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
                spec.path.c_str(), m.accel.size(), m.dt, m.pga() / kGravity, ss.damping,
                ro.max_step_fraction);
    print_spectrum(r, nullptr);
  }
  return 0;
}

// --- pound motion target ----------------------------------------------------------------------

int run_target(int argc, const char* const* argv) {
  std::vector<OptionSpec> specs = design_spectrum_option_specs();
  for (auto& s : period_option_specs()) specs.push_back(s);
  Options o("motion target", "A design spectrum at a list of periods.", specs);
  if (help_asked(o, argc, argv)) return 0;
  const auto target = make_design_spectrum(o);
  const ResponseSpectrum r = design_response_spectrum(*target, periods_from_options(o));
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

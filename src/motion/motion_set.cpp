#include "motion/motion_set.hpp"

#include <cmath>
#include <utility>

#include "core/error.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/spectrum_factory.hpp"
#include "sampling/counter_rng.hpp"

namespace pound {

std::vector<OptionSpec> motion_set_option_specs() {
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

namespace {

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

}  // namespace

MotionSetRequest motion_set_from_options(const Options& o) {
  MotionSetRequest r;
  r.target = make_design_spectrum(o);
  r.count = o.get_int("count");
  if (r.count < 1 || r.count > 100000) throw o.invalid("count", "valid: 1 to 100000");
  r.duration = o.get_positive("duration");
  r.seed = o.get_int("seed");
  if (r.seed < 0) throw o.invalid("seed", "valid: a whole number >= 0");
  r.settings = generator_settings(o, r.duration);
  r.variability = variability_from_options(o, '-');
  return r;
}

MotionSet generate_motion_set(const MotionSetRequest& request) {
  const DesignSpectrum& target = *request.target;
  const SimqkeSettings& s = request.settings;
  const long count = request.count, seed = request.seed;
  MotionSet out;
  SimqkeGenerator gen(target, request.duration, s);
  out.periods = log_spaced_periods(s.match_t_min, s.match_t_max, s.match_periods);
  const std::vector<double>& periods = out.periods;
  out.design = target.sample(periods);
  const SpectrumCalculator calc(periods, target.damping(), s.dt);
  const std::size_t off = std::size_t(s.match_extend);
  for (std::size_t j = 0; j < periods.size(); ++j)
    if (std::fabs(gen.match_periods()[off + j] / periods[j] - 1.0) > 1e-12)
      throw NumericalError("motion generate: report and matching periods differ");
  // Random targets: motion i draws eps from the stream (seed, "motion.spectrum"), index i.
  const TargetVariability var(request.variability, gen.match_periods());
  out.variable = var.enabled();
  if (out.variable)
    out.sigma.assign(var.sigma().begin() + long(off),
                     var.sigma().begin() + long(off + periods.size()));
  const CounterRng target_rng(std::uint64_t(seed), stream_id(kTargetStream));
  out.mean.assign(periods.size(), 0.0);
  std::vector<double> log_mean(periods.size(), 0.0);
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
    out.reports.push_back(r);
    out.motions.push_back(std::move(g.motion));
  }
  for (double& x : log_mean) x = std::exp(x);
  out.geomean = std::move(log_mean);
  return out;
}

}  // namespace pound

#include "motion/spectrum_options.hpp"

#include "motion/motion_processing.hpp"

namespace pound {

std::vector<OptionSpec> period_option_specs() {
  return {
      {"periods", "s", "", "periods, a list (default: 100 log-spaced from t-min to t-max)"},
      {"t-min", "s", "0.05", "shortest period of the default list"},
      {"t-max", "s", "4", "longest period of the default list"},
      {"n-periods", "-", "100", "number of periods of the default list"},
      {"json", "", "", "print one JSON object", true},
  };
}

std::vector<double> periods_from_options(const Options& o) {
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

std::vector<OptionSpec> record_spectrum_option_specs() {
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
  for (auto& s : period_option_specs()) specs.push_back(s);
  return specs;
}

MotionFileSpec record_file_spec(const Options& o, const std::string& check_pga_key) {
  MotionFileSpec spec;
  spec.path = o.get_string("input");
  spec.format = parse_motion_format(o.get_string("format"), o.where("format"));
  if (o.given("units")) spec.units = parse_accel_units(o.get_string("units"), o.where("units"));
  if (o.given("dt")) spec.dt = o.get_positive("dt");
  spec.check_pga = !o.flag("accept-any-pga");
  spec.check_pga_key = check_pga_key;
  return spec;
}

GroundMotion processed_record(const Options& o, GroundMotion m) {
  if (o.given("truncate")) m = truncate(m, o.get_positive("truncate"));
  m = scale(m, o.get_double("scale"));
  if (o.flag("baseline")) m = baseline_correct(m);
  return m;
}

SpectrumSettings spectrum_settings_from_options(const Options& o) {
  SpectrumSettings s;
  s.damping = o.get_double("damping");
  if (!(s.damping >= 0.0 && s.damping < 1.0)) throw o.invalid("damping", "valid: 0 <= damping < 1");
  s.options.max_step_fraction = o.get_nonnegative("substep");
  return s;
}

}  // namespace pound

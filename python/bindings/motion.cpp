// _engine's motion calls: reading a record, the response spectrum of an array, a design
// spectrum and a set of spectrum-compatible motions, with the options and checks of
// `pound motion spectrum|target|generate` (motion/spectrum_options.hpp, motion/motion_set.hpp).
#include "engine.hpp"
#include "motion/motion_reader.hpp"
#include "motion/motion_set.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/spectrum_factory.hpp"
#include "motion/spectrum_options.hpp"

namespace pound::python {
namespace {

std::vector<OptionSpec> target_specs() {
  std::vector<OptionSpec> specs = design_spectrum_option_specs();
  for (auto& s : period_option_specs()) specs.push_back(s);
  return specs;
}

py::dict spectrum_arrays(const ResponseSpectrum& r) {
  py::dict d;
  d["damping"] = r.damping;
  d["period_s"] = to_array(r.period);
  d["sd_m"] = to_array(r.sd);
  d["psv_mps"] = to_array(r.psv);
  d["psa_mps2"] = to_array(r.psa);
  d["sa_abs_mps2"] = to_array(r.sa_abs);
  return d;
}

// The record of `pound motion spectrum`'s file keys: (dt [s], accel [m/s^2], name).
py::tuple read_record(const std::vector<std::string>& args, const std::string& check_pga_key) {
  GroundMotion m;
  {
    py::gil_scoped_release release;
    CLocale c_locale;
    const Options o = parse_options("motion spectrum", record_spectrum_option_specs(), args);
    m = processed_record(o, read_motion(record_file_spec(o, check_pga_key)));
  }
  return py::make_tuple(m.dt, to_array(m.accel), m.name);
}

// The response spectrum of an array (dt, accel) with the damping, sub-step and period keys.
py::dict response_spectrum_of(const std::vector<std::string>& args, double dt,
                              const DoubleArray& accel, const std::string& name,
                              const std::string& check_pga_key) {
  std::vector<double> a = to_vector(accel, name);
  ResponseSpectrum r;
  {
    py::gil_scoped_release release;
    CLocale c_locale;
    const Options o = parse_options("motion spectrum", record_spectrum_option_specs(), args);
    const GroundMotion m =
        motion_from_values(name, dt, std::move(a), !o.flag("accept-any-pga"), check_pga_key);
    const SpectrumSettings s = spectrum_settings_from_options(o);
    r = response_spectrum(m, periods_from_options(o), s.damping, s.options);
  }
  return spectrum_arrays(r);
}

py::dict design_spectrum(const std::vector<std::string>& args) {
  ResponseSpectrum r;
  std::string describe;
  {
    py::gil_scoped_release release;
    CLocale c_locale;
    const Options o = parse_options("motion target", target_specs(), args);
    const auto target = make_design_spectrum(o);
    r = design_response_spectrum(*target, periods_from_options(o));
    describe = target->describe();
  }
  py::dict d = spectrum_arrays(r);
  d["spectrum"] = describe;
  return d;
}

py::dict motion_set_arrays(const MotionSet& g, const MotionSetRequest& rq) {
  const std::size_t count = g.motions.size(), np = g.periods.size();
  const std::size_t n = count ? g.motions.front().accel.size() : 0;
  std::vector<double> t(n), acc, pga, v_end, d_end, min_r, max_r, mean_r;
  std::vector<int> iterations, phase_set;
  for (std::size_t i = 0; i < n; ++i) t[i] = rq.settings.dt * double(i);
  for (std::size_t i = 0; i < count; ++i) {
    const MotionReport& r = g.reports[i];
    acc.insert(acc.end(), g.motions[i].accel.begin(), g.motions[i].accel.end());
    pga.push_back(r.pga);
    v_end.push_back(r.v_end);
    d_end.push_back(r.d_end);
    min_r.push_back(r.match.min_ratio);
    max_r.push_back(r.match.max_ratio);
    mean_r.push_back(r.match.mean_ratio);
    iterations.push_back(r.iterations);
    phase_set.push_back(r.attempt);
  }
  py::dict d;
  d["spectrum"] = rq.target->describe();
  d["variability"] = rq.variability.describe();
  d["dt_s"] = rq.settings.dt;
  d["time_s"] = to_array(t);
  d["accel_mps2"] = to_array(acc, count, n);
  d["period_s"] = to_array(g.periods);
  d["design_psa_mps2"] = to_array(g.design);
  d["target_psa_mps2"] = to_array(g.targets, count, np);
  d["psa_mps2"] = to_array(g.psa, count, np);
  d["mean_psa_mps2"] = to_array(g.mean);
  d["geomean_psa_mps2"] = to_array(g.geomean);
  d["epsilon"] = g.variable ? py::object(to_array(g.eps, count, np)) : py::none();
  d["sigma_lnsa"] = g.variable ? py::object(to_array(g.sigma)) : py::none();
  d["pga_mps2"] = to_array(pga);
  d["final_velocity_mps"] = to_array(v_end);
  d["final_displacement_m"] = to_array(d_end);
  d["min_ratio"] = to_array(min_r);
  d["max_ratio"] = to_array(max_r);
  d["mean_ratio"] = to_array(mean_r);
  d["iterations"] = to_int_array(iterations);
  d["phase_set"] = to_int_array(phase_set);
  return d;
}

py::dict generate(const std::vector<std::string>& args) {
  MotionSetRequest rq;
  MotionSet g;
  {
    py::gil_scoped_release release;
    CLocale c_locale;
    const Options o = parse_options("motion generate", motion_set_option_specs(), args);
    rq = motion_set_from_options(o);
    g = generate_motion_set(rq);
  }
  return motion_set_arrays(g, rq);
}

}  // namespace

void bind_motion(py::module_& m) {
  m.def("read_record", &read_record, py::arg("args"), py::arg("check_pga_key"));
  m.def("response_spectrum", &response_spectrum_of, py::arg("args"), py::arg("dt"),
        py::arg("accel"), py::arg("name"), py::arg("check_pga_key"));
  m.def("design_spectrum", &design_spectrum, py::arg("args"));
  m.def("generate", &generate, py::arg("args"));
  m.def("record_keys", [] { return option_keys(record_spectrum_option_specs()); });
  m.def("target_keys", [] { return option_keys(target_specs()); });
  m.def("generate_keys", [] { return option_keys(motion_set_option_specs()); });
  m.def(
      "log_spaced_periods",
      [](double t_min, double t_max, int n) {
        std::vector<double> p;
        {
          py::gil_scoped_release release;
          p = log_spaced_periods(t_min, t_max, n);
        }
        return to_array(p);
      },
      py::arg("t_min"), py::arg("t_max"), py::arg("n"));
}

}  // namespace pound::python

// _engine.hysteresis: `pound hysteresis` on an array of drifts (study/hysteresis_run.hpp).
#include "engine.hpp"
#include "study/hysteresis_run.hpp"

namespace pound::python {
namespace {

py::array_t<double> hysteresis(const std::vector<std::string>& args, const DoubleArray& drifts) {
  const std::vector<double> d = to_vector(drifts, "drifts");
  std::vector<double> shear;
  {
    py::gil_scoped_release release;
    CLocale c_locale;
    const Options opt = parse_options("hysteresis", hysteresis_option_specs(), args);
    const Building b = tested_storey(opt);
    shear = storey_shears(opt, b, d, "drifts");
  }
  return to_array(shear);
}

}  // namespace

void bind_hysteresis(py::module_& m) {
  m.def("hysteresis", &hysteresis, py::arg("args"), py::arg("drifts"),
        "Storey shears [N] at the drifts [m] of the storey the arguments describe.");
  m.def("hysteresis_keys", [] { return option_keys(hysteresis_option_specs()); });
}

}  // namespace pound::python

// _engine.fragility and _engine.risk: `pound fragility --json` and `pound risk --json` as calls
// (fragility/fragility_run.hpp, risk/risk_run.hpp). They read the campaign file with HDF5, which
// is not thread-safe (nor is io/h5.cpp's record of the last system error, nor h5py beside it in
// the same process): these two keep the GIL while they work, so that they run one at a time and
// never beside h5py. They are post-processing of a few seconds; simulations run in parallel.
#include "engine.hpp"
#include "fragility/fragility_run.hpp"
#include "risk/risk_run.hpp"

namespace pound::python {
namespace {

std::string fragility(const std::vector<std::string>& args, bool write_files) {
  CLocale c_locale;
  const Options opt = parse_options("fragility", fragility_option_specs(), args);
  return fragility_json(run_fragility_analysis(opt, write_files));
}

std::string risk(const std::vector<std::string>& args, bool write_files) {
  CLocale c_locale;
  const Options opt = parse_options("risk", risk_option_specs(), args);
  return risk_json(run_risk_analysis(opt, write_files));
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("fragility", &fragility, py::arg("args"), py::arg("write_files"),
        "pound fragility --json of the arguments (json text); files only with write_files.");
  m.def("fragility_keys", [] { return option_keys(fragility_option_specs()); });
  m.def("risk", &risk, py::arg("args"), py::arg("write_files"),
        "pound risk --json of the arguments (json text); files only with write_files.");
  m.def("risk_keys", [] { return option_keys(risk_option_specs()); });
}

}  // namespace pound::python

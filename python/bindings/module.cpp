// PYBIND11_MODULE(_engine): the exceptions, the version and every binding (engine.hpp).
#include <cstring>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "engine.hpp"
#include "pound/version.hpp"

namespace pound::python {

CLocale::CLocale() {
  static const locale_t c = newlocale(LC_ALL_MASK, "C", static_cast<locale_t>(nullptr));
  previous_ = uselocale(c);
}

CLocale::~CLocale() {
  uselocale(previous_);
}

Options parse_options(const std::string& command, std::vector<OptionSpec> specs,
                      const std::vector<std::string>& args) {
  Options opt(command, "", std::move(specs));
  opt.parse(args);
  return opt;
}

std::vector<std::string> option_keys(const std::vector<OptionSpec>& specs) {
  std::vector<std::string> keys;
  for (const auto& s : specs) keys.push_back(s.key);
  return keys;
}

py::array_t<double> to_array(const std::vector<double>& v) {
  py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(double));
  return a;
}

py::array_t<double> to_array(const std::vector<double>& v, std::size_t rows, std::size_t cols) {
  py::array_t<double> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  if (rows * cols > 0) std::memcpy(a.mutable_data(), v.data(), rows * cols * sizeof(double));
  return a;
}

py::array_t<int> to_int_array(const std::vector<int>& v) {
  py::array_t<int> a(static_cast<py::ssize_t>(v.size()));
  if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(int));
  return a;
}

std::vector<double> to_vector(const DoubleArray& a, const std::string& what) {
  if (a.ndim() != 1)
    throw InputError(what + ": an array of " + std::to_string(a.ndim()) +
                     " dimensions; valid: one dimension (a sequence of numbers)");
  return std::vector<double>(a.data(), a.data() + a.size());
}

}  // namespace pound::python

PYBIND11_MODULE(_engine, m) {
  namespace py = pybind11;
  m.doc() = "The compiled part of pound (docs/python.md); use the package pound.";
  // pound.Error: bad input, the command's one-line message (exit code 2 of the program).
  static py::exception<pound::InputError> error(m, "Error", PyExc_ValueError);
  // pound.NumericalError: a numerical failure (exit code 3 of the program).
  static py::exception<pound::NumericalError> numerical(m, "NumericalError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const pound::InputError& e) {
      error(e.what());
    } catch (const pound::NumericalError& e) {
      numerical(e.what());
    }
  });
  m.attr("__version__") = pound::kVersion;
  m.attr("git_revision") = pound::kGitRevision;
  // pound.G: standard gravity [m/s^2 per g], the engine's own constant (the scripts' g).
  m.attr("G") = pound::kGravity;
  pound::python::bind_simulate(m);
  pound::python::bind_motion(m);
  pound::python::bind_hysteresis(m);
  pound::python::bind_analysis(m);
}

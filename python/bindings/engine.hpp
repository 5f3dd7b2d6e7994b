#pragma once
// The compiled part of the Python package pound (issue 25, docs/python.md): thin bindings of the
// library's calls that the commands make (study/simulation_run.hpp, study/impact_run.hpp,
// study/hysteresis_run.hpp, motion/motion_set.hpp, motion/spectrum_options.hpp). Options come as
// the command line's arguments ("--config", "study.ini", "--contact.e=0.5", ...) and go through
// the command's Options, so that validation and messages are the command's. The pure-Python
// part (python/pound/*.py) builds those arguments and shapes the results.
//
// Every call runs in the C locale (CLocale). The simulations, motions and storey laws release
// the GIL while the engine works (no Python object is touched then): the engine keeps no mutable
// global state (docs/python.md, "Threads") and they make no HDF5 call, so calls from several
// threads run at once. fragility and risk read HDF5 and keep the GIL (analysis.cpp).
#include <locale.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "io/options.hpp"

namespace pound::python {

namespace py = pybind11;

/// A C-contiguous array of doubles (anything numpy converts: lists, float32, ...).
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The calling thread runs in the C locale while this lives (uselocale): the engine reads
/// numbers with strtod and prints them with snprintf, both of which follow LC_NUMERIC, and
/// Python code may set a locale whose decimal separator is a comma.
class CLocale {
 public:
  CLocale();
  ~CLocale();
  CLocale(const CLocale&) = delete;
  CLocale& operator=(const CLocale&) = delete;

 private:
  locale_t previous_;
};

/// The options of a command parsed from its arguments (no --help here).
Options parse_options(const std::string& command, std::vector<OptionSpec> specs,
                      const std::vector<std::string>& args);

/// The declared keys of a command's options ("building#.masses", ...), for the Python side's
/// mapping of keyword arguments to keys.
std::vector<std::string> option_keys(const std::vector<OptionSpec>& specs);

/// Copies into a new numpy array: 1-D, or [rows x cols] from row-major values.
py::array_t<double> to_array(const std::vector<double>& v);
py::array_t<double> to_array(const std::vector<double>& v, std::size_t rows, std::size_t cols);
py::array_t<int> to_int_array(const std::vector<int>& v);
/// The values of a 1-D array (any other shape is a pound.Error naming `what`).
std::vector<double> to_vector(const DoubleArray& a, const std::string& what);

void bind_simulate(py::module_& m);    // simulate, impact (simulate.cpp)
void bind_motion(py::module_& m);      // records, spectra, generation (motion.cpp)
void bind_hysteresis(py::module_& m);  // the storey-law tester (hysteresis.cpp)
void bind_analysis(py::module_& m);    // fragility and risk of a campaign file (analysis.cpp)

}  // namespace pound::python

#include "study/hysteresis_run.hpp"

#include <cmath>

#include "core/error.hpp"
#include "core/format.hpp"
#include "hysteresis/drive.hpp"
#include "hysteresis/registry.hpp"
#include "study/row_options.hpp"

namespace pound {

const char* const kHysteresisSummary =
    "One storey driven through a drift history (one drift in m per line, from rest) by a storey "
    "law's incremental form; prints drift_m,shear_N per drift.";

std::vector<OptionSpec> hysteresis_option_specs() {
  std::vector<OptionSpec> specs = {
      {"law", "", "", "storey law: " + storey_law_names()},
      {"k0", "N/m", "", "initial storey stiffness k0 > 0"},
      {"fy", "N", "", "yield shear Fy > 0 (required by the inelastic laws)"},
      {"height", "m", "3.0", "storey height h > 0 (drift ratios are of h)"},
      {"drifts", "", "", "file of storey drifts in m, one per line, starting from rest"},
      {"json", "", "", "print one JSON object with the arrays drift_m and shear_N", true},
  };
  const auto laws = storey_law_option_specs("");
  specs.insert(specs.end(), laws.begin(), laws.end());
  return specs;
}

Building tested_storey(const Options& opt) {
  Building b;
  b.masses = {1.0};  // not used: no dynamics here
  if (!opt.given("law"))
    throw InputError("command line: --law is required; valid: " + storey_law_names());
  b.hysteresis = opt.get_string("law");
  find_storey_law(b.hysteresis, opt.where("law"));
  if (!opt.given("k0")) throw InputError("command line: --k0 is required (k0 > 0 in N/m)");
  b.stiffnesses = {opt.get_positive("k0")};
  b.storey_heights = {opt.get_positive("height")};
  if (opt.given("fy"))
    b.yield_shears = {opt.get_positive("fy")};
  else if (b.inelastic())
    throw InputError("command line: --fy is required by law '" + b.hysteresis +
                     "' (the yield shear Fy > 0 in N)");
  read_storey_law_keys(opt, "", b);
  validate(b, "command line");
  return b;
}

std::vector<double> storey_shears(const Options& opt, const Building& b,
                                  const std::vector<double>& drifts, const std::string& name) {
  if (drifts.empty()) throw InputError(name + ": no drifts; give at least one storey drift in m");
  for (std::size_t i = 0; i < drifts.size(); ++i)
    if (!std::isfinite(drifts[i]))
      throw InputError(name + ": drift " + std::to_string(i) + " is " +
                       format_number(drifts[i], "%g") + "; valid: finite storey drifts in m");
  return drive(find_storey_law(b.hysteresis, opt.where("law")), b.storey(0), drifts);
}

}  // namespace pound

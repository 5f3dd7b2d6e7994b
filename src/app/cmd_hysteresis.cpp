// pound hysteresis: the storey-law tester (issue 23). One storey driven through a drift history
// (one drift in m per line, from rest) by a law's incremental form; prints drift_m,shear_N per
// drift as CSV, or with --json one object with the arrays drift_m and shear_N.
#include <cstdio>
#include <iostream>
#include <string>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "core/error.hpp"
#include "hysteresis/drive.hpp"
#include "hysteresis/registry.hpp"
#include "io/drift_history.hpp"
#include "io/json.hpp"
#include "io/options.hpp"
#include "structure/building.hpp"
#include "study/row_options.hpp"

namespace pound::app {
namespace {

std::vector<OptionSpec> hysteresis_specs() {
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

// A one-storey building of the options, validated like a study's (errors name the keys).
Building storey_of(const Options& opt) {
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

}  // namespace

int run_hysteresis(int argc, const char* const* argv) {
  Options opt("hysteresis",
              "One storey driven through a drift history (one drift in m per line, from rest) "
              "by a storey law's incremental form; prints drift_m,shear_N per drift.",
              hysteresis_specs());
  if (help_asked(opt, argc, argv)) return 0;
  const Building b = storey_of(opt);
  if (!opt.given("drifts"))
    throw InputError("command line: --drifts FILE is required (one storey drift in m per line)");
  const std::vector<double> drifts = read_drift_history(opt.get_path("drifts"));
  const std::vector<double> shear =
      drive(find_storey_law(b.hysteresis, opt.where("law")), b.storey(0), drifts);
  if (opt.flag("json")) {
    JsonWriter w;
    w.begin_object();
    w.key("drift_m").array(drifts);
    w.key("shear_N").array(shear);
    w.end_object();
    std::cout << w.str() << "\n";
    return 0;
  }
  std::string out = "drift_m,shear_N\n";
  char line[64];
  for (std::size_t i = 0; i < drifts.size(); ++i) {
    std::snprintf(line, sizeof line, "%.17g,%.17g\n", drifts[i], shear[i]);
    out += line;
  }
  std::cout << out;
  return 0;
}

}  // namespace pound::app

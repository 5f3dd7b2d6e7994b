// pound hysteresis: the storey-law tester (issue 23). One storey driven through a drift history
// (one drift in m per line, from rest) by a law's incremental form; prints drift_m,shear_N per
// drift as CSV, or with --json one object with the arrays drift_m and shear_N.
#include <cstdio>
#include <iostream>
#include <string>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "core/error.hpp"
#include "io/drift_history.hpp"
#include "io/json.hpp"
#include "io/options.hpp"
#include "study/hysteresis_run.hpp"

namespace pound::app {

int run_hysteresis(int argc, const char* const* argv) {
  Options opt("hysteresis", kHysteresisSummary, hysteresis_option_specs());
  if (help_asked(opt, argc, argv)) return 0;
  const Building b = tested_storey(opt);
  if (!opt.given("drifts"))
    throw InputError("command line: --drifts FILE is required (one storey drift in m per line)");
  const std::string path = opt.get_path("drifts");
  const std::vector<double> drifts = read_drift_history(path);
  const std::vector<double> shear = storey_shears(opt, b, drifts, path);
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

#pragma once
// A study file of studies/ read as `pound simulate` reads it, for the damped Sears tests.
#include <string>
#include <vector>

#include "io/options.hpp"
#include "motion/ground_motion.hpp"
#include "sears/sears_simulation.hpp"
#include "study/row_options.hpp"
#include "study/sears_row_options.hpp"

namespace pound::test {

struct StudyRun {
  BuildingRow row;
  sears::SearsRowModel model;
  GroundMotion motion;
};

/// studies/<file> with further command-line arguments (e.g. {"--sears.integrator", "fixed"}).
inline StudyRun read_study(const std::string& file, std::vector<std::string> extra = {}) {
  Options opt("simulate", "test study", row_and_sears_option_specs());
  std::vector<std::string> args = {"--config", std::string(POUND_SOURCE_DIR) + "/studies/" + file};
  args.insert(args.end(), extra.begin(), extra.end());
  opt.parse(args);
  StudyRun r;
  r.row = row_from_options(opt);
  r.model = sears_row_from_options(opt, r.row);
  r.motion = motion_from_options(opt);
  return r;
}

}  // namespace pound::test

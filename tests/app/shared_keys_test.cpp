// The keys that `pound simulate` and `pound campaign` share are read by one study reader
// (study/row_study.hpp, issue 31): a bad value gets the same one line from both commands, exit
// code 2 and no output file. The two studies hold the same pair of buildings (the chapter 6
// SDOF pair); every bad value below is given on the command line of both.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "../support/pound_command.hpp"
#include "../support/scratch_dir.hpp"
#include "../support/shell.hpp"

namespace {

namespace fs = std::filesystem;
using pound::test::run_command;
using pound::test::ScratchDir;
using pound::test::slurp;

using Outcome = pound::test::PoundOutcome;
const auto run = &pound::test::run_pound_command;

TEST(SharedKeys, ABadValueGetsTheSameLineFromSimulateAndCampaign) {
  const std::string src = POUND_SOURCE_DIR;
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"contact.xi_relation", "publishd"},  // the campaign took it as 'exact' (issue 31)
      {"contact.e", "1.5"},
      {"contact.e", "abc"},
      {"contact.model", "lvx"},
      {"contact.v0_min", "-1"},
      {"contact.v0_min", "0"},
      {"contact.k", "-5"},
      {"building1.damping", "1.2"},
      {"building1.damping_type", "viscous"},
      {"building1.masses", "-100"},
      {"building2.masses", "abc"},
      {"building1.stiffnesses", "0"},
      {"building2.stiffnesses", "1e4,2e4"},
      {"building1.storey_heights", "-3"},
      {"simulation.collapse_drift_ratio", "-0.1"},
      {"simulation.collapse_drift_ratio", "0"},
      {"simulation.extra_time", "-1"},
      {"integrator.rtol", "0"},
      {"building1.hysteresis", "plastic"},
      {"building1.yield_shears", "-1"},
      {"building1.cap_strength_ratio", "0.8"},
      {"building1.plastic_drift_ratio", "-0.01"},
      {"building1.post_cap_drift_ratio", "0"},
      {"building1.residual_strength_ratio", "1"},
      {"building1.energy_capacity", "0"},
      {"building1.energy_exponent", "-1"},
      {"building1.ultimate_drift_ratio", "-0.2"},
      {"pair1.gap", "-0.01"},
      {"contact.force_cap", "0"},
      {"contact.force_cap", "-2e5"},
      {"contact.force_cap", "abc"},
      {"contact.model", "stereomechanical"},
  };
  for (const auto& [key, value] : bad) {
    SCOPED_TRACE(key + " = " + value);
    const ScratchDir dir("pound_shared_keys_");
    std::string flag = " --" + key + " '" + value + "'";
    if (value == "stereomechanical")  // a cap with a model that has no force history
      flag += " --contact.force_cap 1e5";
    const Outcome sim =
        run(dir, "simulate", "--config " + src + "/studies/ch6-sdof-pair.ini" + flag);
    const std::string out = dir / "run.h5";
    const Outcome camp = run(dir, "campaign",
                             "--config " + src + "/studies/campaign-smoke.ini --samples 2 --quiet" +
                                 flag + " --out " + out);
    EXPECT_EQ(sim.code, 2) << sim.message;
    EXPECT_EQ(camp.code, 2) << camp.message;
    EXPECT_EQ(sim.message, camp.message);
    // One line that names the key.
    EXPECT_EQ(sim.message.find('\n'), sim.message.size() - 1) << sim.message;
    EXPECT_NE(sim.message.find(key), std::string::npos) << sim.message;
    // No result and no journal.
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(out + ".journal"));
  }
}

}  // namespace

// The foundation keys (issue 29) are read by the one study reader (study/row_study.hpp) of
// `pound simulate` and `pound campaign`: a bad value gets the same one line from both, exit
// code 2 and no output file, as the other shared keys do (shared_keys_test.cpp); a good one is
// simulated and reported.
#include <gtest/gtest.h>

#include <cstdio>
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

// Both commands on the same flags: the same single line naming `key`, exit 2, no file.
void expect_same_refusal(const std::string& flags, const std::string& key,
                         const std::string& says) {
  const std::string src = POUND_SOURCE_DIR;
  const ScratchDir dir("pound_foundation_keys_");
  const Outcome sim =
      run(dir, "simulate", "--config " + src + "/studies/ch6-sdof-pair.ini" + flags);
  const std::string out = dir / "run.h5";
  const Outcome camp = run(dir, "campaign",
                           "--config " + src + "/studies/campaign-smoke.ini --samples 2 --quiet" +
                               flags + " --out " + out);
  EXPECT_EQ(sim.code, 2) << sim.message;
  EXPECT_EQ(camp.code, 2) << camp.message;
  EXPECT_EQ(sim.message, camp.message);
  EXPECT_EQ(sim.message.find('\n'), sim.message.size() - 1) << sim.message;
  EXPECT_NE(sim.message.find(key), std::string::npos) << sim.message;
  EXPECT_NE(sim.message.find(says), std::string::npos) << sim.message;
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(out + ".journal"));
}

using Flags = std::vector<std::pair<std::string, std::string>>;

const Flags kCone = {{"building1.foundation", "cone"},
                     {"building1.foundation_radius", "6.8"},
                     {"building1.soil_shear_velocity", "150"},
                     {"building1.soil_density", "1900"},
                     {"building1.soil_poisson", "0.3"}};
const Flags kGazetas = {
    {"building1.foundation", "gazetas"},  {"building1.foundation_length", "14"},
    {"building1.foundation_width", "10"}, {"building1.soil_shear_velocity", "150"},
    {"building1.soil_density", "1900"},   {"building1.soil_poisson", "0.3"}};
const Flags kSprings = {{"building2.foundation", "springs"},
                        {"building2.sway_stiffness", "1e9"},
                        {"building2.rocking_stiffness", "1e11"},
                        {"building2.sway_damping", "1e7"},
                        {"building2.rocking_damping", "1e9"}};

// The flags of `base` with key = value (replaced, or added).
std::string with(Flags base, const std::string& key, const std::string& value) {
  bool found = false;
  for (auto& [k, v] : base)
    if (k == key) {
      v = value;
      found = true;
    }
  if (!found) base.push_back({key, value});
  std::string out;
  for (const auto& [k, v] : base) out += " --" + k + " '" + v + "'";
  return out;
}

TEST(FoundationKeys, ABadValueGetsTheSameLineFromSimulateAndCampaign) {
  // {flags, the key named, what the line says}
  const std::vector<std::vector<std::string>> bad = {
      {with({}, "building1.foundation", "raft"), "building1.foundation",
       "valid: fixed, springs, cone or gazetas"},
      {with(kSprings, "building2.sway_stiffness", "0"), "building2.sway_stiffness", "K_x > 0"},
      {with(kSprings, "building2.rocking_stiffness", "-1e11"), "building2.rocking_stiffness",
       "K_theta > 0"},
      {with(kSprings, "building2.sway_damping", "0"), "building2.sway_damping", "C_x > 0"},
      {with(kSprings, "building2.rocking_damping", "-5"), "building2.rocking_damping",
       "C_theta > 0"},
      {with(kCone, "building1.soil_shear_velocity", "0"), "building1.soil_shear_velocity",
       "Vs > 0"},
      {with(kCone, "building1.soil_density", "-1900"), "building1.soil_density", "rho > 0"},
      {with(kCone, "building1.soil_poisson", "0.5"), "building1.soil_poisson", "nu in [0, 0.5)"},
      {with(kCone, "building1.soil_poisson", "-0.1"), "building1.soil_poisson", "nu in [0, 0.5)"},
      {with(kCone, "building1.foundation_radius", "0"), "building1.foundation_radius", "r > 0"},
      {with(kCone, "building1.foundation_mass", "-1"), "building1.foundation_mass", "m_0 >= 0"},
      {with(kCone, "building1.foundation_inertia", "-1"), "building1.foundation_inertia",
       "I_0 >= 0"},
      {with(kCone, "building1.floor_inertias", "-1"), "building1.floor_inertias", ">= 0 kg m^2"},
      {with(kSprings, "building2.floor_inertias", "1,2,3"), "building2.floor_inertias",
       "one per floor"},
      // A key the kind needs, missing.
      {with({}, "building1.foundation", "cone"), "building1.foundation_radius", "(missing)"},
      {with({}, "building2.foundation", "springs"), "building2.sway_stiffness", "(missing)"},
      {with(kCone, "building1.foundation", "gazetas"), "building1.foundation_length", "(missing)"},
      {with(kGazetas, "building1.foundation_length", "0"), "building1.foundation_length",
       "length > 0 m"},
      {with(kGazetas, "building1.foundation_width", "-1"), "building1.foundation_width",
       "width > 0 m"},
      // Keys given with fixed are checked for range too (and then ignored).
      {with({}, "building1.soil_poisson", "0.7"), "building1.soil_poisson", "nu in [0, 0.5)"},
      {with({}, "building2.rocking_damping", "0"), "building2.rocking_damping", "C_theta > 0"},
  };
  for (const auto& b : bad) {
    SCOPED_TRACE(b[0]);
    expect_same_refusal(b[0], b[1], b[2]);
  }
}

// A good foundation is simulated (issue 29): pound simulate --json gives each building's
// periods with its foundation and the foundation's constants in SI units, and its base's peak
// sway and rotation.
TEST(FoundationKeys, AGoodFoundationIsSimulatedAndReported) {
  const std::string src = POUND_SOURCE_DIR;
  const ScratchDir dir("pound_foundation_keys_");
  std::string flags;
  for (const Flags* f : {&kCone, &kSprings})
    for (const auto& [k, v] : *f) flags += " --" + k + " " + v;
  const int code = run_command(std::string(POUND_BINARY) + " simulate --config " + src +
                               "/studies/ch6-sdof-pair.ini --json" + flags + " >" +
                               (dir / "out.json") + " 2>" + (dir / "err.txt"));
  ASSERT_EQ(code, 0) << slurp(dir / "err.txt");
  const std::string json = slurp(dir / "out.json");
  // The cone of building 1: G = 1900 x 150^2, K_x = 8 G r / (2 - nu) at r = 6.8, nu = 0.3.
  const double G = 1900.0 * 150.0 * 150.0, kx = 8.0 * G * 6.8 / (2.0 - 0.3);
  char expect[64];
  std::snprintf(expect, sizeof expect, "\"sway_stiffness\":%.17g", kx);
  EXPECT_NE(json.find("\"kind\":\"cone\""), std::string::npos) << json;
  EXPECT_NE(json.find(expect), std::string::npos) << expect << " in " << json;
  EXPECT_NE(json.find("\"kind\":\"springs\",\"sway_stiffness\":1000000000,"), std::string::npos)
      << json;
  EXPECT_NE(json.find("\"periods_s\":[0.5"), std::string::npos) << json;  // longer than 0.5 s
  EXPECT_EQ(json.find("\"peak_base_sway_m\":{\"pounding\":null"), std::string::npos) << json;
}

}  // namespace

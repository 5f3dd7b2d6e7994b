// The foundation keys (issue 29, study/foundation_options.hpp): read once by the study reader
// into each Building, with their defaults, one or per-floor inertias, the keys of another kind
// range-checked and ignored, errors naming the key and what is valid.
#include "study/foundation_options.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "study/row_options.hpp"
#include "study/row_study.hpp"
#include "study/simulation_run.hpp"

namespace pound {
namespace {

// A 3-storey and a 2-storey building with a contact stiffness, and `extra` flags.
Options parsed(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"--building1.masses",
                                   "1e5,1e5,1e5",
                                   "--building1.stiffnesses",
                                   "1e8",
                                   "--building2.masses",
                                   "8e4,8e4",
                                   "--building2.stiffnesses",
                                   "9e7",
                                   "--pair1.gap",
                                   "0.02",
                                   "--contact.k",
                                   "1e9"};
  args.insert(args.end(), extra.begin(), extra.end());
  Options o("simulate", "", row_option_specs());
  o.parse(args);
  return o;
}

std::string error_of(const std::vector<std::string>& extra) {
  try {
    const Options o = parsed(extra);
    read_row_study(o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const std::vector<std::string> kCone = {
    "--building1.foundation",          "cone", "--building1.foundation_radius", "11.3",
    "--building1.soil_shear_velocity", "150",  "--building1.soil_density",      "1900",
    "--building1.soil_poisson",        "0.4"};

const std::vector<std::string> kSprings = {
    "--building2.foundation",        "springs", "--building2.sway_stiffness", "1e9",
    "--building2.rocking_stiffness", "2e11",    "--building2.sway_damping",   "3e7",
    "--building2.rocking_damping",   "4e9"};

std::vector<std::string> joined(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(FoundationOptions, FixedIsTheDefault) {
  const BuildingRow row = row_from_options(parsed({}));
  for (const auto& b : row.buildings) {
    EXPECT_EQ(b.foundation.kind, FoundationKind::fixed);
    EXPECT_TRUE(b.foundation.floor_inertias.empty());
  }
}

TEST(FoundationOptions, ConeAndSpringsKeysReachEachBuilding) {
  const BuildingRow row = row_from_options(parsed(
      joined(joined(kCone, kSprings),
             {"--building1.foundation_mass", "2e5", "--building1.floor_inertias", "1e6, 2e6, 3e6",
              "--building2.foundation_inertia", "5e6", "--building2.floor_inertias", "7e5"})));
  const Foundation& c = row.buildings[0].foundation;
  EXPECT_EQ(c.kind, FoundationKind::cone);
  EXPECT_EQ(c.radius, 11.3);
  EXPECT_EQ(c.soil_shear_velocity, 150.0);
  EXPECT_EQ(c.soil_density, 1900.0);
  EXPECT_EQ(c.soil_poisson, 0.4);
  EXPECT_EQ(c.foundation_mass, 2e5);
  EXPECT_EQ(c.foundation_inertia, 0.0);  // the default
  EXPECT_EQ(c.floor_inertias, (std::vector<double>{1e6, 2e6, 3e6}));
  const Foundation& s = row.buildings[1].foundation;
  EXPECT_EQ(s.kind, FoundationKind::springs);
  EXPECT_EQ(s.sway_stiffness, 1e9);
  EXPECT_EQ(s.rocking_stiffness, 2e11);
  EXPECT_EQ(s.sway_damping, 3e7);
  EXPECT_EQ(s.rocking_damping, 4e9);
  EXPECT_EQ(s.foundation_mass, 0.0);  // the default
  EXPECT_EQ(s.foundation_inertia, 5e6);
  // One value for every floor.
  EXPECT_EQ(s.floor_inertias, (std::vector<double>{7e5, 7e5}));
  // The constants follow: the cone's trapped soil (nu = 0.4 > 1/3) joins its base's inertia.
  const FoundationConstants k = foundation_constants(c);
  EXPECT_GT(k.trapped_rocking_inertia, 0.0);
  EXPECT_EQ(k.foundation_inertia, k.trapped_rocking_inertia);
}

// Keys of another kind (or given with fixed) are range-checked and then ignored.
TEST(FoundationOptions, KeysOfAnotherKindAreCheckedAndIgnored) {
  const BuildingRow row = row_from_options(parsed(
      joined(kCone, {"--building1.sway_stiffness", "1e9", "--building2.soil_poisson", "0.3",
                     "--building2.foundation_mass", "1e4", "--building2.floor_inertias", "1, 2"})));
  EXPECT_EQ(row.buildings[0].foundation.sway_stiffness, 0.0);
  EXPECT_EQ(row.buildings[1].foundation.kind, FoundationKind::fixed);
  EXPECT_EQ(row.buildings[1].foundation.soil_poisson, 0.0);
  EXPECT_EQ(row.buildings[1].foundation.foundation_mass, 0.0);
  EXPECT_TRUE(row.buildings[1].foundation.floor_inertias.empty());
  EXPECT_EQ(error_of({"--building2.soil_poisson", "0.5"}),
            "command line: --building2.soil_poisson = '0.5': valid: a Poisson's ratio nu in [0, "
            "0.5)");
  EXPECT_EQ(error_of(joined(kCone, {"--building1.rocking_damping", "0"})),
            "command line: --building1.rocking_damping = '0': valid: a rocking damping C_theta > 0 "
            "N m s/rad");
}

TEST(FoundationOptions, BadValuesNameTheKeyAndWhatIsValid) {
  EXPECT_EQ(error_of({"--building1.foundation", "raft"}),
            "command line: --building1.foundation = 'raft': valid: fixed, springs, cone or "
            "gazetas");
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"sway_stiffness", "0"},   {"rocking_stiffness", "-1"},  {"sway_damping", "-3"},
      {"rocking_damping", "0"},  {"soil_shear_velocity", "0"}, {"soil_density", "-1900"},
      {"soil_poisson", "-0.1"},  {"soil_poisson", "0.5"},      {"foundation_radius", "0"},
      {"foundation_mass", "-1"}, {"foundation_inertia", "-1"}, {"floor_inertias", "1,-1,1"},
      {"floor_inertias", "1,2"}, {"foundation_length", "0"},   {"foundation_width", "-2"},
  };
  for (const auto& [key, value] : bad) {
    SCOPED_TRACE(key + " = " + value);
    const std::string e = error_of({"--building1." + key, value});
    EXPECT_EQ(e.rfind("command line: --building1." + key + " = '" + value + "': ", 0), 0u) << e;
    EXPECT_TRUE(e.find("valid") != std::string::npos ||
                e.find("expected 3 values") != std::string::npos)
        << e;
  }
  // A key the kind needs, missing.
  std::vector<std::string> no_vs = kCone;
  no_vs.erase(no_vs.begin() + 4, no_vs.begin() + 6);
  EXPECT_EQ(error_of(no_vs),
            "command line: --building1.foundation = 'cone': needs building1.soil_shear_velocity, "
            "a shear wave velocity Vs > 0 m/s (missing)");
  EXPECT_NE(error_of({"--building2.foundation", "springs"})
                .find("'springs': needs building2.sway_stiffness, a sway stiffness K_x > 0 N/m "
                      "(missing)"),
            std::string::npos);
}

// A Gazetas footing reads its sides and the soil keys it shares with the cone; a missing side is
// named where the foundation was chosen.
TEST(FoundationOptions, GazetasReadsItsSidesAndTheSoil) {
  const std::vector<std::string> g = {
      "--building2.foundation",        "gazetas", "--building2.foundation_length",   "12",
      "--building2.foundation_width",  "9",       "--building2.soil_shear_velocity", "120",
      "--building2.soil_density",      "1750",    "--building2.soil_poisson",        "0.35",
      "--building2.foundation_radius", "4"};  // a cone's key: checked, ignored
  const Foundation f = row_from_options(parsed(g)).buildings[1].foundation;
  EXPECT_EQ(f.kind, FoundationKind::gazetas);
  EXPECT_EQ(f.length, 12.0);
  EXPECT_EQ(f.width, 9.0);
  EXPECT_EQ(f.soil_shear_velocity, 120.0);
  EXPECT_EQ(f.soil_density, 1750.0);
  EXPECT_EQ(f.soil_poisson, 0.35);
  EXPECT_EQ(f.radius, 0.0);
  std::vector<std::string> no_width = g;
  no_width.erase(no_width.begin() + 4, no_width.begin() + 6);
  EXPECT_EQ(error_of(no_width),
            "command line: --building2.foundation = 'gazetas': needs building2.foundation_width, "
            "a footing width > 0 m across the row (missing)");
}

// Every foundation reaches the row the solvers take.
TEST(FoundationOptions, TheStudyReaderKeepsEveryFoundation) {
  EXPECT_EQ(error_of(kCone), "");
  EXPECT_EQ(error_of(kSprings), "");
  // A bad value elsewhere is still named.
  EXPECT_NE(error_of(joined(kCone, {"--contact.e", "2"})).find("contact.e"), std::string::npos);
  const RowStudy st = read_row_study(parsed(kCone));
  EXPECT_EQ(st.row.buildings[0].foundation.kind, FoundationKind::cone);
  EXPECT_EQ(st.row.buildings[1].foundation.kind, FoundationKind::fixed);
}

TEST(FoundationOptions, KeysAreDeclaredWithUnits) {
  const auto specs = row_option_specs();
  auto unit = [&](const std::string& key) {
    const auto it =
        std::find_if(specs.begin(), specs.end(), [&](const OptionSpec& s) { return s.key == key; });
    return it == specs.end() ? std::string("(none)") : it->unit;
  };
  EXPECT_EQ(unit("building#.foundation"), "");
  EXPECT_EQ(unit("building#.sway_stiffness"), "N/m");
  EXPECT_EQ(unit("building#.rocking_stiffness"), "N m/rad");
  EXPECT_EQ(unit("building#.sway_damping"), "N s/m");
  EXPECT_EQ(unit("building#.rocking_damping"), "N m s/rad");
  EXPECT_EQ(unit("building#.foundation_radius"), "m");
  EXPECT_EQ(unit("building#.soil_shear_velocity"), "m/s");
  EXPECT_EQ(unit("building#.soil_density"), "kg/m^3");
  EXPECT_EQ(unit("building#.soil_poisson"), "-");
  EXPECT_EQ(unit("building#.foundation_mass"), "kg");
  EXPECT_EQ(unit("building#.foundation_inertia"), "kg m^2");
  EXPECT_EQ(unit("building#.floor_inertias"), "kg m^2");
}

}  // namespace
}  // namespace pound

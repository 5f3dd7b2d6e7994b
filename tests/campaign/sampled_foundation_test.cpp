// The sampled soil and foundation parameters (issue 29, campaign/sampled_foundation.hpp): each
// acts on its building's foundation, only on a building with the foundation it needs (a clear
// message otherwise), within its range; and a campaign with a foundation other than fixed is
// refused, after its sampled parameters were checked, until the solvers simulate one.
#include "campaign/sampled_foundation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "campaign/campaign_study.hpp"
#include "campaign/sample.hpp"
#include "core/error.hpp"
#include "study/row_options.hpp"

namespace pound {
namespace {

// Building 1 on a cone, building 2 on springs, a fixed building 3; a records campaign.
Options campaign_options(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"--building1.masses",
                                   "1000, 1000",
                                   "--building1.stiffnesses",
                                   "2e6",
                                   "--building1.foundation",
                                   "cone",
                                   "--building1.foundation_radius",
                                   "5",
                                   "--building1.soil_shear_velocity",
                                   "150",
                                   "--building1.soil_density",
                                   "1900",
                                   "--building1.soil_poisson",
                                   "0.3",
                                   "--building2.masses",
                                   "1500",
                                   "--building2.stiffnesses",
                                   "1e6",
                                   "--building2.foundation",
                                   "springs",
                                   "--building2.sway_stiffness",
                                   "1e8",
                                   "--building2.rocking_stiffness",
                                   "1e10",
                                   "--building2.sway_damping",
                                   "1e6",
                                   "--building2.rocking_damping",
                                   "1e8",
                                   "--building3.masses",
                                   "1200",
                                   "--building3.stiffnesses",
                                   "1e6",
                                   "--contact.model",
                                   "hc-linear",
                                   "--contact.k",
                                   "1e8",
                                   "--motion.source",
                                   "records",
                                   "--motion.file",
                                   POUND_SOURCE_DIR "/motions/elcentro-1940-ns.dat",
                                   "--intensity.levels",
                                   "0.2"};
  args.insert(args.end(), extra.begin(), extra.end());
  Options opt("campaign", "", campaign_option_specs());
  opt.parse(args);
  return opt;
}

std::string error_of(const std::vector<std::string>& extra) {
  try {
    const Options opt = campaign_options(extra);
    read_sampled_parameters(opt, row_from_options(opt));
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SampledFoundation, SoilValuesAndTheSpringsFactorReachTheirBuilding) {
  const Options opt = campaign_options(
      {"--sample.building1.soil_shear_velocity", "uniform(100, 200)",
       "--sample.building1.soil_density", "uniform(1800, 2000)", "--sample.building1.soil_poisson",
       "uniform(0.3, 0.45)", "--sample.building1.foundation_radius", "uniform(6, 12)",
       "--sample.building2.foundation_scale", "lognormal(1, 0.3, 0.5, 2)"});
  const BuildingRow row = row_from_options(opt);
  const std::vector<SampledParameter> params = read_sampled_parameters(opt, row);
  ASSERT_EQ(params.size(), 5u);
  // Sorted keys, as the /samples columns.
  std::vector<std::string> keys;
  for (const auto& p : params) keys.push_back(p.key);
  EXPECT_EQ(keys,
            (std::vector<std::string>{"building1.foundation_radius", "building1.soil_density",
                                      "building1.soil_poisson", "building1.soil_shear_velocity",
                                      "building2.foundation_scale"}));
  SampleModel m;
  m.row = row;
  apply_sampled(params, {11.0, 1950.0, 0.42, 180.0, 1.5}, m);
  const Foundation& c = m.row.buildings[0].foundation;
  EXPECT_EQ(c.radius, 11.0);
  EXPECT_EQ(c.soil_density, 1950.0);
  EXPECT_EQ(c.soil_poisson, 0.42);
  EXPECT_EQ(c.soil_shear_velocity, 180.0);
  const Foundation& s = m.row.buildings[1].foundation;
  EXPECT_EQ(s.sway_stiffness, 1.5e8);
  EXPECT_EQ(s.rocking_stiffness, 1.5e10);
  EXPECT_EQ(s.sway_damping, 1.5e6);
  EXPECT_EQ(s.rocking_damping, 1.5e8);
  EXPECT_EQ(m.row.buildings[2].foundation.kind, FoundationKind::fixed);
  // The study's own row is unchanged.
  EXPECT_EQ(row.buildings[0].foundation.soil_shear_velocity, 150.0);
}

TEST(SampledFoundation, EachNeedsItsFoundationAndRange) {
  EXPECT_EQ(error_of({"--sample.building3.soil_density", "uniform(1800, 2000)"}),
            "command line: --sample.building3.soil_density: building3.foundation is 'fixed'; the "
            "soil under it is sampled only with building3.foundation = cone or gazetas");
  EXPECT_EQ(error_of({"--sample.building2.foundation_radius", "uniform(5, 6)"}),
            "command line: --sample.building2.foundation_radius: building2.foundation is "
            "'springs'; the footing radius of a cone is sampled only with "
            "building2.foundation = cone");
  EXPECT_EQ(error_of({"--sample.building1.foundation_scale", "uniform(0.5, 2)"}),
            "command line: --sample.building1.foundation_scale: building1.foundation is 'cone'; "
            "the factor on the foundation's springs and dashpots is sampled only with "
            "building1.foundation = springs");
  EXPECT_NE(error_of({"--sample.building1.soil_poisson", "uniform(0.3, 0.5)"})
                .find("soil_poisson must stay in [0, 0.5)"),
            std::string::npos);
  EXPECT_NE(error_of({"--sample.building1.soil_shear_velocity", "normal(150, 50)"})
                .find("its values must be > 0"),
            std::string::npos);
  EXPECT_EQ(error_of({"--sample.building1.soil_poisson", "uniform(0, 0.49)"}), "(no error)");
}

// One site (soil_shear_velocity, soil_density, soil_poisson without a building): the soil under
// every building on the soil (a cone, building 1, and a Gazetas footing, building 3), no other
// building's foundation touched; refused without one, or beside a building's own key for the
// same soil.
TEST(SampledFoundation, TheSitesSoilActsUnderEveryCone) {
  const Options opt =
      campaign_options({"--building3.foundation", "gazetas", "--building3.foundation_length", "8",
                        "--building3.foundation_width", "6", "--building3.soil_shear_velocity",
                        "300", "--building3.soil_density", "2000", "--building3.soil_poisson",
                        "0.25", "--sample.soil_shear_velocity", "uniform(100, 200)",
                        "--sample.soil_poisson", "uniform(0.35, 0.45)"});
  const BuildingRow row = row_from_options(opt);
  const std::vector<SampledParameter> params = read_sampled_parameters(opt, row);
  ASSERT_EQ(params.size(), 2u);
  EXPECT_EQ(params[0].key, "soil_poisson");
  EXPECT_EQ(params[1].key, "soil_shear_velocity");
  SampleModel m;
  m.row = row;
  apply_sampled(params, {0.4, 125.0}, m);
  for (const int b : {0, 2}) {
    EXPECT_EQ(m.row.buildings[b].foundation.soil_shear_velocity, 125.0) << b;
    EXPECT_EQ(m.row.buildings[b].foundation.soil_poisson, 0.4) << b;
  }
  EXPECT_EQ(m.row.buildings[0].foundation.soil_density, 1900.0);  // not sampled: its own
  EXPECT_EQ(m.row.buildings[2].foundation.soil_density, 2000.0);
  EXPECT_EQ(m.row.buildings[1].foundation.sway_stiffness, 1e8);  // springs: untouched

  EXPECT_EQ(error_of({"--sample.soil_density", "uniform(1800, 2000)",
                      "--sample.building1.soil_density", "uniform(1800, 2000)"}),
            "command line: --sample.soil_density: soil_density sets the soil under every building "
            "on the soil; sample it there or as building1.soil_density, not both");
  Options fixed("campaign", "", campaign_option_specs());
  fixed.parse({"--building1.masses", "1000", "--building1.stiffnesses", "2e6",
               "--sample.soil_density", "1900"});
  try {
    read_sampled_parameters(fixed, row_from_options(fixed));
    ADD_FAILURE() << "a site's soil without a cone was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "command line: --sample.soil_density: no building has foundation = cone or "
              "gazetas; the site's soil is sampled only under them");
  }
  EXPECT_NE(error_of({"--sample.soil_poisson", "uniform(0.3, 0.5)"})
                .find("soil_poisson must stay in [0, 0.5)"),
            std::string::npos);
}

// A campaign on soil samples it (issue 29): each sample's cone has its own shear wave velocity,
// the /samples column, and the samples are simulated.
TEST(SampledFoundation, ACampaignSamplesTheSoilAndSimulatesIt) {
  const CampaignStudy st = campaign_from_options(
      campaign_options({"--sample.building1.soil_shear_velocity", "uniform(100, 200)"}), 4, 1);
  SampleRunner runner(st);
  double lo = 1e300, hi = 0.0;
  for (long id = 0; id < 4; ++id) {
    const SampleOutcome o = runner.run(id);
    EXPECT_EQ(o.status, SampleStatus::ok) << o.message;
    ASSERT_EQ(o.values.size(), 1u);
    lo = std::min(lo, o.values[0]);
    hi = std::max(hi, o.values[0]);
  }
  EXPECT_GE(lo, 100.0);
  EXPECT_LE(hi, 200.0);
  EXPECT_GT(hi - lo, 10.0);  // the four samples have their own soils
}

}  // namespace
}  // namespace pound

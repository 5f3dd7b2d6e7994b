#include "campaign/sampled_parameters.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "campaign/campaign_study.hpp"
#include "campaign/sample.hpp"
#include "core/error.hpp"

namespace pound {
namespace {

// Two buildings on the El Centro record: building 1 with two storeys and yield shears (an
// elastic law: the shears set the yield drift of its ductility), building 2 with one storey and
// none; hc-linear with a fixed k, one PGA stripe.
CampaignStudy study(const std::vector<std::string>& extra, long samples = 8) {
  std::vector<std::string> args = {"--building1.masses",
                                   "1000, 1000",
                                   "--building1.stiffnesses",
                                   "2e6, 3e6",
                                   "--building1.yield_shears",
                                   "4e4, 3e4",
                                   "--building2.masses",
                                   "1500",
                                   "--building2.stiffnesses",
                                   "1e6",
                                   "--contact.model",
                                   "hc-linear",
                                   "--contact.k",
                                   "1e8",
                                   "--motion.source",
                                   "records",
                                   "--motion.file",
                                   POUND_SOURCE_DIR "/motions/elcentro-1940-ns.dat",
                                   "--motion.duration",
                                   "4",
                                   "--intensity.levels",
                                   "0.2"};
  args.insert(args.end(), extra.begin(), extra.end());
  Options opt("campaign", "", campaign_option_specs());
  opt.parse(args);
  return campaign_from_options(opt, samples, 5);
}

std::string error_of(const std::vector<std::string>& extra) {
  try {
    study(extra);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::size_t index_of(const CampaignStudy& st, const std::string& key) {
  for (std::size_t i = 0; i < st.parameters.size(); ++i)
    if (st.parameters[i].key == key) return i;
  ADD_FAILURE() << key << " is not sampled";
  return 0;
}

TEST(SampledParameters, EveryEntryHasAUnitAHelpAndWhatItActsOn) {
  const auto& table = sampled_parameter_table();
  const auto specs = sampled_option_specs();
  ASSERT_EQ(specs.size(), table.size());
  std::vector<std::string> keys;
  for (std::size_t i = 0; i < table.size(); ++i) {
    const auto& e = table[i];
    keys.push_back(e.key);
    EXPECT_EQ(specs[i].key, e.key);
    EXPECT_FALSE(std::string(e.help).empty()) << e.key;
    // Labels pick a value when drawn; every other parameter is applied to the sample.
    EXPECT_EQ(e.stage == SampleStage::label, e.apply == nullptr) << e.key;
    EXPECT_EQ(e.stage == SampleStage::label, std::string(e.unit).empty()) << e.key;
  }
  for (const char* k :
       {"e", "k", "k_factor", "gap", "damping", "model", "chi", "D", "building#.mass_scale",
        "building#.stiffness_scale", "building#.strength_scale", "hardening"})
    EXPECT_NE(std::find(keys.begin(), keys.end(), k), keys.end()) << k;
}

TEST(SampledParameters, ParametersComeInSortedKeyOrder) {
  const CampaignStudy st =
      study({"--sample.hardening", "uniform(0, 0.1)", "--sample.e", "uniform(0.5, 0.9)",
             "--sample.building1.strength_scale", "uniform(0.8, 1.2)", "--sample.gap",
             "uniform(0, 0.01)", "--sample.building1.mass_scale", "1.1"});
  std::vector<std::string> keys;
  for (const auto& p : st.parameters) keys.push_back(p.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"building1.mass_scale", "building1.strength_scale", "e",
                                            "gap", "hardening"}));
  EXPECT_EQ(st.parameters[1].building, 0);
  EXPECT_EQ(st.parameters[2].building, -1);
}

TEST(SampledParameters, StrengthScaleMultipliesTheYieldShearsOfItsBuildingOnly) {
  const CampaignStudy fixed = study({"--sample.building1.strength_scale", "1.3"});
  SampleRunner r(fixed);
  const SampleModel m = r.model(r.draw(0));
  ASSERT_EQ(m.row.buildings[0].yield_shears.size(), 2u);
  EXPECT_EQ(m.row.buildings[0].yield_shears[0], 4e4 * 1.3);
  EXPECT_EQ(m.row.buildings[0].yield_shears[1], 3e4 * 1.3);
  EXPECT_EQ(m.row.buildings[0].storey(1).Fy, 3e4 * 1.3);
  EXPECT_TRUE(m.row.buildings[1].yield_shears.empty());
  EXPECT_EQ(fixed.row.buildings[0].yield_shears[0], 4e4);  // the study itself is unchanged
  EXPECT_EQ(m.row.buildings[0].stiffnesses, fixed.row.buildings[0].stiffnesses);

  // A distribution: each sample's shears are the study's times that sample's draw.
  const CampaignStudy st = study({"--sample.building1.strength_scale", "uniform(0.8, 1.2)"});
  SampleRunner rs(st);
  const std::size_t i = index_of(st, "building1.strength_scale");
  for (long id = 0; id < st.samples; ++id) {
    const SampleDraw d = rs.draw(id);
    const SampleModel ms = rs.model(d);
    EXPECT_GE(d.values[i], 0.8);
    EXPECT_LE(d.values[i], 1.2);
    EXPECT_EQ(ms.row.buildings[0].yield_shears[0], 4e4 * d.values[i]) << id;
    EXPECT_EQ(ms.row.buildings[0].yield_shears[1], 3e4 * d.values[i]) << id;
  }
}

TEST(SampledParameters, HardeningSetsEveryStoreyOfEveryBuilding) {
  const CampaignStudy st = study({"--sample.hardening", "uniform(0, 0.1)"});
  SampleRunner r(st);
  for (long id = 0; id < st.samples; ++id) {
    const SampleDraw d = r.draw(id);
    const double b = d.values[index_of(st, "hardening")];
    const SampleModel m = r.model(d);
    EXPECT_GE(b, 0.0);
    EXPECT_LT(b, 0.1);
    for (const auto& bd : m.row.buildings) {
      EXPECT_EQ(bd.hardening, std::vector<double>(bd.masses.size(), b)) << id;
      for (int j = 0; j < bd.floors(); ++j) EXPECT_EQ(bd.storey(j).b, b) << id;
    }
  }
}

// `none` switches a sampled key off (a command line over a study that samples it): the
// parameter is not drawn and the row keeps its fixed value.
TEST(SampledParameters, NoneSwitchesASampledKeyOff) {
  const CampaignStudy on = study({"--sample.hardening", "uniform(0, 0.1)"});
  const CampaignStudy off = study({"--sample.hardening", " none "});
  ASSERT_EQ(on.parameters.size(), off.parameters.size() + 1);
  for (const auto& p : off.parameters) EXPECT_NE(p.key, "hardening");
  const CampaignStudy none = study({});
  EXPECT_EQ(off.parameters.size(), none.parameters.size());
  SampleRunner r(off), r0(none);
  const SampleModel m = r.model(r.draw(0)), m0 = r0.model(r0.draw(0));
  for (std::size_t b = 0; b < m.row.buildings.size(); ++b)
    for (int j = 0; j < m.row.buildings[b].floors(); ++j)
      EXPECT_EQ(m.row.buildings[b].storey(j).b, m0.row.buildings[b].storey(j).b);
  EXPECT_NE(error_of({"--sample.hardening", "nothing"}).find("sample.hardening"),
            std::string::npos);
}

TEST(SampledParameters, KFactorActsAfterTheStiffnessScalesAndChiDOnTheSearsModel) {
  const CampaignStudy st =
      study({"--sample.building2.stiffness_scale", "4", "--sample.k_factor", "10", "--sample.k",
             "5e7", "--sample.chi", "0.2", "--sample.D", "1.5", "--sample.e", "0.55"});
  SampleRunner r(st);
  const SampleModel m = r.model(r.draw(3));
  EXPECT_EQ(m.row.buildings[1].stiffnesses[0], 4e6);
  // The larger storey stiffness of the sample's row is building 2's scaled one; k_factor wins
  // over a sampled k.
  EXPECT_EQ(m.contact.params.k, 10 * 4e6);
  EXPECT_EQ(m.contact.params.e, 0.55);
  EXPECT_EQ(m.sears.chi, 0.2);
  EXPECT_EQ(m.sears.D, 1.5);
  EXPECT_EQ(st.sears.chi, 0.125);  // the study's Sears model keeps its fixed values
}

TEST(SampledParameters, BadValuesNameTheKeyAndWhatIsValid) {
  // A building without yield shears has no strength to scale.
  std::string m = error_of({"--sample.building2.strength_scale", "uniform(0.8, 1.2)"});
  for (const char* part : {"--sample.building2.strength_scale", "building2 has no yield_shears",
                           "building2.yield_shears", "hysteresis", "bilinear"})
    EXPECT_NE(m.find(part), std::string::npos) << part << " in: " << m;
  EXPECT_EQ(m.find('\n'), std::string::npos);
  m = error_of({"--sample.building1.strength_scale", "uniform(0, 1)"});
  EXPECT_NE(m.find("its values must be > 0"), std::string::npos) << m;
  // Hardening b = k_post / k0 in [0, 1).
  m = error_of({"--sample.hardening", "uniform(0.5, 1.5)"});
  EXPECT_NE(m.find("--sample.hardening = 'uniform(0.5, 1.5)'"), std::string::npos) << m;
  EXPECT_NE(m.find("[0, 1)"), std::string::npos) << m;
  EXPECT_NE(error_of({"--sample.hardening", "uniform(0.5, 1)"}).find("[0, 1)"), std::string::npos);
  EXPECT_NE(error_of({"--sample.hardening", "normal(0.02, 0.01)"}).find("must be >= 0"),
            std::string::npos);
  EXPECT_EQ(error_of({"--sample.hardening", "uniform(0, 0.99)"}), "(no error)");
  // A building the study does not have: the key given is named.
  m = error_of({"--sample.building3.strength_scale", "1.1"});
  EXPECT_NE(m.find("--sample.building3.strength_scale: the study has only 2 buildings (valid: "
                   "building1..building2)"),
            std::string::npos)
      << m;
  // Numbers far past the study, or past the range of a long (held at 10^9 and not found, the
  // message named "key 'sample.'"): the key given is named all the same.
  for (const std::string key : {"--sample.building2000000000000.strength_scale",
                                "--sample.building99999999999999999999999.strength_scale"}) {
    m = error_of({key, "1.1"});
    EXPECT_NE(m.find(key + ": the study has only 2 buildings (valid: building1..building2)"),
              std::string::npos)
        << m;
  }
  // The existing keys keep their messages.
  EXPECT_NE(error_of({"--sample.e", "uniform(0.5, 1.5)"}).find("e must stay in (0, 1]"),
            std::string::npos);
  EXPECT_NE(error_of({"--sample.D", "uniform(0.5, 2)"}).find("D must be >= 1; truncate at 1"),
            std::string::npos);
  EXPECT_NE(error_of({"--sample.damping", "uniform(0, 1)"}).find("damping must stay below 1"),
            std::string::npos);
}

TEST(SampledParameters, TheSampledContactModelTakesEveryModelNameTheDampedSearsModelIncluded) {
  // Not discrete: the names it may take, the damped Sears model's last (it was left out).
  const std::string m = error_of({"--sample.model", "uniform(0, 1)"});
  EXPECT_NE(m.find("--sample.model = 'uniform(0, 1)'"), std::string::npos) << m;
  EXPECT_NE(m.find("valid: discrete(name: weight, ...) with names from stereomechanical, lve, "
                   "mlve, nlve, hertzdamp, hertzdamp-ye, kelvin-ye, hc-linear, hc-hertz, sears"),
            std::string::npos)
      << m;
  // A name that is no model lists the same names.
  EXPECT_NE(error_of({"--sample.model", "discrete(hc-linear: 1, sear: 1)"})
                .find("unknown contact model 'sear'; valid: stereomechanical, lve, mlve, nlve, "
                      "hertzdamp, hertzdamp-ye, kelvin-ye, hc-linear, hc-hertz, sears"),
            std::string::npos);
  // The labels become each sample's model; only the sampled model parameter does that.
  const CampaignStudy st = study({"--sample.model", "discrete(hc-linear: 1, lve: 1)"}, 16);
  ASSERT_EQ(st.parameters.size(), 1u);
  EXPECT_TRUE(st.parameters[0].is_contact_model());
  SampleRunner r(st);
  int lve = 0;
  for (long id = 0; id < 16; ++id) lve += r.draw(id).model == "lve";
  EXPECT_EQ(lve, 8);  // Latin hypercube: half of the 16 samples in each of the two strata
  const CampaignStudy st2 = study({"--sample.e", "uniform(0.5, 0.8)"});
  EXPECT_FALSE(st2.parameters[0].is_contact_model());
}

}  // namespace
}  // namespace pound

// Options glue of `pound impact --model sears` and the thesis chapter 7 study file.
#include "sears/sears_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "io/options.hpp"
#include "sears/contact_stiffness.hpp"

namespace pound::sears {
namespace {

// The common options of `pound impact` that the sears options rely on (declared by the caller
// in src/app/cmd_impact.cpp; repeated here so that the glue is tested alone).
Options impact_options(const std::vector<std::string>& args) {
  std::vector<OptionSpec> specs = sears_impact_option_specs();
  specs.push_back({"model", "", "sears", "contact model"});
  specs.push_back({"m1", "kg", "1", "mass of body 1"});
  specs.push_back({"m2", "kg", "1", "mass of body 2"});
  specs.push_back({"v0", "m/s", "1", "approach velocity"});
  specs.push_back({"dt", "s", "", "step"});
  specs.push_back({"k", "N/m or N/m^1.5", "", "contact stiffness"});
  Options opt("impact", "test", specs);
  opt.parse(args);
  return opt;
}

std::string error_of(const std::vector<std::string>& args) {
  try {
    sears_impact_spec_from(impact_options(args), 10.0, 20.0, 0.5);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SearsOptions, FlatContactStiffnessFollowsFromTheSlabs) {
  const Options opt = impact_options(
      {"--length1", "20", "--length2", "12", "--E", "21e9", "--rho", "2500", "--D", "2"});
  const SearsImpactSpec s = sears_impact_spec_from(opt, 48000.0, 29000.0, 0.1);
  EXPECT_EQ(s.contact.kind, ContactKind::flat);
  EXPECT_DOUBLE_EQ(s.contact.stiffness, flat_contact_stiffness(s.bar1, s.bar2, 2.0));
  EXPECT_EQ(s.modes, 100);
  EXPECT_DOUBLE_EQ(s.xi_s, 0.05);
  EXPECT_DOUBLE_EQ(s.bar1.chi, 0.125);
  EXPECT_DOUBLE_EQ(s.bar2.mass_kg, 29000.0);
  EXPECT_TRUE(std::isinf(s.contact.force_cap_N));
}

TEST(SearsOptions, HertzFromRadiiWithPerBarMaterials) {
  const Options opt = impact_options(
      {"--length1", "0.335", "--length2", "0.32",      "--E",         "200e9",     "--E2",
       "100e9",     "--rho", "7850",      "--poisson", "0.3",         "--contact", "hertz",
       "--radius1", "0.015", "--modes",   "40",        "--force-cap", "5e4"});
  const SearsImpactSpec s = sears_impact_spec_from(opt, 8.7, 8.6, 0.02);
  EXPECT_EQ(s.contact.kind, ContactKind::hertz);
  EXPECT_DOUBLE_EQ(s.bar2.E_Pa, 100e9);
  EXPECT_DOUBLE_EQ(s.contact.stiffness,
                   hertz_stiffness(200e9, 0.3, 0.015, 100e9, 0.3, kFlatRadius));
  EXPECT_EQ(s.modes, 40);
  EXPECT_DOUBLE_EQ(s.contact.force_cap_N, 5e4);
}

TEST(SearsOptions, ErrorsNameTheKeyAndWhatIsValid) {
  const std::vector<std::string> base = {"--length1", "1",    "--length2", "1",
                                         "--E",       "2e11", "--rho",     "7850"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return error_of(a);
  };
  EXPECT_EQ(with({}), "");
  EXPECT_NE(with({"--contact", "round"}).find("--contact = 'round': valid values: flat, hertz"),
            std::string::npos);
  EXPECT_NE(error_of({"--length2", "1", "--E", "2e11", "--rho", "7850"}).find("length1"),
            std::string::npos);
  EXPECT_NE(error_of({"--length1", "1", "--length2", "1", "--rho", "7850"}).find("--E or --E1"),
            std::string::npos);
  EXPECT_NE(with({"--contact", "hertz", "--poisson", "0.3"}).find("--radius1"), std::string::npos);
  EXPECT_NE(with({"--xi-s", "1.2"}).find("xi-s"), std::string::npos);
  EXPECT_NE(with({"--modes", "2.5"}).find("whole number"), std::string::npos);
  const std::string dt = with({"--dt", "1e-3"});
  EXPECT_NE(dt.find("command line: --dt = '1e-3'"), std::string::npos) << dt;
  EXPECT_NE(dt.find("largest allowed step"), std::string::npos) << dt;
}

// Thesis ch. 7, single RC slab pendulums: impulse at full wave speed and at c/8 for the eight
// impact velocities. Prints the table quoted in docs/sears.md.
TEST(SearsStudy, Chapter7PendulumImpulses) {
  const std::string ini = std::string(POUND_SOURCE_DIR) + "/studies/ch7-pendulums.ini";
  const double speeds[] = {0.030, 0.040, 0.096, 0.146, 0.171, 0.183, 0.226, 0.243};
  std::printf("| v0 (m/s) | J, c (N s) | e, c | J, c/8 (N s) | e, c/8 | phases c/8 |\n");
  std::printf("|---|---|---|---|---|---|\n");
  double previous = 0.0;
  for (double v0 : speeds) {
    double J[2], e[2];
    int phases = 0;
    for (int i = 0; i < 2; ++i) {
      const Options opt = impact_options(
          {"--config", ini, "--v0", std::to_string(v0), "--chi", i == 0 ? "1" : "0.125"});
      const SearsImpactSpec s = sears_impact_spec_from(opt, opt.get_double("m1"),
                                                       opt.get_double("m2"), opt.get_double("v0"));
      ASSERT_DOUBLE_EQ(s.contact.stiffness, 3.21e9);
      const SearsImpactOutcome o = run_sears_impact(s);
      J[i] = o.impact.impulse_Ns;
      e[i] = o.impact.e_eff;
      phases = o.impact.contact_phases;
      // Impulse-momentum: J = m* (1 + e) v0 with m* = 109 * 108 / 217 kg.
      EXPECT_NEAR(J[i], 109.0 * 108.0 / 217.0 * (1.0 + e[i]) * v0, 1e-10 * J[i]);
    }
    std::printf("| %.3f | %.4f | %.4f | %.4f | %.4f | %d |\n", v0, J[0], e[0], J[1], e[1], phases);
    // The thesis: "the two velocities produce very similar calculated impulse".
    EXPECT_NEAR(J[1] / J[0], 1.0, 0.03) << v0;
    EXPECT_GT(e[0], e[1]);  // slower waves leave more energy in the slabs
    EXPECT_GT(J[0], previous);
    previous = J[0];
  }
}

}  // namespace
}  // namespace pound::sears

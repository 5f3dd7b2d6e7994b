// The `pound` program as a user meets it: bad input gives one line on stderr naming the file,
// the key and what is valid, a non-zero exit code and no output file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "../support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;

struct CmdResult {
  int code = -1;
  std::string out, err;
};

CmdResult run_pound(const std::string& args) {
  const fs::path dir = pound::test::process_scratch_dir().path();
  const std::string out = (dir / "out.txt").string(), err = (dir / "err.txt").string();
  const std::string cmd = std::string(POUND_BINARY) + " " + args + " >" + out + " 2>" + err;
  const int status = std::system(cmd.c_str());
  CmdResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream o(out), e(err);
  r.out.assign(std::istreambuf_iterator<char>(o), {});
  r.err.assign(std::istreambuf_iterator<char>(e), {});
  return r;
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_ = std::make_unique<pound::test::ScratchDir>("pound_cli_case_");
    dir_ = scratch_->path();
    motion_ = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  }
  void TearDown() override { scratch_.reset(); }

  // A valid two-building study with one line replaced.
  std::string study(const std::string& replace_from = "", const std::string& replace_to = "") {
    std::string text =
        "[building1]\nmasses = 1000, 1000\nstiffnesses = 1e6, 1e6\n"
        "[building2]\nmasses = 1000\nstiffnesses = 5e5\n"
        "[pair1]\ngap = 0.01\n"
        "[contact]\nmodel = hc-linear\ne = 0.5\nk = 5e7\n"
        "[motion]\nfile = " +
        motion_ + "\nduration = 2\n";
    if (!replace_from.empty()) {
      const auto p = text.find(replace_from);
      EXPECT_NE(p, std::string::npos) << replace_from;
      text.replace(p, replace_from.size(), replace_to);
    }
    const std::string path = (dir_ / "study.ini").string();
    std::ofstream(path) << text;
    return path;
  }
  std::string h5() const { return (dir_ / "hist.h5").string(); }

  // Expects exit code 2, one line on stderr containing every fragment, no histories file.
  void expect_error(const std::string& study_path, std::initializer_list<std::string> fragments) {
    const CmdResult r = run_pound("simulate --config " + study_path + " --histories " + h5());
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    for (const auto& f : fragments)
      EXPECT_NE(r.err.find(f), std::string::npos) << f << " in: " << r.err;
    EXPECT_FALSE(fs::exists(h5()));
    for (const auto& entry : fs::directory_iterator(dir_))
      EXPECT_EQ(entry.path().filename().string().find("hist.h5"), std::string::npos);
  }

  std::unique_ptr<pound::test::ScratchDir> scratch_;
  fs::path dir_;
  std::string motion_;
};

TEST_F(Cli, ValidStudyWritesHistoriesAndJson) {
  const CmdResult r = run_pound("simulate --config " + study() + " --json --histories " + h5());
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"disp_amplification\""), std::string::npos);
  EXPECT_NE(r.out.find("\"impacts\""), std::string::npos);
  EXPECT_TRUE(fs::exists(h5()));
}

TEST_F(Cli, UnknownKey) {
  expect_error(study("gap = 0.01", "gap = 0.01\ngpa = 3"),
               {"study.ini:9", "pair1.gpa", "pair#.gap"});
}

TEST_F(Cli, MissingMotionFile) {
  expect_error(study(motion_, "/nonexistent/motion.dat"), {"/nonexistent/motion.dat"});
}

TEST_F(Cli, NegativeMass) {
  expect_error(study("masses = 1000, 1000", "masses = 1000, -1000"),
               {"study.ini:2", "building1.masses", "> 0"});
}

TEST_F(Cli, NanMass) {
  expect_error(study("masses = 1000\n", "masses = nan\n"), {"study.ini:5", "building2.masses"});
}

TEST_F(Cli, RestitutionOutsideUnitInterval) {
  expect_error(study("e = 0.5", "e = 1.5"), {"study.ini:11", "contact.e", "(0, 1]"});
  expect_error(study("e = 0.5", "e = 0"), {"contact.e", "(0, 1]"});
}

TEST_F(Cli, GapNotANumber) {
  expect_error(study("gap = 0.01", "gap = abc"), {"study.ini:8", "pair1.gap", "'abc'"});
}

TEST_F(Cli, UnknownContactModel) {
  expect_error(study("model = hc-linear", "model = hertz"), {"contact.model", "hc-hertz", "lve"});
}

TEST_F(Cli, MotionFileWithNonNumericLine) {
  const std::string bad = (dir_ / "bad.txt").string();
  std::ofstream(bad) << "0.0 0.01\n0.01 0.02\n0.02 x7\n0.03 0.01\n";
  expect_error(study(motion_, bad + "\nunits = g"), {"bad.txt:3"});
}

TEST_F(Cli, SearsStepTooLargeIsOneLineBeforeAnyOutput) {
  // The largest allowed step of the chapter 8 pair is T_min / 2 = l / (N c), about 0.33 ms.
  expect_error(std::string(POUND_SOURCE_DIR) + "/studies/ch8-five-three.ini --sears.dt 1e-2",
               {"--sears.dt = '1e-2'", "largest allowed step is 0.000331"});
}

TEST_F(Cli, YieldingStoreyKeysAreValidated) {
  // Issue 16: a missing yield_shears for an inelastic law, Fy <= 0, b outside [0, 1), n <= 0
  // and an unknown law each give one line naming the key and what is valid.
  const std::string b1 = "stiffnesses = 1e6, 1e6\n";
  expect_error(study(b1, b1 + "hysteresis = bilinear\n"),
               {"study.ini", "building1.yield_shears", "missing", "Fy > 0"});
  expect_error(study(b1, b1 + "hysteresis = bouc-wen\nyield_shears = 2e4, 0\n"),
               {"study.ini:5", "building1.yield_shears", "> 0"});
  expect_error(study(b1, b1 + "hysteresis = bilinear\nyield_shears = 2e4\nhardening = 1\n"),
               {"study.ini:6", "building1.hardening", "[0, 1)"});
  expect_error(study(b1, b1 + "hardening = -0.1\n"), {"building1.hardening", "[0, 1)"});
  expect_error(study(b1, b1 + "hysteresis = bouc-wen\nyield_shears = 2e4\nbw_n = 0\n"),
               {"study.ini:6", "building1.bw_n", "n > 0"});
  expect_error(study(b1, b1 + "hysteresis = takeda\n"),
               {"study.ini:4", "building1.hysteresis", "elastic, bilinear, bouc-wen"});
  expect_error(study(b1, b1 + "yield_shears = 1e4, 2e4, 3e4\n"),
               {"building1.yield_shears", "expected 2 values"});
}

TEST_F(Cli, ImkStoreyKeysAreValidated) {
  // Issue 23: Fc / Fy < 1, theta_p, theta_pc or lambda <= 0, Fr / Fy outside [0, 1) and theta_u
  // below the cap each give one line naming the key and what is valid, exit 2, no file.
  const std::string b1 = "stiffnesses = 1e6, 1e6\n";
  const std::string imk = b1 + "hysteresis = imk\nyield_shears = 2e4\n";
  expect_error(study(b1, imk + "cap_strength_ratio = 0.9\n"),
               {"study.ini:6", "building1.cap_strength_ratio", "Fc / Fy >= 1"});
  expect_error(study(b1, imk + "plastic_drift_ratio = 0\n"),
               {"study.ini:6", "building1.plastic_drift_ratio", "theta_p > 0"});
  expect_error(study(b1, imk + "post_cap_drift_ratio = -0.1\n"),
               {"building1.post_cap_drift_ratio", "theta_pc > 0"});
  expect_error(study(b1, imk + "energy_capacity = 0\n"),
               {"building1.energy_capacity", "lambda > 0"});
  expect_error(study(b1, imk + "residual_strength_ratio = 1\n"),
               {"building1.residual_strength_ratio", "[0, 1)"});
  // uy / h + theta_p = 0.02 / 3 + 0.06
  expect_error(study(b1, imk + "ultimate_drift_ratio = 0.06\n"),
               {"study.ini:6", "building1.ultimate_drift_ratio", "0.0666667"});
  expect_error(study(b1, b1 + "hysteresis = imk\n"), {"building1.yield_shears", "missing"});
}

TEST_F(Cli, YieldingStoreysAreReportedWithTheEnergyBalance) {
  const std::string b1 = "stiffnesses = 1e6, 1e6\n";
  const CmdResult r =
      run_pound("simulate --config " +
                study(b1, b1 + "hysteresis = bilinear\nyield_shears = 8e3\nhardening = 0.05\n") +
                " --motion.scale 3 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"residual_drift_ratio_pounding", "ductility_free",
                        "hysteretic_energy_pounding_J", "energy_pounding", "residual_J"})
    EXPECT_NE(r.out.find(std::string("\"") + f + "\""), std::string::npos) << f;
  const auto p = r.out.find("\"ductility_free\":");
  EXPECT_GT(std::stod(r.out.substr(p + 17)), 1.0) << r.out;  // the first storey yields
}

TEST_F(Cli, KeysTheChosenModelDoesNotReadAreNoted) {
  // A lumped study given a Sears key, and a Sears study given a lumped contact key: each runs,
  // with one note naming the key and where it came from.
  const CmdResult lumped = run_pound("simulate --config " + study() + " --sears.chi 0.2");
  EXPECT_EQ(lumped.code, 0) << lumped.err;
  EXPECT_NE(lumped.err.find("note: command line: --sears.chi is not used by contact model"),
            std::string::npos)
      << lumped.err;
  const CmdResult sears =
      run_pound("simulate --config " + std::string(POUND_SOURCE_DIR) +
                "/studies/ch8-five-three.ini --motion.duration 1 --contact.e 0.5");
  EXPECT_EQ(sears.code, 0) << sears.err;
  EXPECT_NE(sears.err.find("note: command line: --contact.e is not used by contact model sears"),
            std::string::npos)
      << sears.err;
  EXPECT_EQ(sears.err.find("slab_length"), std::string::npos) << sears.err;  // used by sears
  // The note, the run's line, its contact sites (issue 36) and the Sears step.
  EXPECT_NE(sears.err.find("pound simulate: pair 1 (5-storey | 3-storey): floors 1-3 slab to "
                           "slab\n"),
            std::string::npos)
      << sears.err;
  EXPECT_EQ(std::count(sears.err.begin(), sears.err.end(), '\n'), 4) << sears.err;
}

TEST_F(Cli, CommandLineOverridesStudyAndIsValidated) {
  const CmdResult r = run_pound("simulate --config " + study() + " --contact.e 2");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--contact.e"), std::string::npos) << r.err;
}

TEST_F(Cli, ImpactJsonHasTheDocumentedFields) {
  const CmdResult r = run_pound("impact --model lve --e 0.4 --k 1e6 --m1 2 --m2 3 --v0 0.5 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"e_eff", "contact_duration_s", "impulse_Ns", "peak_force_N",
                        "max_penetration_m", "v1_after", "v2_after"})
    EXPECT_NE(r.out.find(std::string("\"") + f + "\""), std::string::npos) << f;
  const auto p = r.out.find("\"e_eff\":");
  EXPECT_NEAR(std::stod(r.out.substr(p + 8)), 0.4, 1e-7);
}

TEST_F(Cli, HelpListsUnitsAndDefaults) {
  const CmdResult r = run_pound("simulate --help");
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--building#.masses"), std::string::npos);
  EXPECT_NE(r.out.find("[kg]"), std::string::npos);
  EXPECT_NE(r.out.find("(default lve)"), std::string::npos);
}

// Issue 14, a new user's trial: each rough edge is a fix with its test.
TEST_F(Cli, HexadecimalMassOnTheCommandLineIsRefused) {
  expect_error(study() + " --building1.masses 0x10,1000",
               {"--building1.masses", "'0x10' is not a finite number",
                "a decimal number such as 16, -0.5 or 2.1e9", "[kg]"});
  expect_error(study() + " --pair1.gap inf", {"--pair1.gap", "'inf'", "[m]"});
}

TEST_F(Cli, StudySavedWithAByteOrderMarkRuns) {
  const std::string path = study();
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  std::ofstream(path) << "\xEF\xBB\xBF" << text;
  const CmdResult r = run_pound("simulate --config " + path + " --json");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"disp_amplification\""), std::string::npos);
}

TEST_F(Cli, DirectoryGivenAsTheMotionFileIsNamedSo) {
  expect_error(study(motion_, dir_.string()),
               {dir_.string() + ": is a directory, not a motion file"});
}

TEST_F(Cli, ImplausibleRecordIsRefusedUnlessTheCheckIsOff) {
  const std::string rec = (dir_ / "huge.txt").string();
  std::ofstream(rec) << "# units: g\n# dt: 0.01\n0.0\n1e30\n-1e30\n0.0\n";
  expect_error(study(motion_, rec),
               {"huge.txt: peak ground acceleration 1e+30 g",
                "read as g as the header states on line 1", "[motion] check_pga = false"});
  // With the check off the record is read (here scaled back to 1 g) and simulated.
  const CmdResult r = run_pound("simulate --config " + study(motion_, rec) +
                                " --motion.check_pga false --motion.scale 1e-30");
  EXPECT_EQ(r.code, 0) << r.err;
  expect_error(study(motion_, rec) + " --motion.check_pga maybe",
               {"--motion.check_pga", "true or false"});
}

}  // namespace

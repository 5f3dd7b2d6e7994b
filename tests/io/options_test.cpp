// Options from the command line and a study file: numbered keys, where a value came from, and
// the "what is valid" part of every error.
#include "io/options.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "../support/scratch_dir.hpp"

namespace pound {
namespace {

std::vector<OptionSpec> specs() {
  return {{"pair#.gap", "m", "0", "at-rest gap between building # and #+1"},
          {"building#.masses", "kg", "", "floor masses of building #"},
          {"contact.e", "-", "0.65", "coefficient of restitution, in (0, 1]"}};
}

// The InputError message of parsing `args` and reading `key` as a number.
std::string error_of(const std::vector<std::string>& args, const std::string& key) {
  Options o("simulate", "", specs());
  try {
    o.parse(args);
    o.get_doubles(key);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Options, NumberedKeyErrorsNameTheirOwnBuildings) {
  EXPECT_EQ(error_of({"--pair2.gap", "abc"}, "pair2.gap"),
            "command line: --pair2.gap: 'abc' is not a finite number (valid: a decimal number "
            "such as 16, -0.5 or 2.1e9); expected at-rest gap between building 2 and 3 [m]");
  EXPECT_EQ(error_of({"--building12.masses", "1e3,x"}, "building12.masses").substr(0, 40),
            "command line: --building12.masses: 'x' i");
  EXPECT_NE(error_of({"--building12.masses", "1e3,x"}, "building12.masses")
                .find("expected floor masses of building 12 [kg]"),
            std::string::npos);
  // A dimensionless key shows no unit.
  EXPECT_EQ(error_of({"--contact.e", "half"}, "contact.e"),
            "command line: --contact.e: 'half' is not a finite number (valid: a decimal number "
            "such as 16, -0.5 or 2.1e9); expected coefficient of restitution, in (0, 1]");
}

TEST(Options, MissingNumberedKeyNamesTheFileAndTheBuilding) {
  const std::string ini = pound::test::process_scratch_dir() / "study.ini";
  std::ofstream(ini) << "[building1]\nmasses = 1000\n";
  const std::string msg = error_of({"--config", ini}, "building3.masses");
  EXPECT_EQ(msg, ini + ": key 'building3.masses': missing; floor masses of building 3 [kg]");
}

TEST(Options, FileValuesNameTheirLineAndTheCommandLineWins) {
  const std::string ini = pound::test::process_scratch_dir() / "lines.ini";
  std::ofstream(ini) << "# a study\n[pair1]\ngap = 0.02\n[contact]\ne = 2x\n";
  Options o("simulate", "", specs());
  const char* argv[] = {"simulate", "--config", ini.c_str(), "--pair1.gap", "0.03"};
  o.parse(5, argv);
  EXPECT_DOUBLE_EQ(o.get_double("pair1.gap"), 0.03);
  EXPECT_EQ(o.where("pair1.gap"), "command line: --pair1.gap");
  try {
    o.get_double("contact.e");
    FAIL() << "2x was read as a number";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(ini + ":5: key 'contact.e': '2x'", 0), 0u) << e.what();
  }
}

TEST(Options, UnknownKeySuggestsTheDeclaredOne) {
  const std::string ini = pound::test::process_scratch_dir() / "typo.ini";
  std::ofstream(ini) << "[pair1]\ngpa = 0.02\n";
  Options o("simulate", "", specs());
  try {
    o.parse({"--config", ini});
    FAIL() << "an unknown key was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(ini + ":2"), std::string::npos) << m;
    EXPECT_NE(m.find("pair1.gpa"), std::string::npos) << m;
    EXPECT_NE(m.find("pair#.gap"), std::string::npos) << m;
  }
}

// A study stored in a result file (its resolved "key = value" lines) is read as a file is.
TEST(Options, StudyTextIsReadAsAFileWithItsNameAndLines) {
  Options o("campaign", "", specs());
  o.parse_text("building1.masses = 1e5, 2e5\npair1.gap = 0.02\n", "run.h5 (stored study)");
  EXPECT_EQ(o.get_doubles("building1.masses"), (std::vector<double>{1e5, 2e5}));
  EXPECT_DOUBLE_EQ(o.get_double("pair1.gap"), 0.02);
  EXPECT_DOUBLE_EQ(o.get_double("contact.e"), 0.65);  // a default
  EXPECT_EQ(o.where("pair1.gap"), "run.h5 (stored study):2: key 'pair1.gap'");
  Options bad("campaign", "", specs());
  try {
    bad.parse_text("pair1.gap = 0.02\npair1.gpa = 0.01\n", "run.h5 (stored study)");
    FAIL() << "an unknown key was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("run.h5 (stored study):2: unknown key 'pair1.gpa'"),
              std::string::npos)
        << e.what();
  }
}

TEST(Options, UnknownCommandLineKeyListsItsSection) {
  Options o("simulate", "", specs());
  try {
    o.parse({"--pair1.gpa", "0.02"});
    FAIL() << "an unknown option was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "command line: unknown option '--pair1.gpa' for 'pound simulate'; valid keys: "
              "pair#.gap");
  }
}

TEST(Options, HexadecimalMassIsRefusedWithTheKeyAndTheValidForm) {
  // strtod reads 0x10 as 16: a user's "0x10 kg" must not become 16 kg.
  const std::string m = error_of({"--building1.masses", "0x10"}, "building1.masses");
  EXPECT_EQ(m,
            "command line: --building1.masses: '0x10' is not a finite number (valid: a decimal "
            "number such as 16, -0.5 or 2.1e9); expected floor masses of building 1 [kg]");
  for (const char* bad : {"inf", "nan", "12kg", "1e", "1000 0x10", "1,2,,3e"})
    EXPECT_NE(error_of({"--building1.masses", bad}, "building1.masses").find("building1.masses"),
              std::string::npos)
        << bad;
  EXPECT_EQ(error_of({"--building1.masses", "1e3, 2.5E+3 .5"}, "building1.masses"), "");
}

TEST(Options, StudyFileWithAUtf8ByteOrderMarkIsRead) {
  const std::string ini = pound::test::process_scratch_dir() / "bom.ini";
  std::ofstream(ini) << "\xEF\xBB\xBF[pair1]\r\ngap = 0.02\r\n[contact]\r\ne = 0.5\r\n";
  Options o("simulate", "", specs());
  o.parse({"--config", ini});
  EXPECT_DOUBLE_EQ(o.get_double("pair1.gap"), 0.02);
  EXPECT_EQ(o.where("pair1.gap"), ini + ":2: key 'pair1.gap'");
  EXPECT_DOUBLE_EQ(o.get_double("contact.e"), 0.5);
  // Only at the very start: a mark inside the text is no white space.
  std::ofstream(ini) << "[pair1]\n\xEF\xBB\xBFgap = 0.02\n";
  Options o2("simulate", "", specs());
  EXPECT_THROW(o2.parse({"--config", ini}), InputError);
}

TEST(Options, ADirectoryGivenAsTheStudyFileIsNamedSo) {
  const std::string d = pound::test::process_scratch_dir().path();
  Options o("simulate", "", specs());
  try {
    o.parse({"--config", d});
    FAIL() << "a directory was read as a study";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              d + ": is a directory, not a study file; give the study file (INI)");
  }
}

// Found by fuzz_study (issue 14): a building number past the range of an int overflowed while
// counting the buildings (undefined behaviour). The numbered sections come from the keys given,
// each with its first key; a number past the range of a long is held at the largest long.
TEST(Options, NumberedSectionsComeFromTheKeysGivenWithoutOverflow) {
  Options o("simulate", "", specs());
  o.parse({"--building1.masses", "1", "--building2000000000000.masses", "1",
           "--building99999999999999999999999.masses", "1", "--pair999999999.gap", "0.1"});
  const auto b = o.numbered_sections("building");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_EQ(b.at(1), "building1.masses");
  EXPECT_EQ(b.at(2000000000000L), "building2000000000000.masses");
  EXPECT_EQ(b.at(std::numeric_limits<long>::max()), "building99999999999999999999999.masses");
  const auto p = o.numbered_sections("pair");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p.at(999999999), "pair999999999.gap");
  EXPECT_TRUE(o.numbered_sections("contact").empty());  // "contact.e": no number
  Options q("simulate", "", specs());
  q.parse({"--building1.masses", "1", "--building12.masses", "1"});
  EXPECT_EQ(q.numbered_sections("building"),
            (std::map<long, std::string>{{1, "building1.masses"}, {12, "building12.masses"}}));
}

}  // namespace
}  // namespace pound

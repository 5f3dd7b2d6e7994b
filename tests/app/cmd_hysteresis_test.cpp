// pound hysteresis, the storey-law tester (issue 23), as a user meets it: CSV and JSON output
// for every registered law, the numbers of the library's drive(), and bad input: one line on
// stderr naming the key and what is valid, exit code 2, nothing on stdout.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/scratch_dir.hpp"
#include "hysteresis/drive.hpp"
#include "hysteresis/registry.hpp"

namespace {

struct Outcome {
  int code = -1;
  std::string out, err;
};

const pound::test::ScratchDir& dir() {
  static const pound::test::ScratchDir d("pound_hysteresis_cmd_");
  return d;
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

Outcome pound_hysteresis(const std::string& args) {
  const std::string out = dir() / "out.txt", err = dir() / "err.txt";
  const int s = std::system(
      (std::string(POUND_BINARY) + " hysteresis " + args + " >" + out + " 2>" + err).c_str());
  return {WIFEXITED(s) ? WEXITSTATUS(s) : -1, slurp(out), slurp(err)};
}

// A drift history file [m].
std::string drifts_file(const std::vector<double>& d, const std::string& name = "d.txt") {
  const std::string path = dir() / name;
  std::ofstream f(path);
  for (double x : d) f << x << "\n";
  return path;
}

const std::vector<double> kDrifts = {0.002, 0.01, 0.03, 0.045, 0.02, -0.01, -0.05, 0.0, 0.08};

// The CSV's data lines as (drift, shear) pairs.
std::vector<std::pair<double, double>> rows(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "drift_m,shear_N");
  std::vector<std::pair<double, double>> r;
  while (std::getline(in, line)) {
    const auto c = line.find(',');
    r.push_back({std::stod(line.substr(0, c)), std::stod(line.substr(c + 1))});
  }
  return r;
}

const char* const kImk =
    "--law imk --k0 2e7 --fy 2e5 --height 3 --cap_strength_ratio 1.15 "
    "--plastic_drift_ratio 0.04 --post_cap_drift_ratio 0.08 --residual_strength_ratio 0.2 "
    "--energy_capacity 50 --energy_exponent 1.2 --ultimate_drift_ratio 0.2";

TEST(HysteresisCommand, CsvOfEveryLawHasOneLinePerDrift) {
  const std::string file = drifts_file(kDrifts);
  for (const auto& law : pound::storey_laws()) {
    const Outcome r = pound_hysteresis("--law " + law.name + " --k0 2e7 --fy 2e5 --drifts " + file);
    ASSERT_EQ(r.code, 0) << law.name << ": " << r.err;
    EXPECT_EQ(r.err, "");
    const auto v = rows(r.out);
    ASSERT_EQ(v.size(), kDrifts.size()) << law.name;
    for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i].first, kDrifts[i]);
    // From rest, the first drift 0.002 m = uy / 5 is elastic (k0 d) for every law but the
    // smooth Bouc-Wen one, 1.3 % below it there (n = 2).
    EXPECT_NEAR(v[0].second, 2e7 * 0.002, law.name == "bouc-wen" ? 600.0 : 1e-6) << law.name;
  }
  // The IMK storey's backbone: 0.03 m on the post-yield line Fy + Kp (d - uy) with
  // Kp = 0.15 Fy / (0.04 x 3) N/m.
  const auto v = rows(pound_hysteresis(std::string(kImk) + " --drifts " + file).out);
  EXPECT_NEAR(v[2].second, 2e5 + 0.15 * 2e5 / 0.12 * (0.03 - 0.01), 1e-6);
}

TEST(HysteresisCommand, NumbersAreTheLibrarysDriveToTheLastDigit) {
  // A cyclic history through the IMK law's deterioration, printed with 17 digits.
  std::vector<double> d;
  for (int i = 1; i <= 2000; ++i)
    d.push_back(0.06 * (i / 2000.0) * std::sin(2 * 3.141592653589793 * i / 200.0));
  const Outcome r = pound_hysteresis(std::string(kImk) + " --drifts " + drifts_file(d, "c.txt"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto v = rows(r.out);
  pound::StoreyParameters p;
  p.k0 = 2e7;
  p.Fy = 2e5;
  p.h = 3;
  p.cap_strength_ratio = 1.15;
  p.plastic_drift_ratio = 0.04;
  p.post_cap_drift_ratio = 0.08;
  p.residual_strength_ratio = 0.2;
  p.energy_capacity = 50;
  p.energy_exponent = 1.2;
  p.ultimate_drift_ratio = 0.2;
  std::vector<double> read;
  for (const auto& x : v) read.push_back(x.first);
  const auto shear = pound::drive(pound::find_storey_law("imk", ""), p, read);
  ASSERT_EQ(v.size(), shear.size());
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i].second, shear[i]) << i;
}

TEST(HysteresisCommand, JsonHasTheTwoArrays) {
  const Outcome r = pound_hysteresis("--law elastic --k0 1e6 --drifts " +
                                     drifts_file({0.001, -0.002}, "e.txt") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "{\"drift_m\":[0.001,-0.002],\"shear_N\":[1000,-2000]}\n");
  const Outcome b = pound_hysteresis("--law bouc-wen --k0 2e7 --fy 2e5 --bw_n 5 --json --drifts " +
                                     drifts_file(kDrifts));
  ASSERT_EQ(b.code, 0) << b.err;
  EXPECT_EQ(b.out.rfind("{\"drift_m\":[", 0), 0u) << b.out;
  EXPECT_NE(b.out.find("],\"shear_N\":["), std::string::npos) << b.out;
}

TEST(HysteresisCommand, BadInputIsOneLineNamingTheKeyWithExitCode2) {
  const std::string file = drifts_file(kDrifts);
  const std::string imk = "--law imk --k0 2e7 --fy 2e5 --drifts " + file;
  const std::string bad = drifts_file({}, "empty.txt");
  { std::ofstream(dir() / "text.txt") << "0.01\n0.02 m\n"; }
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {imk + " --cap_strength_ratio 0.9", {"--cap_strength_ratio = '0.9'", "Fc / Fy >= 1"}},
      {imk + " --plastic_drift_ratio 0", {"--plastic_drift_ratio = '0'", "theta_p > 0"}},
      {imk + " --post_cap_drift_ratio -1", {"--post_cap_drift_ratio = '-1'", "theta_pc > 0"}},
      {imk + " --energy_capacity 0", {"--energy_capacity = '0'", "lambda > 0"}},
      {imk + " --energy_exponent 0", {"--energy_exponent = '0'", "c > 0"}},
      {imk + " --residual_strength_ratio 1", {"--residual_strength_ratio = '1'", "[0, 1)"}},
      {imk + " --residual_strength_ratio -0.1", {"--residual_strength_ratio", "[0, 1)"}},
      {imk + " --ultimate_drift_ratio 0.05",
       {"--ultimate_drift_ratio = '0.05'", "cap drift ratio uy / h + theta_p = 0.0633333"}},
      {imk + " --hardeningg 0.1", {"unknown option '--hardeningg'"}},
      {"--law imk --k0 abc --fy 2e5 --drifts " + file, {"--k0: 'abc' is not a finite number"}},
      {"--law imk --k0 -1 --fy 2e5 --drifts " + file, {"--k0 = '-1'"}},
      {imk + " --height 0", {"--height = '0'"}},
      {imk + " --fy 2e5", {"--fy", "more than once"}},
      {"--law takeda --k0 1 --drifts " + file, {"--law", "elastic, bilinear, bouc-wen, imk"}},
      {"--law imk --k0 2e7 --drifts " + file, {"--fy is required by law 'imk'"}},
      {"--k0 2e7 --drifts " + file, {"--law is required"}},
      {"--law imk --k0 2e7 --fy 2e5", {"--drifts FILE is required"}},
      {"--law imk --k0 2e7 --fy 2e5 --drifts /nonexistent/d.txt", {"/nonexistent/d.txt"}},
      {"--law imk --k0 2e7 --fy 2e5 --drifts " + bad, {"empty.txt", "no drifts"}},
      {"--law imk --k0 2e7 --fy 2e5 --drifts " + dir() / "text.txt",
       {"text.txt:2", "one drift in m per line"}},
      {"--law imk --k0 2e7 --fy 2e5 --drifts " + dir().path(), {"is a directory"}},
  };
  for (const auto& [args, fragments] : cases) {
    const Outcome r = pound_hysteresis(args);
    EXPECT_EQ(r.code, 2) << args << ": " << r.err;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << ": " << r.err;
    for (const auto& f : fragments)
      EXPECT_NE(r.err.find(f), std::string::npos) << f << " in " << r.err;
  }
}

TEST(HysteresisCommand, HelpListsTheLawKeysWithUnits) {
  const Outcome r = pound_hysteresis("--help");
  ASSERT_EQ(r.code, 0);
  for (const char* k : {"--law", "--k0", "--fy", "--height", "--drifts", "--json", "--hardening",
                        "--bw_n", "--cap_strength_ratio", "--plastic_drift_ratio",
                        "--post_cap_drift_ratio", "--ultimate_drift_ratio",
                        "--residual_strength_ratio", "--energy_capacity", "--energy_exponent"})
    EXPECT_NE(r.out.find(k), std::string::npos) << k;
}

}  // namespace

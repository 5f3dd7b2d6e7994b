// pound fragility end to end on a small campaign made here: the JSON fields of every curve,
// the files written, bad input, and the campaign file byte for byte unchanged.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "../support/scratch_dir.hpp"

namespace {

namespace fs = std::filesystem;

const std::string& dir() {
  return pound::test::process_scratch_dir().path();
}

int sh(const std::string& cmd) {
  // Open MPI's dynamically loaded components leak at exit, which LeakSanitizer would report in
  // the sanitizer build; address and undefined-behaviour errors stay fatal.
  ::setenv("ASAN_OPTIONS", "detect_leaks=0", 0);
  const int s = std::system(cmd.c_str());
  return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// A 40-sample campaign of the smoke study (four PGA stripes), made once.
const std::string& campaign() {
  static const std::string out = [] {
    const std::string o = dir() + "/run.h5";
    const std::string cmd = std::string(POUND_BINARY) + " campaign --config " + POUND_SOURCE_DIR +
                            "/studies/campaign-smoke.ini --samples 40 --quiet --out " + o + " 2>" +
                            dir() + "/campaign.log";
    EXPECT_EQ(sh(cmd), 0) << slurp(dir() + "/campaign.log");
    return o;
  }();
  return out;
}

int count(const std::string& s, const std::string& what) {
  int n = 0;
  for (auto p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(CmdFragility, JsonCurvesFilesAndUntouchedCampaign) {
  const std::string before = slurp(campaign());
  ASSERT_FALSE(before.empty());
  const std::string out = dir() + "/frag";
  const std::string json = dir() + "/out.json";
  ASSERT_EQ(
      sh(std::string(POUND_BINARY) + " fragility --input " + campaign() + " --out " + out +
         " --json --replicates 100 --force-limits 3000 > " + json + " 2>" + dir() + "/frag.log"),
      0)
      << slurp(dir() + "/frag.log");
  EXPECT_EQ(slurp(campaign()), before);  // the campaign file is byte for byte the same
  const std::string j = slurp(json);
  // 2 buildings x 4 drift limits x 2 (with and without pounding) + 2 force curves.
  EXPECT_EQ(count(j, "\"edp\":\"drift\""), 16 + 8);  // 16 curves + 8 shift entries
  EXPECT_EQ(count(j, "\"edp\":\"force\""), 2);
  EXPECT_EQ(count(j, "\"pounding\":true"), 10);
  EXPECT_EQ(count(j, "\"pounding\":false"), 8);
  for (const char* key : {"\"building\":0", "\"building\":1", "\"limit\":0.005", "\"limit\":0.025",
                          "\"theta\":", "\"beta\":", "\"theta_ci90\":", "\"beta_ci90\":",
                          "\"shift\":[", "\"curves\":[", "\"sensitivity\":[", "\"samples\":40"})
    EXPECT_NE(j.find(key), std::string::npos) << key;
  EXPECT_LT(j.find("\"shift\""), j.find("\"curves\""));  // the headline comes first
  // Every curve without a finite estimate (status other than "ok") carries null for theta,
  // never a number, and every "ok" curve a number.
  for (auto p = j.find("\"status\":\""); p != std::string::npos;
       p = j.find("\"status\":\"", p + 1)) {
    const bool ok = j.compare(p + 10, 3, "ok\"") == 0;
    const auto t = j.find("\"theta\":", p);
    EXPECT_EQ(j.compare(t + 8, 4, "null") == 0, !ok) << j.substr(p, 80);
    // The bracket is for curves without an estimate; "none_exceed" has no upper bound and
    // "all_exceed" has one.
    const auto lo = j.find("\"theta_bound_lo\":", p), hi = j.find("\"theta_bound_hi\":", p);
    ASSERT_NE(hi, std::string::npos);
    const bool lo_null = j.compare(lo + 17, 4, "null") == 0,
               hi_null = j.compare(hi + 17, 4, "null") == 0;
    EXPECT_EQ(lo_null, ok) << j.substr(p, 400);
    if (ok || j.compare(p + 10, 12, "none_exceed\"") == 0) {
      EXPECT_TRUE(hi_null);
    }
    if (j.compare(p + 10, 11, "all_exceed\"") == 0) {
      EXPECT_FALSE(hi_null);
    }
  }
  for (const char* f :
       {"curves.csv", "shift.csv", "observations.csv", "sensitivity.csv", "fragility.h5"})
    EXPECT_TRUE(fs::exists(out + "/" + f)) << f;
  for (const auto& e : fs::directory_iterator(out))
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << e.path();
  EXPECT_EQ(count(slurp(out + "/curves.csv"), "\n"), 1 + 18);
}

TEST(CmdFragility, BadInputIsOneLineAndExitTwo) {
  const std::string log = dir() + "/bad.log";
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " fragility --input " + dir() + "/missing.h5 2>" + log),
            2);
  EXPECT_NE(slurp(log).find("missing.h5"), std::string::npos);
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " fragility --input " + campaign() +
               " --drift-limits 0.01,-1 --out " + dir() + "/x 2>" + log),
            2);
  EXPECT_NE(slurp(log).find("drift-limits"), std::string::npos);
  EXPECT_EQ(count(slurp(log), "\n"), 1);
}

}  // namespace

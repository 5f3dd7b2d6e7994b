// pound fragility end to end on a small campaign made here: the JSON fields of every curve,
// the files written, bad input, and the campaign file byte for byte unchanged.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "../support/campaign_process.hpp"
#include "../support/scratch_dir.hpp"
#include "../support/shell.hpp"

namespace {

namespace fs = std::filesystem;

// The files of this test file, apart from the other command tests of tests/app.
const std::string& dir() {
  static const std::string d = pound::test::process_scratch_subdir("fragility");
  return d;
}

using pound::test::slurp;
int sh(const std::string& cmd) {
  return pound::test::run_command(cmd);
}

// A 40-sample campaign of the smoke study (four PGA stripes), made once.
const std::string& campaign() {
  static const std::string out = pound::test::make_smoke_campaign(dir() + "/run.h5", 40);
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
  // 2 buildings x (collapse + 4 drift limits) x 2 (with and without pounding) + 2 force curves.
  EXPECT_EQ(count(j, "\"edp\":\"drift\""), 16 + 8);    // 16 curves + 8 shift entries
  EXPECT_EQ(count(j, "\"edp\":\"collapse\""), 4 + 2);  // 4 curves + 2 shift entries
  EXPECT_EQ(count(j, "\"edp\":\"force\""), 2);
  EXPECT_EQ(count(j, "\"pounding\":true"), 12);
  EXPECT_EQ(count(j, "\"pounding\":false"), 10);
  // The smoke study samples no contact model: pooled curves only, and collapse first.
  EXPECT_EQ(count(j, "\"model\":\"all\""), 22 + 10);
  EXPECT_NE(j.find("\"models\":[]"), std::string::npos);
  EXPECT_LT(j.find("\"edp\":\"collapse\""), j.find("\"edp\":\"drift\""));
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
  EXPECT_EQ(count(slurp(out + "/curves.csv"), "\n"), 1 + 22);
  // Every row of every CSV has as many fields as its header names.
  for (const char* f : {"curves.csv", "shift.csv", "observations.csv"}) {
    std::istringstream in(slurp(out + "/" + f));
    std::string line;
    std::getline(in, line);
    const long fields = count(line, ",");
    EXPECT_NE(line.find(",model"), std::string::npos) << f;
    while (std::getline(in, line)) EXPECT_EQ(count(line, ","), fields) << f << ": " << line;
  }
}

// The smoke campaign with yield shears on building 1 (the elastic law: they give it a
// ductility, building 2 has none) and residual drift and ductility limits in the study's
// [fragility] section.
const std::string& inelastic_campaign() {
  static const std::string out = pound::test::make_smoke_campaign(
      dir() + "/duct.h5", 40,
      "--building1.yield_shears 150 --fragility.ductility_limits 1.5"
      " --fragility.residual_drift_limits 0.002");
  return out;
}

// Number of /fragility/curveNNN groups of fragility.h5 whose edp attribute is `edp`, and the
// sum of their left_out attributes.
std::pair<int, double> h5_curves(const std::string& file, const std::string& edp) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  int n = 0;
  double left_out = 0;
  for (int k = 0; k < 1000; ++k) {
    char g[48];
    std::snprintf(g, sizeof g, "/fragility/curve%03d", k);
    if (H5Lexists(f, g, H5P_DEFAULT) <= 0) break;
    const hid_t a = H5Aopen_by_name(f, g, "edp", H5P_DEFAULT, H5P_DEFAULT);
    const hid_t t = H5Aget_type(a);
    std::string value;
    if (H5Tis_variable_str(t) > 0) {
      char* c = nullptr;
      H5Aread(a, t, &c);
      value = c;
      H5free_memory(c);
    } else {
      std::vector<char> buf(H5Tget_size(t) + 1, '\0');
      H5Aread(a, t, buf.data());
      value = buf.data();
    }
    H5Tclose(t);
    H5Aclose(a);
    if (value != edp) continue;
    ++n;
    double x = 0;
    const hid_t l = H5Aopen_by_name(f, g, "left_out", H5P_DEFAULT, H5P_DEFAULT);
    H5Aread(l, H5T_NATIVE_DOUBLE, &x);
    H5Aclose(l);
    left_out += x;
  }
  H5Fclose(f);
  return {n, left_out};
}

TEST(CmdFragility, ResidualDriftAndDuctilityCurves) {
  // The limits of the study's [fragility] section, drift at its default.
  const std::string out = dir() + "/duct-frag", json = dir() + "/duct.json";
  ASSERT_EQ(
      sh(std::string(POUND_BINARY) + " fragility --input " + inelastic_campaign() + " --out " +
         out + " --json --replicates 50 > " + json + " 2>" + dir() + "/duct-frag.log"),
      0)
      << slurp(dir() + "/duct-frag.log");
  std::string j = slurp(json);
  // 2 buildings x 1 limit x (pounding, free) curves + 2 shift entries each.
  EXPECT_EQ(count(j, "\"edp\":\"residual_drift\",\"limit\":0.002"), 4 + 2);
  EXPECT_EQ(count(j, "\"edp\":\"ductility\",\"limit\":1.5"), 4 + 2);
  EXPECT_EQ(count(j, "\"edp\":\"drift\""), 16 + 8);
  // Building 2 has no yield shears: its two ductility curves leave out all 40 analyses.
  EXPECT_EQ(count(j, "\"left_out\":40"), 2);
  EXPECT_EQ(count(j, "\"left_out\":0"), 4 + 16 + 4 + 2);  // collapse, drift, residual, ductility
  EXPECT_EQ(count(j, "\"status\":\"no_data\""), 2);
  EXPECT_EQ(count(slurp(out + "/curves.csv"), "\n"), 1 + 4 + 16 + 4 + 4);
  EXPECT_NE(slurp(out + "/curves.csv").find(",ductility,-,1.5,true,no_data,"), std::string::npos);
  EXPECT_EQ(h5_curves(out + "/fragility.h5", "ductility"), (std::pair<int, double>{4, 80.0}));
  EXPECT_EQ(h5_curves(out + "/fragility.h5", "residual_drift"), (std::pair<int, double>{4, 0.0}));

  // The command line wins over the study.
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " fragility --input " + inelastic_campaign() +
               " --out " + out +
               " --json --replicates 50 --ductility-limits 1,2,4"
               " --residual-drift-limits 0.001,0.003 --drift-limits 0.01 > " +
               json + " 2>/dev/null"),
            0);
  j = slurp(json);
  EXPECT_EQ(count(j, "\"edp\":\"ductility\""), 12 + 6);
  EXPECT_EQ(count(j, "\"edp\":\"residual_drift\""), 8 + 4);
  EXPECT_EQ(count(j, "\"limit\":1.5"), 0);
  EXPECT_EQ(count(j, "\"left_out\":40"), 6);
  // The text tables show the new EDPs and say what was left out.
  const std::string text = dir() + "/duct.txt";
  ASSERT_EQ(sh(std::string(POUND_BINARY) + " fragility --input " + inelastic_campaign() +
               " --out " + out + " --replicates 50 > " + text + " 2>/dev/null"),
            0);
  const std::string t = slurp(text);
  EXPECT_NE(t.find("residual_drift 0.2 %"), std::string::npos) << t;
  EXPECT_EQ(count(t, "40 analyses left out"), 2) << t;
}

TEST(CmdFragility, AFileWithoutDuctilitySaysSoWhenItsCurvesAreAsked) {
  // A campaign file written before the ductility arrays existed: copied, the datasets removed.
  const std::string old = dir() + "/old.h5";
  fs::copy_file(campaign(), old, fs::copy_options::overwrite_existing);
  {
    const hid_t f = H5Fopen(old.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    for (const char* d : {"residual_drift_pounding", "residual_drift_free", "ductility_pounding",
                          "ductility_free", "hysteretic_energy_pounding", "hysteretic_energy_free"})
      EXPECT_GE(H5Ldelete(f, (std::string("/response/") + d).c_str(), H5P_DEFAULT), 0) << d;
    H5Fclose(f);
  }
  const std::string log = dir() + "/old.log";
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " fragility --input " + old + " --out " + dir() +
               "/old-frag --replicates 20 > /dev/null 2>" + log),
            0)
      << slurp(log);
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " fragility --input " + old + " --out " + dir() +
               "/old-frag2 --replicates 20 --ductility-limits 2 2>" + log),
            2);
  const std::string m = slurp(log);
  EXPECT_NE(m.find(old + ": no dataset /response/ductility_pounding"), std::string::npos) << m;
  EXPECT_EQ(count(m, "\n"), 1) << m;
  EXPECT_FALSE(fs::exists(dir() + "/old-frag2"));
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
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " fragility --input " + campaign() +
               " --ductility-limits abc --out " + dir() + "/y 2>" + log),
            2);
  EXPECT_NE(slurp(log).find("--ductility-limits: 'abc' is not a finite number"), std::string::npos)
      << slurp(log);
  EXPECT_EQ(count(slurp(log), "\n"), 1);
  EXPECT_FALSE(fs::exists(dir() + "/y"));
  EXPECT_EQ(sh(std::string(POUND_BINARY) + " fragility --input " + campaign() +
               " --residual-drift-limits 0 --out " + dir() + "/y 2>" + log),
            2);
  EXPECT_NE(slurp(log).find("residual-drift-limits"), std::string::npos) << slurp(log);
  EXPECT_FALSE(fs::exists(dir() + "/y"));
}

}  // namespace

// The `pound motion` command: JSON output, generated files, and bad input giving exit code 2
// with one line on stderr.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "../support/scratch_dir.hpp"
#include "motion/motion_reader.hpp"
#include "motion/spectrum_ec8.hpp"

namespace pound {
namespace {

namespace fs = std::filesystem;

struct CmdResult {
  int code = -1;
  std::string out, err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// One fresh directory per test process: ctest runs the tests of this file in parallel
// processes, which must not share stdout.txt and stderr.txt (a folder of its own beside the
// other command tests of tests/app).
fs::path temp_dir() {
  static const std::string d = test::process_scratch_subdir("motion");
  return d;
}

CmdResult run(const std::string& args) {
  const fs::path d = temp_dir();
  const std::string out = (d / "stdout.txt").string(), err = (d / "stderr.txt").string();
  const std::string cmd =
      std::string("'") + POUND_BINARY + "' motion " + args + " >'" + out + "' 2>'" + err + "'";
  const int status = std::system(cmd.c_str());
  CmdResult r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

std::string write(const std::string& name, const std::string& text) {
  const std::string p = (temp_dir() / name).string();
  std::ofstream(p) << text;
  return p;
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

const std::string kElCentro = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";

TEST(MotionCommand, SpectrumJson) {
  const CmdResult r =
      run("spectrum --input '" + kElCentro + "' --periods 0.5,1,2 --substep 0 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* k : {"\"period_s\":[", "\"sd_m\":[", "\"psv_mps\":[", "\"psa_g\":[",
                        "\"sa_abs_g\":[", "\"pga_g\":"})
    EXPECT_NE(r.out.find(k), std::string::npos) << k << " missing in " << r.out;
  EXPECT_EQ(lines(r.out), 1);
  // PSA 0.916 g at 0.5 s (motions/README.md), printed with 17 digits.
  EXPECT_NE(r.out.find("\"psa_g\":[0.916"), std::string::npos) << r.out;
}

TEST(MotionCommand, TargetJson) {
  const CmdResult r = run("target --spectrum ec8 --ground-type C --ag 0.35 --periods 0.4 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"psa_g\":[1.00624"), std::string::npos) << r.out;
  for (const char* k : {"\"period_s\":[", "\"sd_m\":[", "\"psv_mps\":[", "\"sa_abs_g\":["})
    EXPECT_NE(r.out.find(k), std::string::npos) << k;
}

TEST(MotionCommand, GenerateWritesReadableFiles) {
  const fs::path dir = temp_dir() / "gen";
  fs::remove_all(dir);
  const CmdResult r =
      run("generate --spectrum nzs1170 --site-class C --Z 0.4 --R 1 --count 2 "
          "--duration 8 --dt 0.01 --seed 3 --json --out '" +
          dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* k :
       {"\"motions\":[", "\"mean\":{", "\"min_ratio\":", "\"max_ratio\":", "\"pga_g\":",
        "\"final_velocity_mps\":", "\"final_displacement_m\":", "\"iterations\":"})
    EXPECT_NE(r.out.find(k), std::string::npos) << k;
  EXPECT_TRUE(fs::exists(dir / "motions.h5"));
  EXPECT_TRUE(fs::exists(dir / "motion-001.txt"));
  EXPECT_FALSE(fs::exists(dir / "motion-002.txt"));
  // The text file states its units and dt, so the reader needs nothing else.
  MotionFileSpec spec;
  spec.path = (dir / "motion-000.txt").string();
  const GroundMotion m = read_motion(spec);
  EXPECT_EQ(m.accel.size(), 801u);
  EXPECT_NEAR(m.dt, 0.01, 1e-12);
  EXPECT_GT(m.pga(), 0.2 * kGravity);
}

TEST(MotionCommand, GenerateWithVariabilityWritesEachMotionsTarget) {
  const fs::path dir = temp_dir() / "gen-var";
  fs::remove_all(dir);
  const CmdResult r = run(
      "generate --spectrum ec8 --ground-type C --ag 0.3 --count 2 --duration 8 --seed 3 "
      "--variability spectral --sigma-lnsa 0.6 --correlation baker-jayaram-2008 --json --out '" +
      dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("\"variability\":\"spectral: sigma constant sigma_lnsa = 0.6; correlation "
                       "baker-jayaram-2008\""),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"geometric_mean\":{"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "motions.h5"));
  EXPECT_TRUE(fs::exists(dir / "target-001.txt"));
  EXPECT_FALSE(fs::exists(dir / "target-002.txt"));
  // target-000.txt: period [s], Sa [g] at the 100 report periods 0.05-4 s, around the design
  // spectrum by sigma 0.6: ln(Sa / Sa_EC8) varies between periods.
  std::ifstream in(dir / "target-000.txt");
  std::vector<double> t, sa;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    double a = 0, b = 0;
    ASSERT_TRUE(ls >> a >> b) << line;
    t.push_back(a);
    sa.push_back(b);
  }
  ASSERT_EQ(t.size(), 100u);
  EXPECT_NEAR(t.front(), 0.05, 1e-6);
  EXPECT_NEAR(t.back(), 4.0, 1e-6);
  const Ec8Spectrum design(Ec8Type::type1, Ec8Ground::C, 0.3 * kGravity);
  double lo = 1e9, hi = -1e9;
  for (std::size_t j = 0; j < t.size(); ++j) {
    const double e = std::log(sa[j] * kGravity / design.sa(t[j]));
    lo = std::min(lo, e);
    hi = std::max(hi, e);
  }
  EXPECT_GT(hi - lo, 0.1);
}

void expect_input_error(const std::string& args, const std::string& needle) {
  const CmdResult r = run(args);
  EXPECT_EQ(r.code, 2) << args;
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(MotionCommand, BadInputGivesExitCode2AndOneLine) {
  const std::string text = write("text.txt", "0 0.1\n0.01 0.2\n0.02 abc\n");
  expect_input_error("spectrum --units g --input '" + text + "'", "text.txt:3: 'abc'");
  const std::string nan = write("nan.txt", "0 0.1\n0.01 NaN\n0.02 0.3\n");
  expect_input_error("spectrum --units g --input '" + nan + "'", "nan.txt:2: 'NaN' is not finite");
  const std::string step = write("step.txt", "0 0.1\n0.01 0.2\n0.02 0.1\n0.035 0\n0.04 0.1\n");
  expect_input_error("spectrum --units g --input '" + step + "'", "step.txt:4: time 0.035");
  const std::string nounit = write("nounit.txt", "0 0.1\n0.01 0.2\n0.02 0.1\n");
  expect_input_error("spectrum --input '" + nounit + "'", "give units g, m/s2 or cm/s2");
  expect_input_error("spectrum --units ft --input '" + nounit + "'", "valid: g, m/s2, cm/s2");
  expect_input_error("target --spectrum ec9", "valid: ec8, nzs1170, asce7, japan, table");
  expect_input_error("target --spectrum nzs1170 --site-class C --Z 0.4 --R 1 --damping 0.1",
                     "valid: 0.05");
}

TEST(MotionCommand, BadVariabilityInputIsOneLineExitTwoAndNoFile) {
  const fs::path dir = temp_dir() / "bad-var";
  fs::remove_all(dir);
  const std::string gen =
      "generate --spectrum ec8 --ground-type C --ag 0.3 --count 1 "
      "--duration 4 --variability spectral --out '" +
      dir.string() + "' ";
  expect_input_error(gen + "--sigma-lnsa -0.1", "--sigma-lnsa");
  expect_input_error(gen + "--sigma-table '" + (temp_dir() / "none.txt").string() + "'",
                     "cannot open the sigma table");
  const std::string bad = write("bad-sigma.txt", "0.1 0.6\n0.5 x\n");
  expect_input_error(gen + "--sigma-table '" + bad + "'", "bad-sigma.txt:2");
  expect_input_error(gen + "--correlation bj2008", "valid: baker-jayaram-2008, none, full");
  expect_input_error(gen + "--sigma-model ask14", "valid: boore-atkinson-2008");
  EXPECT_FALSE(fs::exists(dir));
}

// Issue 28: stations along a row. Files motion-NNN-sK.txt, the station delays as leading
// samples, a station dimension in motions.h5 and the lag and coherency in the report.
TEST(MotionCommand, GenerateWithStationsWritesEveryStation) {
  const fs::path dir = temp_dir() / "gen-stations";
  fs::remove_all(dir);
  const CmdResult r = run(
      "generate --spectrum ec8 --ground-type C --ag 0.3 --count 2 --duration 6 --seed 3 "
      "--stations 3 --spacing 25 --apparent-velocity 250 --coherency harichandran-vanmarcke-1986 "
      "--json --out '" +
      dir.string() + "'");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* k : {"\"coherency_model\":\"harichandran-vanmarcke-1986: A = 0.736",
                        "\"apparent_velocity_mps\":250", "\"delay_s\":0.2", "\"lag_s\":",
                        "\"frequencies_hz\":[1,2,4,6]", "\"stations\":[1,2]", "\"achieved\":["})
    EXPECT_NE(r.out.find(k), std::string::npos) << k << "\n" << r.out;
  EXPECT_TRUE(fs::exists(dir / "motions.h5"));
  EXPECT_TRUE(fs::exists(dir / "target-001.txt"));
  EXPECT_FALSE(fs::exists(dir / "motion-000.txt"));
  // Station K of motion 1: 601 samples delayed by 25 (K - 1) / 250 s = 10 (K - 1) samples.
  for (int k = 1; k <= 3; ++k) {
    MotionFileSpec spec;
    spec.path = (dir / ("motion-001-s" + std::to_string(k) + ".txt")).string();
    const GroundMotion m = read_motion(spec);
    ASSERT_EQ(m.accel.size(), 601u + 10u * unsigned(k - 1)) << k;
    for (int i = 0; i < 10 * (k - 1); ++i) ASSERT_EQ(m.accel[std::size_t(i)], 0.0);
    EXPECT_NE(m.accel[std::size_t(10 * (k - 1))], 0.0);
  }
  EXPECT_FALSE(fs::exists(dir / "motion-002-s1.txt"));
  // The table: a row per motion and station, a mean per station and the pairs' coherency.
  const CmdResult t =
      run("generate --spectrum ec8 --ground-type C --ag 0.3 --count 1 --duration 6 --seed 3 "
          "--positions 0,30 --coherency luco-wong-1986 --out '" +
          (temp_dir() / "gen-stations-table").string() + "'");
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_NE(t.out.find("# lag and lagged coherency of the set"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("1-2        30.0"), std::string::npos) << t.out;
}

// Issue 37: stations closer than a model's fitted range (SMART-1: 100 m) get one note line on
// stderr with the model's coherency at zero frequency there and the share of the displacement
// it leaves independent (HV86 at 12 m: 0.9910134, sqrt(2 x 0.0089866) = 13.4 %, worked by hand
// in tests/ground/coherency_test.cpp), and the command goes on. The Abrahamson models, fitted
// on dense arrays, tend to 1 there: no note.
TEST(MotionCommand, StationsBelowTheFittedRangeGetOneNote) {
  const std::string gen =
      "generate --spectrum ec8 --ground-type C --ag 0.3 --count 1 --duration 4 --seed 3 "
      "--positions 0,12,40 --out '";
  const CmdResult r = run(gen + (temp_dir() / "gen-note-hv").string() +
                          "' --coherency harichandran-vanmarcke-1986");
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string note =
      "pound motion generate: note: coherency harichandran-vanmarcke-1986 was fitted at "
      "separations of 100 m and more; at 12 m its coherency at zero frequency is 0.991, which "
      "leaves sqrt(2 (1 - 0.991)) = 13.4 % of the ground displacement independent at the two "
      "stations (abrahamson-2007-soil and -rock tend to 1 there)\n";
  EXPECT_NE(r.err.find(note), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("note:"), r.err.rfind("note:")) << r.err;  // one line
  for (const char* model : {"abrahamson-2007-soil", "luco-wong-1986"}) {
    const CmdResult a =
        run(gen + (temp_dir() / "gen-note-none").string() + "' --coherency " + model);
    ASSERT_EQ(a.code, 0) << a.err;
    EXPECT_EQ(a.err.find("note:"), std::string::npos) << model << ": " << a.err;
  }
}

TEST(MotionCommand, BadStationInputIsOneLineExitTwoAndNoFile) {
  const fs::path dir = temp_dir() / "bad-stations";
  fs::remove_all(dir);
  const std::string gen =
      "generate --spectrum ec8 --ground-type C --ag 0.3 --count 1 "
      "--duration 4 --out '" +
      dir.string() + "' ";
  const std::string st = gen + "--stations 3 --spacing 20 ";
  expect_input_error(st + "--apparent-velocity 0", "--apparent-velocity = '0': valid: a non-zero");
  expect_input_error(st + "--apparent-velocity nan", "--apparent-velocity");
  expect_input_error(st + "--coherency harichandran-vanmarcke-1986 --coherency-parameters "
                          "1.5,0.147,5210,1.09,2.78",
                     "--coherency-parameters: coherency harichandran-vanmarcke-1986 parameter "
                     "A = 1.5 is out of range; valid: 0 < A <= 1");
  expect_input_error(st + "--coherency harichandran-vanmarcke-1986 --coherency-parameters "
                          "0.7,0,5210,1.09,2.78",
                     "parameter alpha = 0 is out of range; valid: alpha > 0");
  expect_input_error(st + "--coherency harichandran-vanmarcke-1986 --coherency-parameters "
                          "0.7,0.1,5210,-1,2.78",
                     "parameter f0");
  expect_input_error(st + "--coherency hv86", "--coherency: unknown coherency model 'hv86'");
  expect_input_error(st + "--coherency-parameters 1", "give --coherency MODEL too");
  expect_input_error(st + "--coherency hv86",
                     "valid: none, harichandran-vanmarcke-1986, luco-wong-1986, "
                     "hao-oliveira-penzien-1989, abrahamson-2007-soil, abrahamson-2007-rock");
  expect_input_error(st + "--coherency abrahamson-2007-soil --coherency-parameters 1,2",
                     "--coherency-parameters: coherency abrahamson-2007-soil takes no parameters, "
                     "not 2; valid: no parameters, or a model that takes them: "
                     "harichandran-vanmarcke-1986, luco-wong-1986, hao-oliveira-penzien-1989");
  expect_input_error(st + "--coherency abrahamson-2007-rock --coherency-parameters 0.4",
                     "abrahamson-2007-rock takes no parameters, not 1");
  expect_input_error(gen + "--positions 0,20,10", "valid: strictly increasing");
  expect_input_error(gen + "--stations 3", "--stations = '3': give --stations N and --spacing D");
  expect_input_error(gen + "--spacing 10", "--spacing = '10': give --stations N and --spacing D");
  expect_input_error(gen + "--stations 0 --spacing 10", "valid: 1 to 50");
  expect_input_error(gen + "--stations 2 --spacing -5", "valid: a spacing > 0 m");
  expect_input_error(gen + "--positions 0,10 --stations 2", "not both");
  expect_input_error(gen + "--coherency luco-wong-1986", "give the stations too");
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
}  // namespace pound

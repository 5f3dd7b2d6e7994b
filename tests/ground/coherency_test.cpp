// Coherency models against their formulas at points worked by hand, their limits, and the
// validation messages.
#include "ground/coherency.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace pound {
namespace {

TEST(GroundCoherency, HarichandranVanmarckeAtPointsWorkedByHand) {
  const Coherency c = make_coherency("harichandran-vanmarcke-1986", {}, "test");
  // d = 20 m, f = 5 Hz: (5 / 1.09)^2.78 = 69.038437, theta = 5210 / sqrt(70.038437) =
  // 622.54321 m, 2 d (1 - A + alpha A) = 14.88768 m; 14.88768 / (0.147 theta) = 0.16268226,
  // 14.88768 / theta = 0.02391429: 0.736 e^-0.16268226 + 0.264 e^-0.02391429 = 0.88325935.
  EXPECT_NEAR(c(20.0, 5.0), 0.88325935, 1e-8);
  // d = 100 m, f = 2 Hz: (2 / 1.09)^2.78 = 5.4052741, theta = 2058.5853 m, 2 d (..) = 74.4384 m:
  // 0.736 e^-0.24598625 + 0.264 e^-0.03615998 = 0.83012697.
  EXPECT_NEAR(c(100.0, 2.0), 0.83012697, 1e-8);
  EXPECT_EQ(c(0.0, 5.0), 1.0);
  EXPECT_LT(c(100.0, 6.0), c(100.0, 1.0));
  EXPECT_LT(c(100.0, 4.0), c(20.0, 4.0));
}

TEST(GroundCoherency, LucoWongAndHaoAtPointsWorkedByHand) {
  const Coherency lw = make_coherency("luco-wong-1986", {}, "test");
  // alpha omega d = 2.5e-4 x 2 pi x 4 x 50 = 0.314159; exp(-0.098696) = 0.906018.
  EXPECT_NEAR(lw(50.0, 4.0), 0.906018, 1e-6);
  EXPECT_EQ(lw(0.0, 4.0), 1.0);
  EXPECT_EQ(lw(50.0, 0.0), 1.0);
  const Coherency hao = make_coherency("hao-oliveira-penzien-1989", {}, "test");
  // d = 100 m, f = 5 Hz: alpha = 3.583e-3 / 5 - 1.811e-5 x 5 + 1.177e-4 = 7.4375e-4;
  // exp(-1.109e-2) exp(-7.4375e-4 x 10 x 25) = 0.98897127 x 0.83032549 = 0.82116805.
  EXPECT_NEAR(hao(100.0, 5.0), 0.82116805, 1e-8);
  // f = 20 Hz: alpha is held at its 10 Hz value 2.949e-4: exp(-1.109e-2 - 2.949e-4 x 10 x 400).
  EXPECT_NEAR(hao(100.0, 20.0), std::exp(-1.109e-2 - 2.949e-4 * 10.0 * 400.0), 1e-12);
  EXPECT_NEAR(hao(100.0, 20.0), 0.30401142, 1e-8);
  EXPECT_NEAR(hao(100.0, 0.0), std::exp(-1.109e-2), 1e-15);
  EXPECT_EQ(hao(0.0, 3.0), 1.0);
  EXPECT_EQ(Coherency{}(100.0, 5.0), 1.0);
}

// Abrahamson (2007) plane-wave coherency, values worked by hand with python3 from the formula
// (docs/ground.md), a fresh transcription of the report's form and of the coefficients as
// code_aster's signal_correlation_utils.py has them, not this code's output.
TEST(GroundCoherency, AbrahamsonSoilAtPointsWorkedByHand) {
  const Coherency c = make_coherency("abrahamson-2007-soil", {}, "test");
  // d = 12 m, f = 5 Hz: tanh(4.8) = 0.99986455, fc = 14.3 - 2.35 ln 13 = 8.2723690 Hz,
  // a2 = 15.8 - 0.528 = 15.272 Hz; (5 x 0.99986455 / 8.2723690)^3 = 0.22072109,
  // (4.9993228 / 15.272)^15 = 5.31e-8: 1 / sqrt(1.22072109 x 1.0000000531) = 0.90509000.
  const double d[] = {3.0, 12.0, 50.0}, f[] = {0.5, 2.0, 5.0, 10.0};
  const double want[3][4] = {{0.99997311, 0.99828315, 0.97414361, 0.83611629},
                             {0.99988966, 0.99301089, 0.90509000, 0.60077859},
                             {0.99951799, 0.97048850, 0.71342582, 0.33701611}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(c(d[i], f[k]), want[i][k], 1e-6) << d[i] << " m";
}

TEST(GroundCoherency, AbrahamsonRockAtPointsWorkedByHand) {
  const Coherency c = make_coherency("abrahamson-2007-rock", {}, "test");
  // d = 12 m, f = 5 Hz: l = ln 13 = 2.5649494, n1 = 3.8 - 0.04 l + 0.0105 (l - 3.6)^2 =
  // 3.7086510, fc = 27.9 - 4.82 l + 1.24 (l - 3.6)^2 = 16.865393 Hz; (4.9993228 / 16.865393)^n1
  // = 0.011003123, (4.9993228 / 40)^16.4 = 1.5e-15: 1 / sqrt(1.011003123) = 0.99454343.
  const double d[] = {3.0, 12.0, 50.0}, f[] = {0.5, 2.0, 5.0, 10.0};
  const double want[3][4] = {{0.99999994, 0.99998769, 0.99960124, 0.99450348},
                             {0.99999892, 0.99981612, 0.99454343, 0.93500541},
                             {0.99998712, 0.99799307, 0.94767382, 0.64302094}};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(c(d[i], f[k]), want[i][k], 1e-6) << d[i] << " m";
}

TEST(GroundCoherency, AbrahamsonTendsToOneAtZeroFrequencyAndZeroDistance) {
  for (const char* name : {"abrahamson-2007-soil", "abrahamson-2007-rock"}) {
    const Coherency c = make_coherency(name, {}, "test");
    for (double d : {0.5, 12.0, 50.0, 250.0, 400.0, 1000.0}) EXPECT_EQ(c(d, 0.0), 1.0) << name;
    for (double f : {0.0, 1.0, 10.0, 25.0}) EXPECT_EQ(c(0.0, f), 1.0) << name;
    EXPECT_GT(c(1e-3, 10.0), 0.999999) << name;  // continuous at d = 0
    // Beyond 300 m the coefficients are held (finite, in (0, 1], no longer falling with d).
    EXPECT_EQ(c(400.0, 2.0), c(1000.0, 2.0)) << name;
    EXPECT_GT(c(400.0, 2.0), 0.0) << name;
    EXPECT_LT(c(50.0, 5.0), c(12.0, 5.0)) << name;
    EXPECT_EQ(c.fitted_min_separation(), 0.0) << name;
    EXPECT_EQ(fitted_range_note(c, 12.0), "") << name;
  }
  EXPECT_EQ(make_coherency("abrahamson-2007-rock", {}, "x").describe(),
            "abrahamson-2007-rock (plane-wave coherency, EPRI 1015110)");
}

// HV86 at 12 m, f = 0: theta = k, 2 d (1 - A + alpha A) = 8.932608 m; 0.736 e^-0.011663 +
// 0.264 e^-0.0017145 = 0.9910134, sqrt(2 (1 - 0.9910134)) = 0.13406. Hao et al. at 12 m:
// e^(-1.109e-4 x 12) = 0.9986701, sqrt(2 x 0.0013299) = 0.05157.
TEST(GroundCoherency, NoteBelowTheFittedRangeGivesTheFloorAndTheIndependentShare) {
  const Coherency hv = make_coherency("harichandran-vanmarcke-1986", {}, "test");
  EXPECT_EQ(fitted_range_note(hv, 12.0),
            "coherency harichandran-vanmarcke-1986 was fitted at separations of 100 m and more; "
            "at 12 m its coherency at zero frequency is 0.991, which leaves sqrt(2 (1 - 0.991)) "
            "= 13.4 % of the ground displacement independent at the two stations "
            "(abrahamson-2007-soil and -rock tend to 1 there)");
  const std::string hao =
      fitted_range_note(make_coherency("hao-oliveira-penzien-1989", {}, "t"), 12.0);
  EXPECT_NE(hao.find("at 12 m its coherency at zero frequency is 0.999"), std::string::npos) << hao;
  EXPECT_NE(hao.find("= 5.2 % of the ground"), std::string::npos) << hao;
  EXPECT_EQ(fitted_range_note(hv, 100.0), "");
  EXPECT_EQ(fitted_range_note(hv, 150.0), "");
  EXPECT_EQ(fitted_range_note(make_coherency("luco-wong-1986", {}, "t"), 12.0), "");
  EXPECT_EQ(fitted_range_note(Coherency{}, 12.0), "");
}

void expect_refused(const std::string& name, const std::vector<double>& p,
                    const std::string& needle) {
  try {
    make_coherency(name, p, "command line: --coherency-parameters");
    ADD_FAILURE() << name << " accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(needle), std::string::npos) << m;
    EXPECT_NE(m.find("--coherency-parameters"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

TEST(GroundCoherency, BadParametersNameTheParameterAndWhatIsValid) {
  const std::string hv = "harichandran-vanmarcke-1986";
  expect_refused(hv, {1.5, 0.147, 5210, 1.09, 2.78},
                 "parameter A = 1.5 is out of range; valid: 0 < A <= 1");
  expect_refused(hv, {0.0, 0.147, 5210, 1.09, 2.78}, "valid: 0 < A <= 1");
  expect_refused(hv, {0.7, -1, 5210, 1.09, 2.78}, "parameter alpha");
  expect_refused(hv, {0.7, 0.1, 0, 1.09, 2.78}, "parameter k");
  expect_refused(hv, {0.7, 0.1, 5210, 0, 2.78}, "parameter f0");
  expect_refused(hv, {0.7, 0.1, 5210, 1, -2}, "parameter b");
  expect_refused(hv, {0.7, 0.1}, "takes 5 parameters (A, alpha, k, f0, b), not 2");
  expect_refused("luco-wong-1986", {0.0}, "valid: alpha > 0 s/m");
  expect_refused("hao-oliveira-penzien-1989", {1e-4, -1e-3, 0, 0}, "alpha >= 0 over 0.05-10 Hz");
  const std::string takers =
      "valid: no parameters, or a model that takes them: harichandran-vanmarcke-1986, "
      "luco-wong-1986, hao-oliveira-penzien-1989";
  expect_refused("none", {1.0}, "coherency none takes no parameters, not 1; " + takers);
  expect_refused("abrahamson-2007-soil", {1.0, 2.0},
                 "coherency abrahamson-2007-soil takes no parameters, not 2; " + takers);
  expect_refused("abrahamson-2007-rock", {0.4}, "abrahamson-2007-rock takes no parameters");
  expect_refused("hv86", {},
                 "valid: none, harichandran-vanmarcke-1986, luco-wong-1986, "
                 "hao-oliveira-penzien-1989, abrahamson-2007-soil, abrahamson-2007-rock");
  EXPECT_EQ(make_coherency("harichandran-vanmarcke-1986", {}, "x").describe(),
            "harichandran-vanmarcke-1986: A = 0.736, alpha = 0.147, k = 5210 m, f0 = 1.09 Hz, "
            "b = 2.78");
}

}  // namespace
}  // namespace pound

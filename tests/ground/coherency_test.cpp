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
  expect_refused("none", {1.0}, "takes 0 parameters");
  expect_refused("hv86", {},
                 "valid: none, harichandran-vanmarcke-1986, luco-wong-1986, "
                 "hao-oliveira-penzien-1989");
  EXPECT_EQ(make_coherency("harichandran-vanmarcke-1986", {}, "x").describe(),
            "harichandran-vanmarcke-1986: A = 0.736, alpha = 0.147, k = 5210 m, f0 = 1.09 Hz, "
            "b = 2.78");
}

}  // namespace
}  // namespace pound

// Design spectra at their corner periods against hand calculations from the clauses.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../support/scratch_dir.hpp"
#include "core/error.hpp"
#include "motion/ground_motion.hpp"
#include "motion/spectrum_asce7.hpp"
#include "motion/spectrum_ec8.hpp"
#include "motion/spectrum_factory.hpp"
#include "motion/spectrum_japan.hpp"
#include "motion/spectrum_nzs1170.hpp"
#include "motion/spectrum_table.hpp"

namespace pound {
namespace {

constexpr double g = kGravity;

TEST(MotionDesignSpectrum, Ec8Type1GroundC) {
  // Table 3.2, C: S = 1.15, TB = 0.2, TC = 0.6, TD = 2.0; ag = 0.35 g, eta = 1.
  const Ec8Spectrum s(Ec8Type::type1, Ec8Ground::C, 0.35 * g);
  EXPECT_NEAR(s.sa(0.0) / g, 0.35 * 1.15, 1e-12);                    // ag S
  EXPECT_NEAR(s.sa(0.1) / g, 0.35 * 1.15 * (1 + 0.5 * 1.5), 1e-12);  // eq. 3.2
  EXPECT_NEAR(s.sa(0.2) / g, 1.00625, 1e-12);                        // 2.5 ag S
  EXPECT_NEAR(s.sa(0.6) / g, 1.00625, 1e-12);
  EXPECT_NEAR(s.sa(2.0) / g, 1.00625 * 0.6 / 2.0, 1e-12);         // 0.301875
  EXPECT_NEAR(s.sa(4.0) / g, 1.00625 * 0.6 * 2.0 / 16.0, 1e-12);  // 0.07546875
}

TEST(MotionDesignSpectrum, Ec8Type2GroundDAndDamping) {
  // Table 3.3, D: S = 1.8, TB = 0.1, TC = 0.3, TD = 1.2.
  const Ec8Spectrum s(Ec8Type::type2, Ec8Ground::D, 0.2 * g);
  EXPECT_NEAR(s.sa(0.1) / g, 0.9, 1e-12);
  EXPECT_NEAR(s.sa(0.3) / g, 0.9, 1e-12);
  EXPECT_NEAR(s.sa(1.2) / g, 0.225, 1e-12);
  // eq. 3.6: eta(10 %) = sqrt(10/15); eta(30 %) = 0.535 -> bounded to 0.55.
  EXPECT_NEAR(ec8_eta(0.10), std::sqrt(10.0 / 15.0), 1e-14);
  EXPECT_DOUBLE_EQ(ec8_eta(0.30), 0.55);
  const Ec8Spectrum d(Ec8Type::type2, Ec8Ground::D, 0.2 * g, 0.10);
  EXPECT_NEAR(d.sa(0.2) / g, 0.9 * std::sqrt(10.0 / 15.0), 1e-12);
  EXPECT_NEAR(d.sa(0.0) / g, 0.2 * 1.8, 1e-12);  // eta does not act at T = 0
}

TEST(MotionDesignSpectrum, Nzs1170ClassC) {
  // Table 3.1 class C with Z = 0.4, R = 1, N = 1.
  const Nzs1170Spectrum s(NzsSiteClass::C, 0.4, 1.0);
  EXPECT_NEAR(s.sa(0.0) / g, 1.33 * 0.4, 1e-12);
  EXPECT_NEAR(s.sa(0.1) / g, 2.93 * 0.4, 1e-12);
  EXPECT_NEAR(s.sa(0.3) / g, 2.93 * 0.4, 1e-12);
  EXPECT_NEAR(s.sa(1.5) / g, 2.0 * std::pow(0.5 / 1.5, 0.75) * 0.4, 1e-12);  // 0.351
  EXPECT_NEAR(s.sa(2.0) / g, 1.32 / 2.0 * 0.4, 1e-12);                       // 0.264
  EXPECT_NEAR(s.sa(3.0) / g, 0.44 * 0.4, 1e-12);                             // 0.176
  EXPECT_NEAR(s.sa(4.0) / g, 3.96 / 16.0 * 0.4, 1e-12);
  // The branches of Table 3.1 meet at the corners to the table's rounding (0.5 %).
  for (NzsSiteClass c : {NzsSiteClass::A, NzsSiteClass::C, NzsSiteClass::D, NzsSiteClass::E})
    for (double T : {0.3, 0.56, 1.0, 1.5, 3.0})
      EXPECT_NEAR(nzs_spectral_shape(c, T - 1e-9) / nzs_spectral_shape(c, T + 1e-9), 1.0, 5e-3);
  // Table 3.1 rock at 0.4 s: 1.89; class D at 1.0 s: 2.4 (0.75)^0.75 = 1.935.
  EXPECT_NEAR(nzs_spectral_shape(NzsSiteClass::B, 0.4), 1.89, 0.005);
  EXPECT_NEAR(nzs_spectral_shape(NzsSiteClass::D, 1.0), 1.935, 0.001);
}

TEST(MotionDesignSpectrum, Nzs1170ReturnPeriodAndNearFault) {
  EXPECT_DOUBLE_EQ(nzs_return_period_factor(500), 1.0);
  EXPECT_DOUBLE_EQ(nzs_return_period_factor(2500), 1.8);
  EXPECT_DOUBLE_EQ(nzs_return_period_factor(25), 0.25);
  EXPECT_THROW(nzs_return_period_factor(300), InputError);
  EXPECT_DOUBLE_EQ(nzs_near_fault_factor(1.0, 0.0), 1.0);
  EXPECT_NEAR(nzs_near_fault_factor(3.0, 2.0), 1.36, 1e-12);
  EXPECT_NEAR(nzs_near_fault_factor(2.5, 0.0), 1.24, 1e-12);
  EXPECT_NEAR(nzs_near_fault_factor(3.0, 11.0), 1.18, 1e-12);  // 1 + 0.36 * 9/18
  EXPECT_NEAR(nzs_near_fault_factor(6.0, 1.0), 1.72, 1e-12);
  EXPECT_DOUBLE_EQ(nzs_near_fault_factor(4.0, 25.0), 1.0);
  const Nzs1170Spectrum s(NzsSiteClass::C, 0.4, 1.0, 1.0, 2.0);
  EXPECT_NEAR(s.sa(3.0) / g, 0.44 * 0.4 * 1.36, 1e-12);
  EXPECT_THROW(Nzs1170Spectrum(NzsSiteClass::C, 0.5, 1.5), InputError);  // Z R > 0.7
}

TEST(MotionDesignSpectrum, Asce7) {
  // SDS = 1.0 g, SD1 = 0.6 g, TL = 8 s: T0 = 0.12 s, TS = 0.6 s.
  const Asce7Spectrum s(1.0 * g, 0.6 * g, 8.0);
  EXPECT_NEAR(s.t0(), 0.12, 1e-14);
  EXPECT_NEAR(s.ts(), 0.6, 1e-14);
  EXPECT_NEAR(s.sa(0.0) / g, 0.4, 1e-12);
  EXPECT_NEAR(s.sa(0.06) / g, 0.7, 1e-12);
  EXPECT_NEAR(s.sa(0.12) / g, 1.0, 1e-12);
  EXPECT_NEAR(s.sa(0.6) / g, 1.0, 1e-12);
  EXPECT_NEAR(s.sa(1.0) / g, 0.6, 1e-12);
  EXPECT_NEAR(s.sa(8.0) / g, 0.075, 1e-12);
  EXPECT_NEAR(s.sa(10.0) / g, 0.048, 1e-12);
}

TEST(MotionDesignSpectrum, JapanBedrockAndSurface) {
  const JapanSpectrum rock(JapanLevel::level2, JapanSoil::bedrock);
  EXPECT_NEAR(rock.sa(0.0), 3.2, 1e-12);
  EXPECT_NEAR(rock.sa(0.16), 8.0, 1e-12);
  EXPECT_NEAR(rock.sa(0.16 - 1e-12), 8.0, 1e-9);  // 3.2 + 30 * 0.16 = 8.0: continuous
  EXPECT_NEAR(rock.sa(0.64), 8.0, 1e-12);
  EXPECT_NEAR(rock.sa(1.0), 5.12, 1e-12);
  EXPECT_NEAR(JapanSpectrum(JapanLevel::level1, JapanSoil::bedrock).sa(0.3), 1.6, 1e-12);
  // Type 2 ground: Gs = 1.5 T / 0.64 up to Tu = 0.864 s, then 2.025.
  const JapanSpectrum t2(JapanLevel::level2, JapanSoil::type2);
  EXPECT_NEAR(t2.sa(0.5), 12.0, 1e-12);
  EXPECT_NEAR(t2.sa(0.8), 5.12 / 0.8 * 1.5 * 0.8 / 0.64, 1e-12);  // = 12.0
  EXPECT_NEAR(t2.sa(1.0), 5.12 * 2.025, 1e-12);
  const JapanSpectrum t1(JapanLevel::level2, JapanSoil::type1, 0.8);
  EXPECT_NEAR(t1.sa(0.6), 8.0 * 0.864 / 0.6 * 0.8, 1e-12);
  EXPECT_NEAR(t1.sa(2.0), 5.12 / 2.0 * 1.35 * 0.8, 1e-12);
  // Fh = 1.5 / (1 + 10 h): 0.75 at h = 0.10.
  EXPECT_NEAR(JapanSpectrum(JapanLevel::level2, JapanSoil::bedrock, 1.0, 0.10).sa(0.3), 6.0, 1e-12);
}

TEST(MotionDesignSpectrum, TableLogLog) {
  const std::string p = test::process_scratch_dir() / "pound_table_spectrum.txt";
  std::ofstream(p) << "# T [s]  Sa [g]\n0.1 1.0\n1.0 0.1\n2.0 0.1\n";
  const TableSpectrum s = read_spectrum_table(p);
  EXPECT_NEAR(s.sa(0.5) / g, 0.2, 1e-12);  // Sa ~ 1/T between the first two points
  EXPECT_NEAR(s.sa(std::sqrt(0.1)) / g, std::sqrt(0.1), 1e-12);
  EXPECT_NEAR(s.sa(1.5) / g, 0.1, 1e-12);
  EXPECT_NEAR(s.sa(0.01) / g, 1.0, 1e-12);  // held below the first period
  std::ofstream(p) << "0.1 1.0\n0.05 0.5\n";
  try {
    read_spectrum_table(p);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pound_table_spectrum.txt:2:"), std::string::npos);
  }
}

TEST(MotionDesignSpectrum, FactoryFromOptions) {
  Options o("motion target", "", design_spectrum_option_specs());
  const char* argv[] = {"target", "--spectrum", "ec8", "--ground-type", "C", "--ag", "0.35"};
  o.parse(7, argv);
  EXPECT_NEAR(make_design_spectrum(o)->sa(0.4) / g, 1.00625, 1e-12);
  Options bad("motion target", "", design_spectrum_option_specs());
  const char* argv2[] = {"target", "--spectrum", "nzs1170", "--site-class", "F", "--Z",
                         "0.4",    "--R",        "1"};
  bad.parse(9, argv2);
  try {
    make_design_spectrum(bad);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--site-class"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("A, B, C, D or E"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pound

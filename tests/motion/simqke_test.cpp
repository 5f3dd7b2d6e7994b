// Spectrum-compatible generation: the random numbers, determinism, and the acceptance
// criteria of issue 4 for Eurocode 8 and NZS 1170.5 (seven 20 s motions each).
#include "motion/simqke.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "motion/motion_processing.hpp"
#include "motion/response_spectrum.hpp"
#include "motion/spectrum_ec8.hpp"
#include "motion/spectrum_nzs1170.hpp"

namespace pound {
namespace {

TEST(MotionSimqke, PhiloxKnownAnswer) {
  // Random123 known-answer vector: Philox4x32-10, counter 0 and key 0 give
  // 6627e8d5 e169c58d bc57ac4c 9b00dbd8; u uses the first two words (27 + 26 bits).
  const double u =
      (double(0x6627e8d5u >> 5) * 67108864.0 + double(0xe169c58du >> 6)) / 9007199254740992.0;
  EXPECT_EQ(philox_uniform(0, 0, 0), u);
  EXPECT_NE(philox_uniform(0, 1, 0), u);
  EXPECT_NE(philox_uniform(1, 0, 0), u);
  EXPECT_NE(philox_uniform(0, 0, 0, 1), u);
  // Uniform on [0, 1): the mean of 20000 draws is 0.5 within 4 standard errors.
  double sum = 0.0;
  for (std::uint32_t i = 0; i < 20000; ++i) sum += philox_uniform(42, 3, i);
  EXPECT_NEAR(sum / 20000.0, 0.5, 4.0 * std::sqrt(1.0 / 12.0 / 20000.0));
}

// bin_power: at every FFT bin the ratio interpolated in ln T between the matching periods
// around the bin (the end ratio beyond them) to the given power. Checked against itself at power
// 1 (pow(x, 1) is x: the interpolated ratio), each bin's value then lying between the ratios of
// two neighbouring matching periods, and the ratios (growing with the period) falling with the
// bin's frequency; and the held powers of the bins outside the matching periods (issue 38) the
// same bits as pow of the end ratios.
TEST(MotionSimqke, BinPowerIsTheInterpolatedRatioToThePower) {
  const Ec8Spectrum target(Ec8Type::type1, Ec8Ground::C, 0.35 * kGravity);
  SimqkeGenerator gen(target, 10.0, SimqkeSettings{});
  const std::size_t np = gen.match_periods().size();
  std::vector<double> ratio(np);
  for (std::size_t j = 0; j < np; ++j) ratio[j] = std::exp(0.05 * double(j) + 0.01 * std::sin(j));
  std::vector<double> one, p;
  gen.bin_power(ratio, 1.0, one);
  gen.bin_power(ratio, 1.6, p);
  ASSERT_EQ(one.size(), gen.fft_bins());
  EXPECT_EQ(one[0], 1.0);
  EXPECT_EQ(p[0], 1.0);
  const double f_hi = 1.0 / gen.match_periods().front(), f_lo = 1.0 / gen.match_periods().back();
  int outside = 0;
  for (std::size_t k = 1; k < one.size(); ++k) {
    EXPECT_EQ(p[k], std::pow(one[k], 1.6)) << "bin " << k;
    EXPECT_GE(one[k], ratio.front() * (1 - 1e-15));
    EXPECT_LE(one[k], ratio.back() * (1 + 1e-15));
    if (k > 1) {
      EXPECT_LE(one[k], one[k - 1]) << "bin " << k;
    }
    const double f = gen.bin_frequency(k);
    if (f >= f_hi) {
      EXPECT_EQ(p[k], std::pow(ratio.front(), 1.6)) << "bin " << k;
      ++outside;
    }
    if (f <= f_lo) {
      EXPECT_EQ(p[k], std::pow(ratio.back(), 1.6)) << "bin " << k;
    }
  }
  EXPECT_GT(outside, 100);
}

// A station's ratios after the dead band (ground/station_generator.hpp) are mostly exp(0) = 1,
// in runs: a bin between two equal ratios takes their power, computed once (issue 38), which is
// pow of the interpolated ratio, bit for bit (ratio_j + w 0 is ratio_j); where they differ pow
// of the interpolated ratio itself.
TEST(MotionSimqke, BinPowerBetweenEqualRatiosIsTheirPower) {
  const Ec8Spectrum target(Ec8Type::type1, Ec8Ground::C, 0.35 * kGravity);
  SimqkeGenerator gen(target, 10.0, SimqkeSettings{});
  const std::size_t np = gen.match_periods().size();
  std::vector<double> ratio(np, 1.0);
  for (std::size_t j = 0; j < np; ++j)
    if (j % 7 == 3 || j % 11 == 5) ratio[j] = std::exp(0.03 * std::sin(double(j)));
  ratio[20] = ratio[21] = ratio[22] = 1.37;  // a run of equal ratios other than 1
  std::vector<double> one, p;
  gen.bin_power(ratio, 1.0, one);  // the interpolated ratio (pow(x, 1) is x)
  gen.bin_power(ratio, 1.6, p);
  ASSERT_EQ(p.size(), gen.fft_bins());
  // The ratio interpolated linearly in ln T, written out here (to round-off: the bins'
  // frequencies are formed otherwise in the generator), end values held.
  const std::vector<double>& T = gen.match_periods();
  const double lt0 = std::log(T.front()), dlt = std::log(T.back() / T.front()) / double(np - 1);
  int unit = 0, run = 0, between = 0;
  for (std::size_t k = 1; k < p.size(); ++k) {
    const double x = (std::log(1.0 / gen.bin_frequency(k)) - lt0) / dlt;
    const double xc = std::min(std::max(x, 0.0), double(np - 1));
    const auto j = std::min(std::size_t(xc), np - 2);
    EXPECT_NEAR(one[k], ratio[j] + (xc - double(j)) * (ratio[j + 1] - ratio[j]), 1e-12)
        << "bin " << k;
    EXPECT_EQ(p[k], std::pow(one[k], 1.6)) << "bin " << k;
    if (one[k] == 1.0) {
      EXPECT_EQ(p[k], 1.0);
      ++unit;
    } else if (one[k] == 1.37) {
      EXPECT_EQ(p[k], std::pow(1.37, 1.6));
      ++run;
    } else {
      ++between;
    }
  }
  EXPECT_GT(unit, 100);
  EXPECT_GT(run, 5);
  EXPECT_GT(between, 100);
}

TEST(MotionSimqke, DeterministicForSameInputs) {
  const Ec8Spectrum target(Ec8Type::type1, Ec8Ground::C, 0.35 * kGravity);
  SimqkeSettings s;
  s.max_iterations = 5;
  const GroundMotion a = generate_spectrum_compatible(target, 10.0, 7, s);
  const GroundMotion b = generate_spectrum_compatible(target, 10.0, 7, s);
  const GroundMotion c = generate_spectrum_compatible(target, 10.0, 8, s);
  ASSERT_EQ(a.accel.size(), 1001u);
  EXPECT_EQ(a.accel, b.accel);
  EXPECT_NE(a.accel, c.accel);
  EXPECT_DOUBLE_EQ(a.dt, 0.01);
}

// Coarse iterations (SimqkeStart::coarse_stride, issue 38): a corrector that scales the motion
// by 1.1 leaves its spectrum's shape as it is (the oscillators are linear: PSA(1.1^i a) = 1.1^i
// PSA(a)), so the coarse spectrum, the full one of iteration 0 (the reference) scaled by the
// computed periods' ratio and interpolated between them, is 1.1^i times it at every matching
// period, the computed and the skipped alike (to round-off), and so is the ratio the corrector is
// given. Plain interpolation of ln PSA between the computed periods misses the skipped ones by
// the spectrum's own roughness (here up to about 10 %). The returned attempt is scored over the
// coarse periods, its psa empty; score() gives it the full spectrum and score.
TEST(MotionSimqke, CoarseIterationsKeepTheReferenceShape) {
  const Ec8Spectrum target(Ec8Type::type1, Ec8Ground::C, 0.35 * kGravity);
  SimqkeGenerator gen(target, 10.0, SimqkeSettings{});
  SimqkeStart s = gen.start();
  s.coarse_stride = 4;
  s.full_every = 1000;  // the full spectrum at iteration 0 alone
  std::vector<double> re, im, full, psa;
  simqke_phasors(11, 0, 0, s.amplitude, re, im);
  const GroundMotion m0 = gen.synthesise(s, re, im);
  gen.spectrum(m0, full);
  const std::size_t np = full.size();
  int calls = 0;
  double largest = 0.0, off = 0.0;  // |relative error| of the ratio; of plain interpolation
  const SimqkeGenerator::Corrector scale = [&](GroundMotion& m, const std::vector<double>& ratio) {
    const double f = std::pow(1.1, calls);  // the ratio given is of iteration `calls`
    ASSERT_EQ(ratio.size(), np);
    for (std::size_t j = 0; j < np; ++j) {
      largest = std::max(largest, std::fabs(ratio[j] * f * full[j] / s.target[j] - 1.0));
      if (j % 4 == 2 && j + 2 < np)  // the mid-point in ln T of two computed periods
        off = std::max(off, std::fabs(std::sqrt(full[j - 2] * full[j + 2]) / full[j] - 1.0));
    }
    for (double& a : m.accel) a *= 1.1;
    ++calls;
  };
  SimqkeAttempt a = gen.match(s, m0, scale);
  EXPECT_GE(calls, 3);
  EXPECT_LT(largest, 1e-12);
  EXPECT_GT(off, 0.02);  // the test would see a plain interpolation
  EXPECT_TRUE(a.psa.empty());
  // The coarse score of the kept iteration: max |q - 1| over periods 0, 4, 8, ... and the last.
  const double g = std::pow(1.1, a.iterations);
  double coarse = 0.0;
  for (std::size_t j = 0; j < np; ++j)
    if (j % 4 == 0 || j + 1 == np)
      coarse = std::max(coarse, std::fabs(g * full[j] / s.target[j] - 1.0));
  EXPECT_NEAR(a.score, coarse, 1e-12);
  const int evaluations = a.spectra;
  gen.score(s, a);
  gen.spectrum(a.motion, psa);
  EXPECT_EQ(a.psa, psa);
  EXPECT_EQ(a.spectra, evaluations + 1);
  double dev = 0.0;
  for (std::size_t j = 0; j < np; ++j) dev = std::max(dev, std::fabs(psa[j] / s.target[j] - 1.0));
  EXPECT_EQ(a.score, dev);
}

// Issue 4 acceptance: every motion within 0.90-1.20 of the target at 100 log-spaced periods
// 0.05-4 s (5 %, sub-steps of T/20), the mean within 0.95-1.05, final velocity < 1 cm/s and
// final displacement < 1 cm.
void check_acceptance(const DesignSpectrum& target) {
  constexpr int kMotions = 7;
  SimqkeSettings settings;
  SimqkeGenerator gen(target, 20.0, settings);
  const std::vector<double> periods = log_spaced_periods(0.05, 4.0, 100);
  const std::vector<double> tgt = target.sample(periods);
  const SpectrumCalculator check(periods, 0.05, 0.01);
  std::vector<double> mean(periods.size(), 0.0);
  for (int i = 0; i < kMotions; ++i) {
    const GeneratedMotion g = gen.generate(2026, std::uint64_t(i));
    ASSERT_EQ(g.motion.accel.size(), 2001u);
    const std::vector<double> psa = check.compute(g.motion.accel).psa;
    const SpectrumMatch m = compare_spectra(psa, tgt);
    EXPECT_GE(m.min_ratio, 0.90) << "motion " << i;
    EXPECT_LE(m.max_ratio, 1.20) << "motion " << i;
    const GroundKinematics k = integrate(g.motion);
    EXPECT_LT(std::fabs(k.final_velocity()), 0.01) << "motion " << i;
    EXPECT_LT(std::fabs(k.final_displacement()), 0.01) << "motion " << i;
    EXPECT_DOUBLE_EQ(k.final_velocity(), g.final_velocity);
    for (std::size_t j = 0; j < periods.size(); ++j) mean[j] += psa[j] / kMotions;
  }
  const SpectrumMatch mm = compare_spectra(mean, tgt);
  EXPECT_GE(mm.min_ratio, 0.95);
  EXPECT_LE(mm.max_ratio, 1.05);
}

TEST(MotionSimqke, AcceptanceEurocode8Type1GroundC) {
  check_acceptance(Ec8Spectrum(Ec8Type::type1, Ec8Ground::C, 0.35 * kGravity));
}

TEST(MotionSimqke, AcceptanceNzs1170ClassC) {
  check_acceptance(Nzs1170Spectrum(NzsSiteClass::C, 0.4, 1.0));
}

}  // namespace
}  // namespace pound

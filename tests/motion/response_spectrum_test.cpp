// Response spectra: closed-form step and harmonic responses, and the published El Centro
// values of the fixture (motions/README.md).
#include "motion/response_spectrum.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "motion/motion_reader.hpp"

namespace pound {
namespace {

GroundMotion elcentro() {
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  return read_motion(spec);
}

// Constant ground acceleration a0 from rest: x(t) = -a0/w^2 (1 - e^{-z w t}(cos wd t +
// z/sqrt(1-z^2) sin wd t)); exact for a piecewise-linear input, so the recurrence must
// reproduce it to round-off at every sample.
TEST(MotionResponseSpectrum, StepResponseIsExact) {
  const double T = 0.7, z = 0.05, a0 = 2.5, dt = 0.013;
  GroundMotion m{"step", dt, std::vector<double>(500, a0)};
  const SdofHistory h = sdof_history(m, T, z);
  const double w = 2 * M_PI / T, q = std::sqrt(1 - z * z), wd = w * q;
  for (std::size_t i = 0; i < m.accel.size(); i += 37) {
    const double t = dt * double(i);
    const double e = std::exp(-z * w * t);
    const double x = -a0 / (w * w) * (1 - e * (std::cos(wd * t) + z / q * std::sin(wd * t)));
    const double v = -a0 / (w * w) * e * (w * w / wd) * std::sin(wd * t);
    EXPECT_NEAR(h.x[i], x, 1e-13) << "t = " << t;
    EXPECT_NEAR(h.v[i], v, 1e-12) << "t = " << t;
  }
}

// Peak of the step response: SD = a0/w^2 (1 + exp(-pi z / sqrt(1 - z^2))), reached at
// t = pi / wd; a step of pi / (40 wd) lands on it.
TEST(MotionResponseSpectrum, StepResponsePeak) {
  const double T = 1.0, z = 0.05, a0 = 1.0;
  const double w = 2 * M_PI / T, wd = w * std::sqrt(1 - z * z);
  GroundMotion m{"step", M_PI / wd / 40.0, std::vector<double>(400, a0)};
  const ResponseSpectrum r = response_spectrum(m, {T}, z);
  const double sd = a0 / (w * w) * (1 + std::exp(-M_PI * z / std::sqrt(1 - z * z)));
  EXPECT_NEAR(r.sd[0], sd, 1e-12);
  EXPECT_NEAR(r.psa[0], w * w * sd, 1e-10);
  EXPECT_NEAR(r.psv[0], w * sd, 1e-11);
}

// Harmonic input a_g = A sin(W t) from rest: steady state plus the free vibration that
// cancels its initial conditions. With 200 samples per forcing period the only error is the
// linear interpolation of the sine, O((W dt)^2 / 12) ~ 1e-4 relative.
TEST(MotionResponseSpectrum, HarmonicInputClosedForm) {
  const double T = 0.5, z = 0.05, A = 3.0;
  const double w = 2 * M_PI / T, q = std::sqrt(1 - z * z), wd = w * q;
  for (const double beta : {0.5, 1.0, 1.6}) {
    const double W = beta * w, dt = 2 * M_PI / W / 200.0;
    const std::size_t n = std::size_t(30.0 * T / dt);
    GroundMotion m{"sine", dt, {}};
    for (std::size_t i = 0; i < n; ++i) m.accel.push_back(A * std::sin(W * dt * double(i)));
    // Steady state of x'' + 2 z w x' + w^2 x = -A sin(W t): x = C sin W t + D cos W t.
    const double den = std::pow(w * w - W * W, 2) + std::pow(2 * z * w * W, 2);
    const double C = -A * (w * w - W * W) / den, D = A * 2 * z * w * W / den;
    // Free vibration with x(0) = -D, v(0) = -C W.
    const double x0 = -D, v0 = -C * W;
    double peak = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const double t = dt * double(i), e = std::exp(-z * w * t);
      const double x = C * std::sin(W * t) + D * std::cos(W * t) +
                       e * (x0 * std::cos(wd * t) + (v0 + z * w * x0) / wd * std::sin(wd * t));
      peak = std::max(peak, std::fabs(x));
    }
    const ResponseSpectrum r = response_spectrum(m, {T}, z);
    EXPECT_NEAR(r.sd[0] / peak, 1.0, 2e-4) << "beta = " << beta;
    if (beta == 1.0) {
      // At resonance the 30-cycle response approaches A / (2 z w^2) (1 - e^{-z w t}).
      EXPECT_NEAR(r.sd[0], A / (2 * z * w * w) * (1 - std::exp(-z * w * 30 * T)), 2e-3 * r.sd[0]);
    }
  }
}

TEST(MotionResponseSpectrum, ElCentroPublishedValues) {
  const GroundMotion m = elcentro();
  const std::vector<double> T = {0.2, 0.5, 1.0, 2.0};
  const ResponseSpectrum plain = response_spectrum(m, T, 0.05, {0.0});
  const ResponseSpectrum fine = response_spectrum(m, T, 0.05, {0.05});
  // motions/README.md: PSA 0.916 g (0.5 s), 0.454 g (1 s), 0.137 g (2 s); 0.2 s: 0.793 g
  // without sub-stepping, 0.820 g with steps of T/20. Published to three digits.
  EXPECT_NEAR(plain.psa[0] / kGravity, 0.793, 0.0006);
  EXPECT_NEAR(fine.psa[0] / kGravity, 0.820, 0.0006);
  EXPECT_NEAR(plain.psa[1] / kGravity, 0.916, 0.0006);
  EXPECT_NEAR(plain.psa[2] / kGravity, 0.454, 0.0006);
  EXPECT_NEAR(plain.psa[3] / kGravity, 0.137, 0.0006);
  // Pseudo-quantities are consistent, and the absolute acceleration at 5 % damping is
  // within a few percent of the pseudo-acceleration at these periods.
  for (std::size_t i = 0; i < T.size(); ++i) {
    const double w = 2 * M_PI / T[i];
    EXPECT_NEAR(fine.psv[i], w * fine.sd[i], 1e-12);
    EXPECT_NEAR(fine.sa_abs[i] / fine.psa[i], 1.0, 0.05);
  }
}

TEST(MotionResponseSpectrum, ZeroPeriodIsPga) {
  const GroundMotion m = elcentro();
  const ResponseSpectrum r = response_spectrum(m, {0.0, 0.01}, 0.05);
  EXPECT_DOUBLE_EQ(r.psa[0], m.pga());
  EXPECT_NEAR(r.psa[1] / m.pga(), 1.0, 0.02);  // a stiff oscillator follows the ground
}

// The PGA is computed only where a period 0 asks for it (issue 38: the generator's periods
// have none, and the pass over the record cost a twentieth of a spectrum): a period 0 anywhere
// in the list is the PGA on both entry points, and the other periods have the same bits with
// and without it, from compute() and from compute_psa().
TEST(MotionResponseSpectrum, ZeroPeriodIsPgaWhereverItStands) {
  const GroundMotion m = elcentro();
  const SpectrumCalculator with({0.5, 0.0, 1.0}, 0.05, m.dt), without({0.5, 1.0}, 0.05, m.dt);
  const ResponseSpectrum a = with.compute(m.accel), b = without.compute(m.accel);
  std::vector<double> pa, pb;
  with.compute_psa(m.accel, pa);
  without.compute_psa(m.accel, pb);
  ASSERT_EQ(pa.size(), 3u);
  ASSERT_EQ(pb.size(), 2u);
  EXPECT_EQ(a.psa[1], m.pga());
  EXPECT_EQ(a.sa_abs[1], m.pga());
  EXPECT_EQ(a.sd[1], 0.0);
  EXPECT_EQ(pa[1], m.pga());
  for (int i : {0, 1}) {
    const int j = i == 0 ? 0 : 2;  // the same period in the list with 0
    EXPECT_EQ(pb[i], b.psa[i]);
    EXPECT_EQ(pa[j], pb[i]);
    EXPECT_EQ(a.psa[j], b.psa[i]);
    EXPECT_EQ(a.sa_abs[j], b.sa_abs[i]);
    EXPECT_GT(pb[i], 0.0);
  }
}

// The recurrence as first written (before issue 13): each record step split into m equal
// sub-steps taken one after the other, the peaks looked for at every sub-step's end. The
// calculator now takes one step of dt and computes the inner points directly from the state at
// the step's start; both are exact for the piecewise-linear ground acceleration, so they agree
// to round-off.
ResponseSpectrum sub_stepped(const GroundMotion& g, const std::vector<double>& periods, double z) {
  ResponseSpectrum r;
  for (double T : periods) {
    const int m = std::max(1, int(std::ceil(g.dt / (0.05 * T) - 1e-9)));
    const SdofStep k = SdofStep::make(T, z, g.dt / m);
    const double w = 2 * M_PI / T;
    double x = 0, v = 0, xmax = 0, amax = 0;
    for (std::size_t i = 0; i + 1 < g.accel.size(); ++i)
      for (int j = 0; j < m; ++j) {
        const double da = (g.accel[i + 1] - g.accel[i]) / m;
        const double a0 = g.accel[i] + j * da, a1 = g.accel[i] + (j + 1) * da;
        const double xn = k.a11 * x + k.a12 * v + k.b11 * a0 + k.b12 * a1;
        v = k.a21 * x + k.a22 * v + k.b21 * a0 + k.b22 * a1;
        x = xn;
        xmax = std::max(xmax, std::fabs(x));
        amax = std::max(amax, std::fabs(2 * z * w * v + w * w * x));
      }
    r.sd.push_back(xmax);
    r.sa_abs.push_back(amax);
  }
  return r;
}

TEST(MotionResponseSpectrum, InnerPointsGiveTheSubSteppedPeaks) {
  GroundMotion noise{"noise", 0.01, {}};
  std::uint64_t s = 12345;
  for (int i = 0; i < 1500; ++i) {  // a rough record: uniform noise in [-3, 3] m/s^2
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    noise.accel.push_back(6.0 * double(s >> 11) / 9007199254740992.0 - 3.0);
  }
  // 0.011 s needs 19 sub-steps at 0.01 s, 0.2 s one; 37 periods fill several blocks of eight.
  const std::vector<double> T = log_spaced_periods(0.011, 6.0, 37);
  for (const GroundMotion& g : {elcentro(), noise}) {
    const ResponseSpectrum fast = response_spectrum(g, T, 0.05);
    const ResponseSpectrum ref = sub_stepped(g, T, 0.05);
    for (std::size_t i = 0; i < T.size(); ++i) {
      EXPECT_NEAR(fast.sd[i], ref.sd[i], 1e-12 * ref.sd[i]) << g.name << " T = " << T[i];
      EXPECT_NEAR(fast.sa_abs[i], ref.sa_abs[i], 1e-12 * ref.sa_abs[i])
          << g.name << " T = " << T[i];
    }
    // The inner points matter: without them some short period's peak is lower by > 1 %.
    const ResponseSpectrum plain = response_spectrum(g, T, 0.05, {0.0});
    double most = 0.0;
    for (std::size_t i = 0; i < T.size(); ++i) most = std::max(most, ref.sd[i] / plain.sd[i]);
    EXPECT_GT(most, 1.01) << g.name;
  }
}

TEST(MotionResponseSpectrum, EveryInstructionSetGivesTheSameBits) {
  const GroundMotion g = elcentro();
  const std::vector<double> T = log_spaced_periods(0.02, 5.0, 45);
  ResponseSpectrumOptions o;
  o.simd = SimdPath::baseline;
  const ResponseSpectrum base = response_spectrum(g, T, 0.05, o);
  int paths = 0;
  for (SimdPath p : {SimdPath::avx2, SimdPath::avx512, SimdPath::automatic}) {
    if (!simd_path_available(p)) continue;
    ++paths;
    o.simd = p;
    const ResponseSpectrum r = response_spectrum(g, T, 0.05, o);
    EXPECT_EQ(std::memcmp(r.sd.data(), base.sd.data(), T.size() * sizeof(double)), 0);
    EXPECT_EQ(std::memcmp(r.sa_abs.data(), base.sa_abs.data(), T.size() * sizeof(double)), 0);
  }
  EXPECT_GE(paths, 1);  // at least the automatic choice
}

TEST(MotionResponseSpectrum, LogSpacedPeriods) {
  const auto t = log_spaced_periods(0.05, 4.0, 100);
  ASSERT_EQ(t.size(), 100u);
  EXPECT_DOUBLE_EQ(t.front(), 0.05);
  EXPECT_DOUBLE_EQ(t.back(), 4.0);
  EXPECT_NEAR(t[1] / t[0], std::pow(80.0, 1.0 / 99.0), 1e-12);
}

}  // namespace
}  // namespace pound

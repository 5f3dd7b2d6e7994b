// Intensity envelopes: the defining values of Jennings-Housner-Tsai and Saragoni-Hart.
#include "motion/envelope.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"

namespace pound {
namespace {

TEST(MotionEnvelope, JenningsTrapezoidalExponential) {
  EnvelopeSettings s;  // automatic: t1 = 0.1 tw, t2 = 0.5 tw, I(tw) = 0.05
  const Envelope e(s, 20.0);
  EXPECT_DOUBLE_EQ(e(0.0), 0.0);
  EXPECT_NEAR(e(1.0), 0.25, 1e-15);  // (t / t1)^2 with t1 = 2 s
  EXPECT_DOUBLE_EQ(e(2.0), 1.0);
  EXPECT_DOUBLE_EQ(e(10.0), 1.0);
  EXPECT_NEAR(e(20.0), 0.05, 1e-12);
  EXPECT_NEAR(e(15.0), std::sqrt(0.05), 1e-12);  // exponential: half-way in log
  EXPECT_DOUBLE_EQ(e.strong_duration(), 8.0);
  s.rise = 1.0;
  s.strong_end = 6.0;
  s.decay = 0.5;
  const Envelope f(s, 20.0);
  EXPECT_NEAR(f(8.0), std::exp(-1.0), 1e-15);
  s.strong_end = 25.0;
  EXPECT_THROW(Envelope(s, 20.0), InputError);
}

TEST(MotionEnvelope, SaragoniHartPeakAndEnd) {
  EnvelopeSettings s;
  s.shape = EnvelopeShape::saragoni_hart;
  s.epsilon = 0.2;
  s.eta = 0.05;
  const Envelope e(s, 20.0);
  EXPECT_NEAR(e(4.0), 1.0, 1e-12);    // peak at eps tw
  EXPECT_NEAR(e(20.0), 0.05, 1e-12);  // eta at tw
  EXPECT_LT(e(3.9), 1.0);
  EXPECT_LT(e(4.1), 1.0);
  EXPECT_GT(e.strong_duration(), 3.0);
}

}  // namespace
}  // namespace pound

// Integration, baseline correction, truncation and scaling of records.
#include "motion/motion_processing.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "motion/motion_reader.hpp"

namespace pound {
namespace {

TEST(MotionProcessing, IntegrationIsExactForLinearAcceleration) {
  // a(t) = 2 + 3 t: v = 2 t + 1.5 t^2, d = t^2 + 0.5 t^3, exact for the piecewise-linear rule.
  GroundMotion m{"lin", 0.1, {}};
  for (int i = 0; i <= 50; ++i) m.accel.push_back(2.0 + 3.0 * 0.1 * i);
  const GroundKinematics k = integrate(m);
  const double t = 5.0;
  EXPECT_NEAR(k.final_velocity(), 2 * t + 1.5 * t * t, 1e-10);
  EXPECT_NEAR(k.final_displacement(), t * t + 0.5 * t * t * t, 1e-9);
}

TEST(MotionProcessing, BaselineCorrectionZeroesFinalVelocityAndDisplacement) {
  // A decaying sine plus a constant offset 0.05 m/s^2, which drifts 0.05*20^2/2 = 10 m.
  GroundMotion m{"drift", 0.01, {}};
  for (int i = 0; i <= 2000; ++i) {
    const double t = 0.01 * i;
    m.accel.push_back(3.0 * std::exp(-0.2 * t) * std::sin(2 * M_PI * 1.3 * t) + 0.05);
  }
  ASSERT_GT(std::fabs(integrate(m).final_displacement()), 5.0);
  const GroundMotion c = baseline_correct(m);
  const GroundKinematics k = integrate(c);
  EXPECT_LT(std::fabs(k.final_velocity()), 1e-10);
  EXPECT_LT(std::fabs(k.final_displacement()), 1e-10);
  // The correction is a smooth low-order polynomial: the peak changes little.
  EXPECT_NEAR(c.pga(), m.pga(), 0.5);
  EXPECT_DOUBLE_EQ(c.accel.front(), m.accel.front());  // the correction vanishes at both ends
  EXPECT_DOUBLE_EQ(c.accel.back(), m.accel.back());
}

TEST(MotionProcessing, TruncateAndScale) {
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  const GroundMotion m = read_motion(spec);
  const GroundMotion t = truncate(m, 8.0);  // the thesis uses the first 8 s
  EXPECT_EQ(t.accel.size(), 401u);
  EXPECT_NEAR(t.duration(), 8.0, 1e-12);
  const GroundMotion s = scale(t, 0.5);
  EXPECT_NEAR(s.pga(), 0.5 * 0.31882 * kGravity, 1e-12);
  EXPECT_EQ(truncate(m, 100.0).accel.size(), m.accel.size());
}

}  // namespace
}  // namespace pound

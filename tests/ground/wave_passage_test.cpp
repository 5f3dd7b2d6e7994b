// Wave passage: arrival delays along the row and the delay of a record by whole and
// fractional samples.
#include "ground/wave_passage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace pound {
namespace {

TEST(GroundWavePassage, ArrivalDelaysFollowTheDirectionOfTravel) {
  const std::vector<double> x = {0.0, 20.0, 50.0};
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(arrival_delays(x, inf), (std::vector<double>{0.0, 0.0, 0.0}));
  EXPECT_EQ(arrival_delays(x, -inf), (std::vector<double>{0.0, 0.0, 0.0}));
  const std::vector<double> fwd = arrival_delays(x, 500.0);
  EXPECT_DOUBLE_EQ(fwd[0], 0.0);
  EXPECT_DOUBLE_EQ(fwd[1], 0.04);
  EXPECT_DOUBLE_EQ(fwd[2], 0.1);
  const std::vector<double> back = arrival_delays(x, -250.0);
  EXPECT_DOUBLE_EQ(back[0], 0.2);
  EXPECT_DOUBLE_EQ(back[1], 0.12);
  EXPECT_DOUBLE_EQ(back[2], 0.0);
  EXPECT_THROW(arrival_delays(x, 0.0), std::invalid_argument);
  EXPECT_THROW(arrival_delays(x, std::nan("")), std::invalid_argument);
}

GroundMotion record(std::size_t n, double dt) {
  GroundMotion m;
  m.name = "test";
  m.dt = dt;
  for (std::size_t i = 0; i < n; ++i) m.accel.push_back(std::sin(0.37 * double(i)) + 0.1 * i);
  return m;
}

TEST(GroundWavePassage, ZeroAndWholeSampleDelaysAreExact) {
  const GroundMotion m = record(501, 0.01);
  const GroundMotion same = delayed(m, 0.0);
  EXPECT_EQ(same.accel, m.accel);
  EXPECT_EQ(same.name, m.name);
  EXPECT_EQ(same.dt, m.dt);
  // 0.07 s = 7 samples (7.000000000000001 in floating point: within 1e-9 of a whole number).
  const GroundMotion d = delayed(m, 0.07);
  ASSERT_EQ(d.accel.size(), m.accel.size() + 7);
  for (std::size_t i = 0; i < 7; ++i) EXPECT_EQ(d.accel[i], 0.0);
  for (std::size_t i = 0; i < m.accel.size(); ++i) ASSERT_EQ(d.accel[i + 7], m.accel[i]);
  EXPECT_EQ(d.dt, m.dt);
  EXPECT_NE(d.name.find("test, delayed by 0.07 s"), std::string::npos) << d.name;
  EXPECT_THROW(delayed(m, -0.01), std::invalid_argument);
}

// A band-limited signal: sines at 1.3, 7.9 and 31 Hz (below 0.8 Nyquist = 40 Hz at dt = 0.01 s)
// under a Gaussian envelope that is below 1e-16 at both ends of the record.
double signal(double t) {
  const double e = std::exp(-0.5 * (t - 10.0) * (t - 10.0) / (1.2 * 1.2));
  return e * (std::sin(2 * M_PI * 1.3 * t) + 0.5 * std::cos(2 * M_PI * 7.9 * t + 0.3) +
              0.2 * std::sin(2 * M_PI * 31.0 * t + 1.1));
}

TEST(GroundWavePassage, FractionalDelayOfABandLimitedSignalIsTheShiftedSignal) {
  GroundMotion m;
  m.dt = 0.01;
  for (int i = 0; i <= 2000; ++i) m.accel.push_back(signal(0.01 * i));
  for (double delay : {0.0337, 0.1234567, 0.005}) {
    const GroundMotion d = delayed(m, delay);
    ASSERT_EQ(d.accel.size(), m.accel.size() + std::size_t(std::ceil(delay / m.dt)));
    double peak = 0.0, err = 0.0;
    for (std::size_t i = 0; i < d.accel.size(); ++i) {
      const double exact = signal(0.01 * double(i) - delay);
      peak = std::max(peak, std::fabs(exact));
      err = std::max(err, std::fabs(d.accel[i] - exact));
    }
    EXPECT_LT(err / peak, 1e-6) << "delay " << delay;
  }
}

}  // namespace
}  // namespace pound

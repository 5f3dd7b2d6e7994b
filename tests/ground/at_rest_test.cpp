// Generated motions under different buildings made to end at rest (ground/at_rest.hpp, issue
// 28): the trace's final velocity and displacement vanish (a conservation check on the exact
// integrals, independent of the correction's form), the leading zeros and the last value stay,
// a whole-sample delay commutes with the correction bit for bit, and one motion under every
// building is left untouched.
#include "ground/at_rest.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ground/ground_trace.hpp"
#include "ground/wave_passage.hpp"

namespace pound {
namespace {

// 8 s at 0.01 s of a decaying two-tone motion that starts at a_0 = 1.2 m/s^2 and carries a
// constant offset: from rest its velocity and displacement drift.
GroundMotion drifting(double phase) {
  GroundMotion m;
  m.name = "drifting";
  m.dt = 0.01;
  for (int i = 0; i <= 800; ++i) {
    const double t = i * m.dt;
    m.accel.push_back(1.2 * std::cos(2.0 * M_PI * 1.7 * t + phase) * std::exp(-0.3 * t) +
                      0.8 * std::sin(2.0 * M_PI * 4.1 * t) + 0.05);
  }
  return m;
}

double final_velocity(const GroundMotion& m) {
  const GroundTrace tr(m);
  return tr.vel(tr.duration() + 1.0);
}

double final_displacement(const GroundMotion& m) {
  const GroundTrace tr(m);
  return tr.disp(tr.duration() + 1.0);
}

TEST(AtRest, TheTraceEndsAtRestAndKeepsItsEnds) {
  const GroundMotion m = drifting(0.0);
  ASSERT_GT(std::fabs(final_velocity(m)), 0.05);  // it does drift before
  const GroundMotion c = ending_at_rest(m);
  ASSERT_EQ(c.accel.size(), m.accel.size());
  EXPECT_EQ(c.dt, m.dt);
  // The correction vanishes at the rest before the record (t = -dt) and at its end: the last
  // value stays, the first moves by the correction one sample in.
  EXPECT_EQ(c.accel.back(), m.accel.back());
  EXPECT_NEAR(c.accel.front(), m.accel.front(), 0.05);
  EXPECT_LT(std::fabs(final_velocity(c)), 1e-12);
  EXPECT_LT(std::fabs(final_displacement(c)), 1e-12);
  // The correction is a slow polynomial: small beside the record's peak (1.2 + 0.8 + 0.05).
  double change = 0.0;
  for (std::size_t i = 0; i < m.accel.size(); ++i)
    change = std::max(change, std::fabs(c.accel[i] - m.accel[i]));
  EXPECT_LT(change, 0.2);
}

TEST(AtRest, LeadingZerosStayAndAWholeSampleDelayCommutes) {
  const GroundMotion m = drifting(0.4);
  const GroundMotion late = delayed(m, 7 * m.dt);  // seven leading zeros
  const GroundMotion c = ending_at_rest(late);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(c.accel[i], 0.0) << i;
  EXPECT_LT(std::fabs(final_velocity(c)), 1e-12);
  EXPECT_LT(std::fabs(final_displacement(c)), 1e-12);
  // The same correction as the undelayed record's, shifted: the delayed trace is the other one
  // seven samples later (ground_trace.hpp), so corrected motions still differ by the delay only.
  const GroundMotion c0 = ending_at_rest(m);
  ASSERT_EQ(c.accel.size(), c0.accel.size() + 7);
  for (std::size_t i = 0; i < c0.accel.size(); ++i) EXPECT_EQ(c.accel[i + 7], c0.accel[i]) << i;
}

TEST(AtRest, OnlyDifferingMotionsAreCorrected) {
  const GroundMotion m = drifting(0.0);
  std::vector<GroundMotion> same = {m, m, m};
  end_at_rest_where_they_differ(same);
  for (const GroundMotion& s : same) EXPECT_EQ(s.accel, m.accel);  // bit for bit: uniform input
  std::vector<GroundMotion> row = {m, drifting(1.0), delayed(m, 0.0237)};
  end_at_rest_where_they_differ(row);
  for (const GroundMotion& s : row) {
    EXPECT_LT(std::fabs(final_velocity(s)), 1e-12);
    EXPECT_LT(std::fabs(final_displacement(s)), 1e-12);
  }
  // A fractional delay's band-limited shift leaves its own drift, taken away too; the relative
  // ground displacement of the first and last building stays bounded after the records.
  const GroundTrace a(row[0]), b(row[2]);
  const double end = b.duration();
  EXPECT_NEAR(a.disp(end + 10.0) - b.disp(end + 10.0), a.disp(end) - b.disp(end), 1e-12);
}

}  // namespace
}  // namespace pound

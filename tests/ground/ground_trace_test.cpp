// The ground under each building (issue 28; physics.md section 5a): GroundTrace's velocity and
// displacement against closed forms, delayed records moving apart only by the delay, the
// channels RowGround shares, and the exact peak relative ground displacement against a dense
// search.
#include "ground/ground_trace.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "ground/row_ground.hpp"
#include "ground/wave_passage.hpp"
#include "motion/motion_reader.hpp"

namespace pound {
namespace {

GroundMotion record_of(std::vector<double> accel, double dt) {
  GroundMotion m;
  m.name = "test";
  m.dt = dt;
  m.accel = std::move(accel);
  return m;
}

std::string fmt(double x) {
  char s[32];
  std::snprintf(s, sizeof s, "%.3g", x);
  return s;
}

GroundMotion elcentro() {
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  return read_motion(spec);
}

// The acceleration is linear between samples and rises from 0 at t = -dt to a_0 at t = 0
// (ground_trace.hpp), so a record of constant a_i = A has, with T its last sample,
//   vg = A (t + dt)^2 / (2 dt), ug = A (t + dt)^3 / (6 dt)          on [-dt, 0],
//   vg = A (t + dt / 2),        ug = A dt^2 / 6 + A dt t / 2 + A t^2 / 2   on [0, T],
// and vg(T), ug(T) + vg(T) (t - T) after T (the acceleration 0 there).
TEST(GroundTrace, ConstantAccelerationMatchesTheClosedForm) {
  const double A = 1.7, dt = 0.02;
  const int n = 101;  // T = 2 s
  const GroundTrace g(record_of(std::vector<double>(n, A), dt));
  const double T = dt * (n - 1);
  auto v_exact = [&](double t) {
    if (t <= -dt) return 0.0;
    if (t < 0.0) return A * (t + dt) * (t + dt) / (2 * dt);
    return A * (std::min(t, T) + dt / 2);
  };
  auto u_exact = [&](double t) {
    if (t <= -dt) return 0.0;
    if (t < 0.0) return A * std::pow(t + dt, 3) / (6 * dt);
    const double s = std::min(t, T);
    return A * dt * dt / 6 + A * dt * s / 2 + A * s * s / 2 + v_exact(T) * (t - s);
  };
  double worst_v = 0.0, worst_u = 0.0;
  for (int k = -80; k <= 3000; ++k) {  // every 1.37 ms from -0.11 s to 4.0 s
    const double t = 0.00137 * k;
    worst_v = std::max(worst_v, std::fabs(g.vel(t) - v_exact(t)) / (A * (T + dt)));
    worst_u = std::max(worst_u, std::fabs(g.disp(t) - u_exact(t)) / u_exact(4.2));
  }
  EXPECT_LT(worst_v, 1e-13);
  EXPECT_LT(worst_u, 1e-13);
  RecordProperty("worst_relative_v_u", fmt(worst_v) + " " + fmt(worst_u));
  // The rise from rest: nothing before -dt, a_0 dt / 2 and a_0 dt^2 / 6 at t = 0.
  EXPECT_EQ(g.vel(-dt), 0.0);
  EXPECT_EQ(g.disp(-0.5), 0.0);
  EXPECT_DOUBLE_EQ(g.vel(0.0), A * dt / 2);
  EXPECT_DOUBLE_EQ(g.disp(0.0), A * dt * dt / 6);
  EXPECT_DOUBLE_EQ(g.vel(-dt / 2), A * dt / 8);
  EXPECT_DOUBLE_EQ(g.disp(-dt / 2), A * dt * dt / 48);
  EXPECT_EQ(g.acc(-dt / 2), 0.0);  // the buildings' own ground acceleration: 0 before t = 0
  // After the record: the acceleration 0, the velocity held, the displacement linear in t.
  EXPECT_EQ(g.acc(T + 0.5), 0.0);
  EXPECT_NEAR(g.vel(T + 3.0), A * (T + dt / 2), 1e-13 * A * T);  // summed over 100 samples
  EXPECT_NEAR(g.disp(T + 3.0) - g.disp(T + 1.0), 2.0 * A * (T + dt / 2), 1e-12);
}

// a_i = c0 + c1 t_i: the piecewise-linear acceleration is c0 + c1 t on [0, T], so
//   vg = c0 dt / 2 + c0 t + c1 t^2 / 2,  ug = c0 dt^2 / 6 + c0 dt t / 2 + c0 t^2 / 2 + c1 t^3 / 6.
TEST(GroundTrace, LinearAccelerationMatchesTheClosedForm) {
  const double c0 = -0.8, c1 = 0.45, dt = 0.01;
  const int n = 1201;  // T = 12 s
  std::vector<double> a;
  for (int i = 0; i < n; ++i) a.push_back(c0 + c1 * dt * i);
  const GroundTrace g(record_of(a, dt));
  const double T = dt * (n - 1);
  auto v_exact = [&](double t) { return c0 * dt / 2 + c0 * t + c1 * t * t / 2; };
  auto u_exact = [&](double t) {
    return c0 * dt * dt / 6 + c0 * dt * t / 2 + c0 * t * t / 2 + c1 * t * t * t / 6;
  };
  const double vs = std::fabs(v_exact(T)), us = std::fabs(u_exact(T));
  double worst_v = 0.0, worst_u = 0.0, worst_a = 0.0;
  for (int k = 0; k <= 5000; ++k) {
    const double t = T * k / 5000.0 * (1 - 1e-15);
    worst_a = std::max(worst_a, std::fabs(g.acc(t) - (c0 + c1 * t)));
    worst_v = std::max(worst_v, std::fabs(g.vel(t) - v_exact(t)) / vs);
    worst_u = std::max(worst_u, std::fabs(g.disp(t) - u_exact(t)) / us);
  }
  EXPECT_LT(worst_a, 1e-12);
  EXPECT_LT(worst_v, 1e-12);
  EXPECT_LT(worst_u, 1e-12);
  RecordProperty("worst_relative_v_u", fmt(worst_v) + " " + fmt(worst_u));
  // After the record's end: the final velocity, the displacement growing linearly with it.
  for (double after : {0.013, 1.0, 7.5}) {
    EXPECT_NEAR(g.vel(T + after), v_exact(T), 1e-12 * vs);
    EXPECT_NEAR(g.disp(T + after), u_exact(T) + v_exact(T) * after, 1e-12 * us);
  }
}

// Just below the last sample, t / dt can round to the last index (for dt = 0.02 s and 36
// samples, t = nextafter(0.7, 0) gives 35): the interval's formula must not read a sample
// past the record. A stale value kept in the vector's spare capacity shows such a read.
TEST(GroundTrace, JustBeforeTheLastSampleReadsOnlyTheRecord) {
  for (int n : {36, 42, 70, 71, 83}) {
    GroundMotion m = record_of(std::vector<double>(n, 1.0), 0.02);
    m.accel.push_back(1e300);  // a stale value beyond the end
    m.accel.pop_back();
    const double last = m.duration();
    const GroundTrace g(std::move(m));
    const double t = std::nextafter(last, 0.0);
    ASSERT_LT(t, last);
    EXPECT_NEAR(g.vel(t), g.vel(last), 1e-12) << n;
    EXPECT_NEAR(g.disp(t), g.disp(last), 1e-12) << n;
  }
}

// A record delayed by k whole samples (k leading zeros) rises from rest at its last leading
// zero as the record does at -dt, so its vg and ug are the record's shifted by k dt (to
// round-off), for a record that starts at a non-zero acceleration (El Centro: 0.0063 g).
TEST(GroundTrace, WholeSampleDelayShiftsVelocityAndDisplacement) {
  const GroundMotion m = elcentro();
  ASSERT_NE(m.accel.front(), 0.0);
  const GroundTrace g(m);
  double vmax = 0.0, umax = 0.0;
  for (double t = 0.0; t < m.duration() + 2.0; t += 0.001) {
    vmax = std::max(vmax, std::fabs(g.vel(t)));
    umax = std::max(umax, std::fabs(g.disp(t)));
  }
  for (int k : {1, 5, 37}) {
    // By leading zeros written here, and by delayed().
    GroundMotion z = m;
    z.accel.insert(z.accel.begin(), std::size_t(k), 0.0);
    const GroundMotion d = delayed(m, k * m.dt);
    ASSERT_EQ(d.accel, z.accel);
    const GroundTrace gz(z);
    double worst_v = 0.0, worst_u = 0.0;
    for (double t = -0.05; t < m.duration() + 2.0; t += 0.00071) {
      const double ts = t + k * m.dt;
      worst_v = std::max(worst_v, std::fabs(gz.vel(ts) - g.vel(t)));
      worst_u = std::max(worst_u, std::fabs(gz.disp(ts) - g.disp(t)));
    }
    EXPECT_LT(worst_v, 1e-12 * vmax) << k;
    EXPECT_LT(worst_u, 1e-12 * umax) << k;
    RecordProperty("worst_relative_v_u_" + std::to_string(k),
                   fmt(worst_v / vmax) + " " + fmt(worst_u / umax));
    // Nothing moves before the delayed record's ramp.
    EXPECT_EQ(gz.vel((k - 1) * m.dt * 0.999), 0.0);
    EXPECT_EQ(gz.disp((k - 1) * m.dt * 0.999), 0.0);
  }
}

TEST(RowGround, EqualMotionsShareAChannel) {
  const GroundMotion m = elcentro();
  GroundMotion copy = m;
  copy.name = "another name, the same values";
  GroundMotion scaled = m;
  for (double& a : scaled.accel) a *= 0.5;
  const RowGround g = RowGround::per_building({m, copy, delayed(m, 0.1), scaled, m});
  EXPECT_EQ(g.buildings(), 5);
  EXPECT_EQ(g.channels(), 3);
  EXPECT_EQ(g.channel(0), 0);
  EXPECT_EQ(g.channel(1), 0);
  EXPECT_EQ(g.channel(2), 1);
  EXPECT_EQ(g.channel(3), 2);
  EXPECT_EQ(g.channel(4), 0);
  EXPECT_EQ(&g.under(4), &g.trace(0));
  EXPECT_EQ(g.peak_relative_displacement(0, 4, 40.0), 0.0);
  EXPECT_DOUBLE_EQ(g.duration(), m.duration() + 0.1);
  EXPECT_EQ(g.pga(), m.pga());
  // One motion under every building: one channel, as RowGround::uniform.
  const RowGround same = RowGround::per_building({m, m, m});
  EXPECT_EQ(same.channels(), 1);
  EXPECT_EQ(RowGround::uniform(m, 3).channels(), 1);
  // Different spacings cannot share the solvers' grid.
  GroundMotion other = m;
  other.dt = 0.01;
  EXPECT_THROW(RowGround::per_building({m, other}), std::invalid_argument);
}

// The largest |ug_a - ug_b| over [0, t_end] by a dense search: 40 points per sample interval,
// then a golden-section refinement around every sampled local maximum within 1e-6 of the
// best, and the ends.
double dense_peak(const RowGround& g, double t_end) {
  const GroundTrace &a = g.under(0), &b = g.under(1);
  auto f = [&](double t) { return std::fabs(a.disp(t) - b.disp(t)); };
  const double h = g.dt() / 40.0;
  const long m = static_cast<long>(std::ceil(t_end / h));
  std::vector<double> fs(m + 1);
  for (long i = 0; i <= m; ++i) fs[i] = f(std::min(h * i, t_end));
  double best = std::max(fs.front(), fs.back());
  for (double x : fs) best = std::max(best, x);
  double peak = std::max(fs.front(), fs.back());
  for (long i = 1; i < m; ++i) {
    if (!(fs[i] >= fs[i - 1] && fs[i] >= fs[i + 1] && fs[i] >= best * (1 - 1e-6))) continue;
    double lo = h * (i - 1), hi = std::min(h * (i + 1), t_end);
    const double r = (std::sqrt(5.0) - 1) / 2;
    for (int it = 0; it < 120; ++it) {
      const double x1 = hi - r * (hi - lo), x2 = lo + r * (hi - lo);
      if (f(x1) < f(x2))
        lo = x1;
      else
        hi = x2;
    }
    peak = std::max({peak, fs[i], f(0.5 * (lo + hi))});
  }
  return peak;
}

TEST(RowGround, PeakRelativeDisplacementMatchesADenseSearch) {
  const GroundMotion m = elcentro();
  // 1. El Centro against 0.8 x El Centro 7 samples later (longer by 0.14 s).
  GroundMotion late = delayed(m, 7 * m.dt);
  for (double& a : late.accel) a *= 0.8;
  // 2. El Centro against 12 s of a different record (two sines, ending at a non-zero value).
  std::vector<double> s;
  for (int i = 0; i <= 600; ++i) {
    const double t = m.dt * i;
    s.push_back(2.5 * std::sin(2 * M_PI * 1.3 * t) + 1.1 * std::cos(2 * M_PI * 3.7 * t + 0.4));
  }
  // 3. A record that ends at 1 m/s^2 (velocity 1.005 m/s) while the other, at rest until then,
  // accelerates at 410 m/s^2 from that sample on: the relative displacement peaks 0.7 samples
  // after the first record's end, where that record's acceleration is already 0.
  const double dt = 0.01;
  std::vector<double> ends(101, 1.0), starts(101, 0.0);
  starts.push_back(410.0);
  starts.push_back(410.0);
  struct Case {
    std::string name;
    RowGround g;
    double t_end;
  };
  const std::vector<Case> cases = {
      {"el centro / delayed 0.8 el centro", RowGround::per_building({m, late}),
       late.duration() + 2.0},
      {"el centro / two sines", RowGround::per_building({m, record_of(s, m.dt)}), 15.0},
      {"el centro / two sines, cut at 7.123 s", RowGround::per_building({m, record_of(s, m.dt)}),
       7.123},
      {"a record ending at 1 m/s^2",
       RowGround::per_building({record_of(ends, dt), record_of(starts, dt)}), 1.02}};
  for (const auto& c : cases) {
    const double exact = c.g.peak_relative_displacement(0, 1, c.t_end);
    const double dense = dense_peak(c.g, c.t_end);
    EXPECT_NEAR(exact, dense, 1e-9 * dense) << c.name;
    EXPECT_EQ(exact, c.g.peak_relative_displacement(1, 0, c.t_end)) << c.name;
    char note[96];
    std::snprintf(note, sizeof note, "%.9g m, dense %.3g relative", exact, (exact - dense) / dense);
    RecordProperty(c.name, note);
  }
}

}  // namespace
}  // namespace pound

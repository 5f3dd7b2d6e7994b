#include "ground/row_ground.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "motion/motion_processing.hpp"

namespace pound {

RowGround RowGround::uniform(const GroundMotion& motion, int buildings) {
  RowGround g;
  g.traces_.emplace_back(motion);
  g.channel_of_.assign(static_cast<std::size_t>(buildings), 0);
  return g;
}

RowGround RowGround::per_building(const std::vector<GroundMotion>& motions) {
  RowGround g;
  std::vector<const GroundMotion*> seen;
  for (const auto& m : motions) {
    if (!seen.empty() && m.dt != seen.front()->dt)
      throw std::invalid_argument("RowGround: the buildings' motions have different spacings");
    int c = -1;
    for (std::size_t k = 0; k < seen.size() && c < 0; ++k)
      if (seen[k]->dt == m.dt && seen[k]->accel == m.accel) c = static_cast<int>(k);
    if (c < 0) {
      c = static_cast<int>(seen.size());
      seen.push_back(&m);
      g.traces_.emplace_back(m);
    }
    g.channel_of_.push_back(c);
  }
  return g;
}

double RowGround::duration() const {
  double d = 0.0;
  for (const auto& t : traces_) d = std::max(d, t.duration());
  return d;
}

double RowGround::pga() const {
  double a = 0.0;
  for (const auto& t : traces_) a = std::max(a, t.motion().pga());
  return a;
}

RowGround RowGround::scaled(double factor) const {
  RowGround g;
  g.channel_of_ = channel_of_;
  for (const auto& t : traces_) g.traces_.emplace_back(scale(t.motion(), factor));
  return g;
}

double RowGround::peak_relative_displacement(int a, int b, double t_end) const {
  const int ca = channel(a), cb = channel(b);
  if (ca == cb) return 0.0;
  const GroundTrace &ta = traces_[ca], &tb = traces_[cb];
  const double dt = ta.dt();
  auto diff = [&](double t) { return std::fabs(ta.disp(t) - tb.disp(t)); };
  // A trace's acceleration at the start and end of sample interval i [m/s^2].
  auto on_interval = [](const GroundTrace& g, long i, double& a0, double& a1) {
    const std::vector<double>& acc = g.motion().accel;
    const auto k = static_cast<std::size_t>(i);
    a0 = a1 = 0.0;
    if (k + 1 < acc.size()) {
      a0 = acc[k];
      a1 = acc[k + 1];
    }
  };
  double peak = 0.0;
  const double last = std::min(t_end, std::max(ta.duration(), tb.duration()));
  const auto intervals = static_cast<long>(std::ceil(last / dt - 1e-9));
  for (long i = 0; i < intervals; ++i) {
    const double t0 = dt * double(i), t1 = std::min(dt * double(i + 1), last);
    peak = std::max(peak, diff(t0));
    // The rate of the difference over the interval is quadratic in s = t - t0:
    // r(s) = dv0 + da0 s + (da1 - da0) s^2 / (2 dt), dv the velocity and da the acceleration
    // differences at the interval's ends (ground_trace.hpp).
    // The accelerations on the interval: linear between its samples, 0 from a record's last
    // sample on (GroundMotion::at gives a_last at that sample itself, not 0 after it).
    double a0a, a1a, a0b, a1b;
    on_interval(ta, i, a0a, a1a);
    on_interval(tb, i, a0b, a1b);
    const double dv0 = ta.vel(t0) - tb.vel(t0);
    const double da0 = a0a - a0b;
    const double da1 = a1a - a1b;
    const double A = (da1 - da0) / (2.0 * dt), B = da0, C = dv0;
    double roots[2];
    int nr = 0;
    if (std::fabs(A) > 0.0) {
      const double disc = B * B - 4.0 * A * C;
      if (disc >= 0.0) {
        const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
        if (q != 0.0) roots[nr++] = q / A;
        if (q != 0.0) roots[nr++] = C / q;
      }
    } else if (B != 0.0) {
      roots[nr++] = -C / B;
    }
    for (int k = 0; k < nr; ++k)
      if (roots[k] > 0.0 && t0 + roots[k] < t1) peak = std::max(peak, diff(t0 + roots[k]));
  }
  peak = std::max(peak, diff(last));
  // After both records the difference changes linearly: its largest value is at t_end.
  if (t_end > last) peak = std::max(peak, diff(t_end));
  return peak;
}

}  // namespace pound

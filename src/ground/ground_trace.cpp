#include "ground/ground_trace.hpp"

#include <algorithm>
#include <utility>

#include "motion/motion_processing.hpp"

namespace pound {

GroundTrace::GroundTrace(GroundMotion motion) : motion_(std::move(motion)) {
  GroundKinematics k = integrate(motion_);
  v_ = std::move(k.velocity);
  u_ = std::move(k.displacement);
  if (motion_.accel.empty()) return;
  // From rest at t = -dt, the acceleration rising linearly to a_0 at t = 0 (see the header).
  const double dt = motion_.dt, a0 = motion_.accel.front();
  const double v0 = a0 * dt / 2.0, u0 = a0 * dt * dt / 6.0;
  for (std::size_t i = 0; i < v_.size(); ++i) {
    u_[i] += u0 + v0 * (dt * double(i));
    v_[i] += v0;
  }
}

void GroundTrace::kinematics(double t, double& v, double& u) const {
  const std::size_t n = motion_.accel.size();
  const double dt = motion_.dt;
  if (n == 0 || !(t > -dt)) {
    v = u = 0.0;
    return;
  }
  if (t < 0.0) {  // the rise from rest at -dt to a_0 at 0
    const double s = t + dt, a0 = motion_.accel.front();
    v = a0 * s * s / (2.0 * dt);
    u = a0 * s * s * s / (6.0 * dt);
    return;
  }
  const double last = dt * double(n - 1);
  if (t >= last) {  // after the record: the final velocity, the displacement growing with it
    v = v_[n - 1];
    u = u_[n - 1] + v_[n - 1] * (t - last);
    return;
  }
  // t / dt rounds to n - 1 for some t just below the last sample: stay on the last interval.
  const auto i = std::min(static_cast<std::size_t>(t / dt), n - 2);
  const double s = t - dt * double(i);
  const double a0 = motion_.accel[i], da = motion_.accel[i + 1] - a0;
  v = v_[i] + s * (a0 + da * s / (2.0 * dt));
  u = u_[i] + s * (v_[i] + s * (a0 / 2.0 + da * s / (6.0 * dt)));
}

double GroundTrace::vel(double t) const {
  double v, u;
  kinematics(t, v, u);
  return v;
}

double GroundTrace::disp(double t) const {
  double v, u;
  kinematics(t, v, u);
  return u;
}

}  // namespace pound

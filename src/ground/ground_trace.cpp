#include "ground/ground_trace.hpp"

#include <utility>

#include "motion/motion_processing.hpp"

namespace pound {

GroundTrace::GroundTrace(GroundMotion motion) : motion_(std::move(motion)) {
  GroundKinematics k = integrate(motion_);
  v_ = std::move(k.velocity);
  u_ = std::move(k.displacement);
}

void GroundTrace::kinematics(double t, double& v, double& u) const {
  const std::size_t n = motion_.accel.size();
  if (n == 0 || !(t > 0.0)) {
    v = u = 0.0;
    return;
  }
  const double dt = motion_.dt;
  const double last = dt * double(n - 1);
  if (t >= last) {  // after the record: the final velocity, the displacement growing with it
    v = v_[n - 1];
    u = u_[n - 1] + v_[n - 1] * (t - last);
    return;
  }
  const auto i = static_cast<std::size_t>(t / dt);
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

#pragma once
// The ground under one building (issue 28): its acceleration ag(t), piecewise linear between
// the samples of a record, zero before t = 0 and after the last sample, and the exact integrals
// of that acceleration from rest, the velocity vg(t) and the displacement ug(t) (physics.md
// section 5a: the contact between buildings on different ground acts on absolute
// displacements). After the record vg keeps its final value and ug grows linearly with it (no
// baseline correction here: the [motion] keys decide that). Kernel only: no files, no printing.
#include <cstddef>
#include <vector>

#include "motion/ground_motion.hpp"

namespace pound {

class GroundTrace {
 public:
  GroundTrace() = default;
  explicit GroundTrace(GroundMotion motion);

  const GroundMotion& motion() const { return motion_; }
  double dt() const { return motion_.dt; }  ///< sample spacing [s]
  /// Time of the last sample [s].
  double duration() const { return motion_.duration(); }

  /// Acceleration [m/s^2] (GroundMotion::at: linear between samples).
  double acc(double t) const { return motion_.at(t); }
  /// Velocity [m/s] and displacement [m] at t [s]: on the sample interval [t_i, t_i+1] with
  /// s = t - t_i and a(s) = a_i + (a_i+1 - a_i) s / dt (physics.md section 5),
  ///   vg = v_i + a_i s + (a_i+1 - a_i) s^2 / (2 dt),
  ///   ug = u_i + v_i s + a_i s^2 / 2 + (a_i+1 - a_i) s^3 / (6 dt),
  /// with v_i, u_i the exact integrals at the samples (motion_processing.hpp, integrate()).
  double vel(double t) const;
  double disp(double t) const;
  /// Both at once [m/s], [m].
  void kinematics(double t, double& v, double& u) const;

 private:
  GroundMotion motion_;
  std::vector<double> v_, u_;  // at the samples [m/s], [m]
};

}  // namespace pound

#pragma once
// The ground under one building (issue 28): its acceleration ag(t), piecewise linear between
// the samples of a record, zero before t = 0 and after the last sample, and the exact integrals
// of that acceleration, the velocity vg(t) and the displacement ug(t) (physics.md section 5a:
// the contact between buildings on different ground acts on absolute displacements). After the
// record vg keeps its final value and ug grows linearly with it (no baseline correction here:
// the [motion] keys decide that).
//
// The integrals start from rest one sample before the record, at t = -dt, with the acceleration
// rising linearly from 0 there to the first sample a_0: vg(0) = a_0 dt / 2, ug(0) = a_0 dt^2 / 6.
// A record delayed by k samples (ground/wave_passage.hpp: k leading zeros) rises the same way
// from its last leading zero, so its vg and ug are the undelayed ones shifted by k dt exactly,
// and two buildings on delayed copies of one record move apart only by the delay. (From rest at
// t = 0 instead, a generated motion, which starts at a_0 of up to 0.2 g, would leave the delayed
// copy a velocity a_0 dt / 2 faster for the rest of the run: 0.1 m apart after 10 s.) The
// solvers' ground acceleration is GroundMotion::at's, 0 before t = 0, so this moves nothing of a
// building relative to its own ground. Kernel only: no files, no printing.
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
  /// with v_i, u_i the exact integrals at the samples (motion_processing.hpp, integrate(), from
  /// rest at t = -dt); 0 before t = -dt.
  double vel(double t) const;
  double disp(double t) const;
  /// Both at once [m/s], [m].
  void kinematics(double t, double& v, double& u) const;

 private:
  GroundMotion motion_;
  std::vector<double> v_, u_;  // at the samples [m/s], [m]
};

}  // namespace pound

#pragma once
// A uniformly sampled ground-acceleration record, the input of every simulation.
#include <string>
#include <vector>

namespace pound {

struct GroundMotion {
  std::string name;           ///< file name or generator description, for reports
  double dt = 0.0;            ///< sample spacing [s]
  std::vector<double> accel;  ///< ground acceleration at t = i*dt, i = 0..n-1 [m/s^2]

  /// Time of the last sample [s].
  double duration() const { return accel.empty() ? 0.0 : dt * double(accel.size() - 1); }
  /// Acceleration at time t [m/s^2]: linear between samples (the piecewise-linear excitation
  /// the exact recurrences assume), 0 before t = 0 and after the last sample.
  double at(double t) const;
  /// Peak absolute acceleration [m/s^2].
  double pga() const;
};

/// Standard gravity [m/s^2], used to convert records given in g.
inline constexpr double kGravity = 9.80665;

}  // namespace pound

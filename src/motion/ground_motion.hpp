#pragma once
// A uniformly sampled ground-acceleration record, the input of every simulation.
#include <cstddef>
#include <string>
#include <vector>

#include "core/constants.hpp"

namespace pound {

struct GroundMotion {
  std::string name;           ///< file name or generator description, for reports
  double dt = 0.0;            ///< sample spacing [s]
  std::vector<double> accel;  ///< ground acceleration at t = i*dt, i = 0..n-1 [m/s^2]

  /// Time of the last sample [s].
  double duration() const { return accel.empty() ? 0.0 : dt * double(accel.size() - 1); }
  /// Acceleration at time t [m/s^2]: linear between samples (the piecewise-linear excitation
  /// the exact recurrences assume), 0 before t = 0 and after the last sample.
  /// Inline: the solvers call it at every stage.
  double at(double t) const {
    if (accel.empty() || t < 0.0) return 0.0;
    const double s = t / dt;
    const auto i = static_cast<std::size_t>(s);
    if (i + 1 >= accel.size()) return i + 1 == accel.size() && s == double(i) ? accel[i] : 0.0;
    const double f = s - double(i);
    return accel[i] + f * (accel[i + 1] - accel[i]);
  }
  /// Peak absolute acceleration [m/s^2].
  double pga() const;
};

}  // namespace pound

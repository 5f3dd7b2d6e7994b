#pragma once
// Ground motions the tests share.
#include <cmath>

#include "motion/ground_motion.hpp"

namespace pound::test {

/// a(t) = amplitude sin(2 pi f t) [m/s^2] at t = i dt, i = 0 .. samples - 1.
inline GroundMotion sine_motion(double amplitude, double frequency_hz, double dt, int samples) {
  GroundMotion g;
  g.name = "sine";
  g.dt = dt;
  for (int i = 0; i < samples; ++i)
    g.accel.push_back(amplitude * std::sin(2.0 * M_PI * frequency_hz * i * dt));
  return g;
}

/// One cycle of a 0.5 s sine of 4 m/s^2, then rest until 3 s, sampled at 5 ms: the pulse of the
/// slab-to-column tests (issue 36).
inline GroundMotion sine_pulse() {
  GroundMotion g;
  g.name = "pulse";
  g.dt = 0.005;
  for (int i = 0; i <= 600; ++i) {
    const double t = i * g.dt;
    g.accel.push_back(t < 0.5 ? 4.0 * std::sin(2 * M_PI * t / 0.5) : 0.0);
  }
  return g;
}

}  // namespace pound::test

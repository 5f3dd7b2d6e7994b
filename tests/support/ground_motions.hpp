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

}  // namespace pound::test

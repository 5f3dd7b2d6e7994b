#pragma once
// Inputs of the tests' own reference integrations (written from physics.md, not from the
// library): the first samples of the El Centro record, and the exact Hunt-Crossley factor.
#include <cmath>
#include <cstddef>
#include <string>

#include "motion/motion_reader.hpp"
#include "simulation/simulate_row.hpp"

#ifndef POUND_SOURCE_DIR
#error "reference_inputs.hpp needs POUND_SOURCE_DIR, the source tree's path"
#endif

namespace pound::test {

/// The first `samples` samples of motions/elcentro-1940-ns.dat (0.02 s) [m/s^2].
inline GroundMotion elcentro_first(int samples) {
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  GroundMotion m = read_motion(spec);
  m.accel.resize(static_cast<std::size_t>(samples));
  return m;
}

/// Exact Hunt-Crossley factor a(e) (Th. 4.20): (1 + e) a = ln((1 + a) / (1 - e a)),
/// 0 < a < 1/e, by bisection (the difference is negative just above 0 and grows to +inf at
/// 1/e).
inline double hunt_crossley_a(double e) {
  auto g = [e](double a) { return std::log((1 + a) / (1 - e * a)) - (1 + e) * a; };
  double lo = 1e-6 / e, hi = (1 - 1e-15) / e;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// The chapter 8 row under the first 6 s of El Centro NS (elcentro_first(301)) and 1 s of free
/// vibration, hc-linear contacts (k = 50 x 8.4e7 N/m, e = 0.6): the foundation tests' run.
inline RowSimulation elcentro_hc_run(const BuildingRow& row, const IntegratorSettings& integ,
                                     bool energy) {
  ContactSpec c;
  c.model = "hc-linear";
  c.params.k = 50 * 8.4e7;
  c.params.e = 0.6;
  RowSimulationOptions o;
  o.extra_time = 1.0;
  o.track_energy = energy;
  return simulate_row(row, elcentro_first(301), c, integ, o);
}

}  // namespace pound::test

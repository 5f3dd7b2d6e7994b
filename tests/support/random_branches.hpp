#pragma once
// Storey states on random branches of their laws (the solver tests of the forces and the exact
// steps on flexible foundations).
#include <cmath>
#include <random>
#include <vector>

#include "structure/building_row.hpp"

namespace pound::test {

/// Each storey of `a` (the foundation's springs left at rest) driven from rest through four
/// random drifts of up to 4 yield drifts (0.01 m where it does not yield), so that the piecewise
/// laws stand on random branches (loading, unloading, capped, ...).
inline std::vector<StoreyState> random_storey_states(const AssembledRow& a, std::mt19937& rng) {
  std::vector<StoreyState> states(a.dofs());
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < a.dofs(); ++i) {
    const RowStorey& st = a.storeys[i];
    if (st.foundation) continue;
    const double uy = std::isfinite(st.p.Fy) ? st.p.Fy / st.p.k0 : 0.01;
    double d = 0.0;
    for (int k = 0; k < 4; ++k) {
      const double d1 = 4.0 * uy * unit(rng);
      StoreyState next;
      st.law->advance(st.p, states[i], d, d1, next);
      states[i] = next;
      d = d1;
    }
  }
  return states;
}

/// Random floor and base displacements u [m, rad] and velocities v [m/s, rad/s] of a row on
/// flexible foundations: within 0.05 m and 0.5 m/s, the bases' rotations (a.rot) within 1e-4
/// rad and 1e-3 rad/s; u(i) then v(i) drawn per DOF.
inline void random_motion(const AssembledRow& a, std::mt19937& rng, double* u, double* v) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int i = 0; i < a.dofs(); ++i) {
    const bool rot = i == a.rot[0] || i == a.rot[1];
    u[i] = (rot ? 1e-4 : 0.05) * unit(rng);
    v[i] = (rot ? 1e-3 : 0.5) * unit(rng);
  }
}

}  // namespace pound::test

#pragma once
// Two simulations of one row that must agree to the integrators' accuracy (the exact steps
// against Dormand-Prince throughout, both at rtol 1e-10; docs/integration.md, "Exact steps"):
// the same events and impacts; peak displacements, drifts and the free run's approach within
// 1e-6 (relative), residual drifts and hysteretic energies within 1e-5; accelerations and
// contact forces, which both sample at their steps' ends (the two paths end their steps at
// different instants), within 1e-2 and 2e-3. Returns the impacts of `e` (GoogleTest checks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "simulation/simulate_row.hpp"

namespace pound::test {

/// The largest relative difference of the floors' peak displacements and drifts, with and
/// without pounding, of x against y.
inline double worst_peaks(const RowSimulation& x, const RowSimulation& y) {
  double w = 0.0;
  for (std::size_t i = 0; i < x.floors.size(); ++i) {
    const FloorResponse &a = x.floors[i], &b = y.floors[i];
    for (auto [p, q] : {std::pair{a.disp_pounding, b.disp_pounding},
                        {a.disp_free, b.disp_free},
                        {a.peak_drift_ratio_pounding, b.peak_drift_ratio_pounding},
                        {a.peak_drift_ratio_free, b.peak_drift_ratio_free}})
      w = std::max(w, std::fabs(p - q) / std::fabs(q));
  }
  return w;
}

inline int expect_same_run(const RowSimulation& e, const RowSimulation& d,
                           const std::string& what) {
  EXPECT_EQ(e.pounding.events, d.pounding.events) << what;
  EXPECT_EQ(e.free.events, d.free.events) << what;
  auto near = [&](double x, double y, double rel, const char* q) {
    EXPECT_NEAR(x, y, rel * std::fabs(y) + 1e-12) << what << " " << q;
  };
  for (std::size_t i = 0; i < e.floors.size(); ++i) {
    near(e.floors[i].disp_pounding, d.floors[i].disp_pounding, 1e-6, "disp");
    near(e.floors[i].disp_free, d.floors[i].disp_free, 1e-6, "disp free");
    near(e.floors[i].peak_drift_ratio_pounding, d.floors[i].peak_drift_ratio_pounding, 1e-6,
         "drift");
    near(e.floors[i].residual_drift_ratio_free, d.floors[i].residual_drift_ratio_free, 1e-5,
         "residual");
    near(e.floors[i].hysteretic_energy_pounding, d.floors[i].hysteretic_energy_pounding, 1e-5,
         "hysteretic");
    near(e.floors[i].accel_pounding, d.floors[i].accel_pounding, 1e-2, "accel");
    near(e.floors[i].accel_free, d.floors[i].accel_free, 1e-2, "accel free");
  }
  int impacts = 0;
  for (std::size_t k = 0; k < e.sites.size(); ++k) {
    EXPECT_EQ(e.sites[k].impacts, d.sites[k].impacts) << what;
    impacts += e.sites[k].impacts;
    near(e.sites[k].peak_force, d.sites[k].peak_force, 2e-3, "force");
    near(e.sites[k].approach_free, d.sites[k].approach_free, 1e-6, "approach");
  }
  return impacts;
}

}  // namespace pound::test

// The error test of a row on flexible bases (issue 38; src/solver/row_run.cpp,
// RowRun::error_norm_on_soil, IntegratorSettings::base_error_by_floors; docs/integration.md "Step
// choice"): each base DOF's error measured by what it does to its building's floors (Hairer,
// Norsett & Wanner I, II.4: the entries' scales), the Dormand-Prince steps inside the bases'
// dashpot bound. Against fine references (rtol 1e-11): the error falls with the tolerance, the
// base entries no longer hold the steps, a fast dashpot stays stable, a massless raft keeps its
// accuracy, fixed bases keep their norm bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "../support/buildings.hpp"
#include "../support/reference_inputs.hpp"
#include "../support/same_run.hpp"
#include "simulation/simulate_row.hpp"
#include "structure/building.hpp"

namespace pound {
namespace {

// The chapter 8 pair on rafts of 40 t and 5e5 kg m^2 on springs (sway 9.56e8 N/m, rocking
// 1.02e11 N m/rad), the dashpots' own rates C / m = C_theta / I = rate [1/s] (the soft-soil
// study's Gazetas footings: 310-980 1/s); m0 = 0: a massless raft.
BuildingRow raft_pair(const std::string& law, double rate, double m0 = 4e4, double i0 = 5e5) {
  BuildingRow row = test::chapter8_pair(0.01);
  for (int b = 0; b < 2; ++b) {
    Building& bd = row.buildings[b];
    bd.hysteresis = law;
    if (law != "elastic") bd.yield_shears.assign(bd.floors(), b == 0 ? 4.5e5 : 1.7e5);
    bd.foundation = test::springs_foundation(9.56e8, 1.02e11, rate * 4e4, rate * 5e5, m0, i0);
  }
  return row;
}

long steps(const RowSimulation& s) {
  return s.free.steps + s.free.rejected + s.pounding.steps + s.pounding.rejected;
}

IntegratorSettings tolerance(double rtol) {
  IntegratorSettings s;
  s.rtol = rtol;
  s.atol = rtol * 1e-2;
  return s;
}

// Tolerance proportionality (Hairer, Norsett & Wanner I, II.4): with Dormand-Prince throughout
// (no exact steps) on rafts at 1000 1/s, the peaks' error against a fine reference falls with
// rtol, by more than 10 over each two decades (measured at rtol 1e-6, 1e-8, 1e-10: elastic 2.8e-6,
// 1.9e-8, 6.1e-10; imk 2.5e-6, 3.7e-8, 4.9e-10), and is within the integration tolerance (1e-6)
// at the default.
TEST(RowRunOnSoil, ErrorFallsWithTheTolerance) {
  for (const std::string law : {"elastic", "imk"}) {
    SCOPED_TRACE(law);
    const BuildingRow raft = raft_pair(law, 1e3);
    IntegratorSettings ref = tolerance(1e-11);
    ref.exact_free = false;
    const RowSimulation r = test::elcentro_hc_run(raft, ref, false);
    double err[3];
    for (int k = 0; k < 3; ++k) {
      IntegratorSettings s = tolerance(k == 0 ? 1e-6 : k == 1 ? 1e-8 : 1e-10);
      s.exact_free = false;
      err[k] = test::worst_peaks(test::elcentro_hc_run(raft, s, false), r);
    }
    std::printf("[ on soil  ] %s: peaks' error at rtol 1e-6, 1e-8, 1e-10: %.2e %.2e %.2e\n",
                law.c_str(), err[0], err[1], err[2]);
    EXPECT_LT(err[1], 1e-6);
    EXPECT_GT(err[0], 10 * err[1]);
    EXPECT_GT(err[1], 10 * err[2]);
  }
}

// The base entries no longer hold the steps: on rafts at 1000 1/s (IMK storeys, their
// Dormand-Prince stretches) the run takes fewer than 0.85 times the steps of each entry against
// its own scale (base_error_by_floors = false, the norm before; measured 0.79), and its peaks stay
// within 1e-6 of the fine reference.
TEST(RowRunOnSoil, BaseEntriesNoLongerHoldTheSteps) {
  const BuildingRow raft = raft_pair("imk", 1e3);
  IntegratorSettings now, before;
  before.base_error_by_floors = false;
  const RowSimulation r = test::elcentro_hc_run(raft, tolerance(1e-11), false);
  const RowSimulation a = test::elcentro_hc_run(raft, now, false);
  const RowSimulation b = test::elcentro_hc_run(raft, before, false);
  std::printf(
      "[ on soil  ] steps %ld against %ld (own scales); peaks within %.2e of the reference "
      "(own scales %.2e)\n",
      steps(a), steps(b), test::worst_peaks(a, r), test::worst_peaks(b, r));
  EXPECT_LT(steps(a), 0.85 * steps(b));
  EXPECT_LT(test::worst_peaks(a, r), 1e-6);
}

// A dashpot far beyond the automatic step (C / m = 1e5 1/s, h_max lambda = 360): the steps stay
// inside Dormand-Prince's stability bound (RowRun::h_explicit_), so the run agrees with the fine
// reference (measured 1.6e-14; without the bound, the base entries weighed by their effect on the
// floors let the steps out to it: 3.7e-4); a massless raft (its velocities follow from the
// displacements and are not tested) too (1.7e-7; 9.4e-8 with each entry against its own scale).
TEST(RowRunOnSoil, FastDashpotAndMasslessRaftAgreeWithTheReference) {
  for (const bool massless : {false, true}) {
    SCOPED_TRACE(massless ? "massless" : "fast dashpot");
    const BuildingRow raft = massless ? raft_pair("imk", 1e3, 0.0, 0.0) : raft_pair("imk", 1e5);
    const RowSimulation r = test::elcentro_hc_run(raft, tolerance(1e-11), false);
    const RowSimulation a = test::elcentro_hc_run(raft, IntegratorSettings{}, false);
    IntegratorSettings before;
    before.base_error_by_floors = false;
    const RowSimulation b = test::elcentro_hc_run(raft, before, false);
    std::printf(
        "[ on soil  ] %s: peaks within %.2e of the reference in %ld steps (own scales: %.2e in "
        "%ld)\n",
        massless ? "massless raft" : "raft at 1e5 1/s", test::worst_peaks(a, r), steps(a),
        test::worst_peaks(b, r), steps(b));
    EXPECT_LT(test::worst_peaks(a, r), 1e-6);
  }
}

// Rows on fixed bases take the same norm either way: the same steps, the same peaks to the bit.
TEST(RowRunOnSoil, FixedBasesKeepTheirNorm) {
  for (const std::string law : {"elastic", "imk"}) {
    BuildingRow row = raft_pair(law, 1e3);
    for (Building& b : row.buildings) b.foundation = Foundation{};
    IntegratorSettings off;
    off.base_error_by_floors = false;
    const RowSimulation a = test::elcentro_hc_run(row, IntegratorSettings{}, false);
    const RowSimulation b = test::elcentro_hc_run(row, off, false);
    EXPECT_EQ(steps(a), steps(b));
    EXPECT_EQ(test::worst_peaks(a, b), 0.0);
  }
}

// A raft too light for its dashpots (issue 38, structure/building_on_base.hpp
// drop_light_base_masses): where its own root C / m times the buildings' shortest period T
// reaches 1e4 it is taken as massless, and the run steps at the buildings' rates, not at
// 3.3 / (C / m). The response is continuous across that bound: rafts with C / m = 2e4 / T (taken
// massless) and 5e3 / T (integrated, its inertial root followed by Dormand-Prince steps) differ by
// the raft's lag, O(2 pi / (rate T)): measured 2.0e-4; the massless one in a quarter of the
// steps (5,112 against 20,732; at 2e4 / T integrated, its steps would be four times the
// latter's).
TEST(RowRunOnSoil, ARaftTooLightForItsDashpotsIsTakenMassless) {
  BuildingRow row = raft_pair("elastic", 1e3);
  double t = 1e9;  // the buildings' shortest fixed-base period [s]
  for (const Building& b : row.buildings) t = std::min(t, assemble(b).periods.minCoeff());
  auto with_rate = [&](double rate_t) {  // rafts whose C / m and C_theta / I are rate_t / t
    BuildingRow r = row;
    for (Building& b : r.buildings) {
      b.foundation.foundation_mass = b.foundation.sway_damping * t / rate_t;
      b.foundation.foundation_inertia = b.foundation.rocking_damping * t / rate_t;
    }
    return r;
  };
  const RowSimulation light = test::elcentro_hc_run(with_rate(2e4), IntegratorSettings{}, false);
  const RowSimulation heavy = test::elcentro_hc_run(with_rate(5e3), IntegratorSettings{}, false);
  std::printf(
      "[ on soil  ] rafts at 2e4 / T (massless) and 5e3 / T: peaks within %.2e; steps %ld "
      "and %ld\n",
      test::worst_peaks(light, heavy), steps(light), steps(heavy));
  EXPECT_LT(test::worst_peaks(light, heavy), 2e-3);
  EXPECT_LT(3 * steps(light), steps(heavy));
}

}  // namespace
}  // namespace pound

// The imk law behind the storey-law interface in both solvers, unchanged: the chapter 8 pair
// with imk storeys (studies/ch8-yielding.ini) through the lumped adaptive solver (hc-linear) and
// the damped Sears model's Newmark path. The energy balance closes, the storeys deteriorate and
// dissipate, and the free runs of the two solvers (the same problem) agree.
#include <gtest/gtest.h>

#include <cmath>

#include "../support/studies.hpp"
#include "simulation/simulate_row.hpp"

namespace pound {
namespace {

const std::vector<std::string> kImk = {
    "--building1.hysteresis", "imk", "--building2.hysteresis",  "imk",
    "--motion.duration",      "10",  "--simulation.extra_time", "2"};

TEST(ImkInTheSolvers, EnergyBalanceClosesAndTheTwoSolversAgreeOnTheFreeRun) {
  const test::StudyRun s = test::read_study("ch8-yielding.ini", kImk);
  RowSimulationOptions o;
  o.extra_time = 2.0;
  o.track_energy = true;
  const sears::SearsRowSimulation sears = sears::simulate_sears_row(s.row, s.motion, s.model, o);
  ContactSpec contact;
  contact.model = "hc-linear";
  contact.params.e = 0.65;
  contact.params.k = 30 * 8.4e7;
  const RowSimulation lumped = simulate_row(s.row, s.motion, contact, IntegratorSettings{}, o);
  for (const RowResult* r : {&lumped.pounding, &lumped.free})
    EXPECT_LT(std::fabs(r->energy.residual()), 1e-7 * r->energy.input);
  for (const RowResult* r : {&sears.base.pounding, &sears.base.free})
    EXPECT_LT(std::fabs(r->energy.residual()), 1e-5 * r->energy.input);
  EXPECT_GT(lumped.pounding.events, 100);  // reversals, zero crossings, targets
  // The free runs are the same problem in both solvers.
  double hysteretic = 0.0;
  for (std::size_t i = 0; i < lumped.floors.size(); ++i) {
    const FloorResponse &a = lumped.floors[i], &b = sears.base.floors[i];
    EXPECT_NEAR(a.peak_drift_ratio_free, b.peak_drift_ratio_free,
                1e-4 * a.peak_drift_ratio_free + 1e-8)
        << i;
    EXPECT_NEAR(a.hysteretic_energy_free, b.hysteretic_energy_free,
                1e-3 * a.hysteretic_energy_free + 1.0)
        << i;
    hysteretic += a.hysteretic_energy_free;
  }
  EXPECT_GT(hysteretic, 0.3 * lumped.free.energy.input);  // they do yield and dissipate
}

}  // namespace
}  // namespace pound

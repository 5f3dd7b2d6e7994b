// The free-run approach (SiteResponse::approach_free): before its first contact a pounding run
// is the free run, so a pounding run with the gap just above a level's approach has no contact
// there and one just below it has. Checked on the chapter 8 pair (elastic and yielding) and an
// SDOF pair under El Centro, for two lumped contact laws.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "../support/buildings.hpp"
#include "motion/motion_processing.hpp"
#include "motion/motion_reader.hpp"
#include "simulation/simulate_row.hpp"

namespace pound {
namespace {

GroundMotion elcentro(double seconds, double factor) {
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  return scale(truncate(read_motion(spec), seconds), factor);
}

ContactSpec contact_of(const std::string& model, double k, double e) {
  ContactSpec c;
  c.model = model;
  c.params.k = k;
  c.params.e = e;
  return c;
}

BuildingRow with_gap(BuildingRow row, double gap) {
  for (auto& g : row.gaps) std::fill(g.begin(), g.end(), gap);
  return row;
}

// Relative tolerance of the bracket: the approach is the peak of the cubic Hermite
// interpolant of the free run's steps, and a contact of the pounding run (the same steps until
// then) is confirmed on a step re-taken to the interpolant's crossing, so the two agree to the
// interpolant's error between steps: contact begins at gaps 0.3e-7 to 2.4e-6 of the approach
// below it on the chapter 8 pair, elastic and yielding (measured). 1e-5 of a 1-8 cm approach
// is 0.1-0.8 um.
constexpr double kBracket = 1e-5;

void expect_bracket(const BuildingRow& row0, const GroundMotion& g, const ContactSpec& contact,
                    const std::string& what) {
  RowSimulationOptions opt;
  opt.record_history = true;
  const RowSimulation base = simulate_row(with_gap(row0, 0.5), g, contact, {}, opt);
  for (const auto& s : base.sites) {
    const double a = s.approach_free;
    ASSERT_TRUE(std::isfinite(a) && a > 0.0) << what;
    EXPECT_EQ(s.impacts, 0) << what << ": a 0.5 m gap is never closed";
    // The approach is the peak of u_L - u_R: at least its largest sampled value, and above it
    // by no more than the interpolant adds between steps.
    const auto& h = base.free.history;
    const AssembledRow ar = assemble(row0);
    double sampled = -1e9;
    for (const auto& u : h.u) {
      const auto& site = ar.sites[std::size_t(&s - &base.sites[0])];
      sampled = std::max(sampled, u(site.dof_left) - u(site.dof_right));
    }
    EXPECT_GE(a, sampled) << what;
    EXPECT_LE(a, sampled * (1 + 1e-3)) << what;
  }
  // Per level: a gap just above that level's approach (and above the others' too) closes no
  // contact anywhere; just below it, the level touches.
  for (std::size_t k = 0; k < base.sites.size(); ++k) {
    const double a = base.sites[k].approach_free;
    double top = 0.0;
    for (const auto& s : base.sites) top = std::max(top, s.approach_free);
    const RowSimulation above = simulate_row(with_gap(row0, top * (1 + kBracket)), g, contact, {});
    for (const auto& s : above.sites)
      EXPECT_EQ(s.impacts, 0) << what << ": gap above every approach, level " << s.floor;
    BuildingRow below = with_gap(row0, 0.5);
    below.gaps[std::size_t(base.sites[k].pair)][std::size_t(base.sites[k].floor - 1)] =
        a * (1 - kBracket);
    const RowSimulation hit = simulate_row(below, g, contact, {});
    EXPECT_GT(hit.sites[k].impacts, 0)
        << what << ": gap just below the approach of level " << base.sites[k].floor;
    // The free run does not depend on the gap.
    EXPECT_EQ(hit.sites[k].approach_free, a) << what;
  }
}

TEST(ApproachFree, ABracketingGapClosesOrNotForAnSdofPair) {
  BuildingRow row;
  row.buildings = {test::uniform_building(1, 1e4, 4e6, 0.05, DampingKind::modal),
                   test::uniform_building(1, 1e4, 1.5e6, 0.05, DampingKind::modal)};
  row.gaps = {{0.0}};
  const GroundMotion g = elcentro(8.0, 1.0);
  for (const char* model : {"hc-linear", "lve"})
    expect_bracket(row, g, contact_of(model, 1e9, 0.6), std::string("sdof ") + model);
}

TEST(ApproachFree, ABracketingGapClosesOrNotAtEachLevelOfTheChapter8Pair) {
  const GroundMotion g = elcentro(6.0, 1.5);
  expect_bracket(test::chapter8_pair(0.0), g, contact_of("hc-linear", 6.3e8, 0.65),
                 "chapter 8 elastic");
  // Yielding storeys (bilinear): the storey switches are events of both runs alike.
  BuildingRow y = test::chapter8_pair(0.0);
  for (auto& b : y.buildings) {
    b.hysteresis = "bilinear";
    b.yield_shears.assign(b.masses.size(), 0.25 * 9.81 * b.masses[0] * double(b.masses.size()));
  }
  expect_bracket(y, g, contact_of("hc-linear", 6.3e8, 0.65), "chapter 8 yielding");
}

}  // namespace
}  // namespace pound

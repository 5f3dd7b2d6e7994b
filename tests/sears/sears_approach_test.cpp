// The free-run approach of the damped Sears model (SiteResult::peak_approach): without contacts
// the slabs' axial modes are never loaded, so the contact faces move with the floors and the
// approach is that of the floors; a pounding run with the gap above it has no contact phase,
// one with the gap below it has.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../support/studies.hpp"
#include "sears/sears_simulation.hpp"
#include "structure/building_row.hpp"

namespace pound::sears {
namespace {

test::StudyRun chapter8(double gap) {
  test::StudyRun s = test::read_study("ch8-five-three.ini", {"--sears.modes", "40"});
  for (auto& g : s.row.gaps) std::fill(g.begin(), g.end(), gap);
  return s;
}

TEST(SearsApproach, WithoutContactsTheFacesMoveWithTheFloors) {
  const test::StudyRun s = chapter8(0.0);
  SearsRowProblem p;
  p.row = &s.row;
  const RowGround p_ground =
      RowGround::uniform(s.motion, static_cast<int>(p.row->buildings.size()));
  p.ground = &p_ground;
  p.t_end = s.motion.duration();
  p.contacts = false;
  p.record_history = true;
  const SearsRowResult r = solve_sears_row(p, s.model);
  const AssembledRow a = assemble(s.row);
  // Face and slab-centre accelerations are the floor's: the modes stay at rest.
  ASSERT_EQ(r.slabs.size(), 6u);
  for (const auto& sl : r.slabs) {
    const int dof = a.offset[std::size_t(sl.building)] + sl.floor - 1;
    EXPECT_EQ(sl.face_accel, r.row.peak_abs_accel(dof)) << "building " << sl.building;
    EXPECT_EQ(sl.centre_accel, r.row.peak_abs_accel(dof)) << "building " << sl.building;
  }
  // The approach is the peak of u_L - u_R of the floors: at least its largest value at the
  // steps' ends, above it by what the cubic between the ends adds (the coarse steps are at most
  // 1/200 of the shortest period: a sampled sine peak is low by at most (pi/200)^2 / 2).
  for (std::size_t k = 0; k < a.sites.size(); ++k) {
    double sampled = -1e9;
    for (const auto& u : r.row.history.u)
      sampled = std::max(sampled, u(a.sites[k].dof_left) - u(a.sites[k].dof_right));
    const double peak = r.row.sites[k].peak_approach;
    EXPECT_GE(peak, sampled) << "site " << k;
    EXPECT_LE(peak, sampled + 1.3e-4 * std::abs(sampled)) << "site " << k;
    EXPECT_GT(peak, 0.0);
  }
}

TEST(SearsApproach, ABracketingGapClosesOrNot) {
  // The free run (coarse steps throughout) and the pounding run (fine steps wherever a bound
  // cannot exclude a contact) are both Newmark average-acceleration integrations of the same
  // floors, the same coarse steps until the faces come close. Contact begins at gaps 1.1e-7 to
  // 2.2e-7 of the approach below it here (measured at 0.5, 1 and 2 x El Centro); the bracket
  // is +-1e-4 of the approach (the campaign identity test allows 1e-3: there the fine steps
  // near an earlier, lower peak can move the trajectory before the largest one).
  const test::StudyRun s0 = chapter8(0.0);
  const SearsRowSimulation base = simulate_sears_row(s0.row, s0.motion, s0.model);
  for (std::size_t k = 0; k < base.base.sites.size(); ++k) {
    const double a = base.base.sites[k].approach_free;
    ASSERT_GT(a, 0.0);
    test::StudyRun above = chapter8(0.0);
    double top = 0.0;
    for (const auto& site : base.base.sites) top = std::max(top, site.approach_free);
    for (auto& g : above.row.gaps) std::fill(g.begin(), g.end(), top * (1 + 1e-4));
    const SearsRowSimulation no = simulate_sears_row(above.row, above.motion, above.model);
    for (const auto& site : no.base.sites) EXPECT_EQ(site.impacts, 0) << "level " << site.floor;
    test::StudyRun below = chapter8(10.0);
    below.row.gaps[0][k] = a * (1 - 1e-4);
    const SearsRowSimulation hit = simulate_sears_row(below.row, below.motion, below.model);
    EXPECT_GT(hit.base.sites[k].impacts, 0) << "level " << k + 1;
    EXPECT_NEAR(hit.base.sites[k].approach_free, a, 1e-12 * a) << "the free run is the gap's";
  }
}

}  // namespace
}  // namespace pound::sears

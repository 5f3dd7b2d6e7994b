// The ground as a row's floors and contact sites meet it (ground/floor_ground.hpp, issue 28):
// the relative ground motion of every site at once (relative_all, the damped Sears path's
// ground_at, issue 38) against each site's relative() and against the two traces' closed-form
// kinematics, on a row of three buildings over two and three channels (sites that share a
// channel, sites that do not), before, during and after the records.
#include "ground/floor_ground.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../support/buildings.hpp"
#include "ground/row_ground.hpp"

namespace pound {
namespace {

GroundMotion record(double amplitude, double frequency, int n, double dt) {
  GroundMotion m;
  m.name = "sine";
  m.dt = dt;
  for (int i = 0; i < n; ++i) m.accel.push_back(amplitude * std::sin(frequency * dt * i));
  return m;
}

// Three buildings (3, 2 and 3 storeys), aligned floors: pair 1 meets at floors 1-2, pair 2 at
// floors 1-2: four slab sites.
BuildingRow three_in_a_row() {
  BuildingRow row;
  row.buildings = {test::uniform_building(3, 4e4, 6e7), test::uniform_building(2, 3e4, 5e7),
                   test::uniform_building(3, 4e4, 6e7)};
  row.gaps = {{0.01, 0.01}, {0.02, 0.02}};
  return row;
}

// relative_all gives every site relative()'s numbers, bit for bit, and those are the traces'
// own kinematics differenced (0 where a site's buildings share a channel).
void check_row(const std::vector<GroundMotion>& motions, int channels) {
  const AssembledRow a = assemble(three_in_a_row());
  const RowGround ground = RowGround::per_building(motions);
  ASSERT_EQ(ground.channels(), channels);
  FloorGround fg(a, &ground);
  const std::size_t ns = a.sites.size();
  ASSERT_EQ(ns, 4u);
  std::vector<double> du(ns), dv(ns);
  int differing = 0;
  for (double t : {-0.05, -0.004, 0.0, 0.0137, 0.5, 1.23456, 1.99, 2.5, 7.0}) {
    fg.relative_all(t, du.data(), dv.data());
    for (std::size_t s = 0; s < ns; ++s) {
      double u1, v1;
      fg.relative(int(s), t, u1, v1);
      EXPECT_EQ(du[s], u1) << "site " << s << " t " << t;
      EXPECT_EQ(dv[s], v1) << "site " << s << " t " << t;
      const auto [l, r] = fg.site_channels(int(s));
      double vl, ul, vr, ur;
      ground.trace(l).kinematics(t, vl, ul);
      ground.trace(r).kinematics(t, vr, ur);
      EXPECT_EQ(du[s], l == r ? 0.0 : ul - ur);
      EXPECT_EQ(dv[s], l == r ? 0.0 : vl - vr);
      if (l != r && t > 0.0) {
        ++differing;
        EXPECT_NE(du[s], 0.0);
      }
    }
  }
  EXPECT_GT(differing, 0);
}

TEST(FloorGround, RelativeAllIsEachSitesRelativeOnTwoChannels) {
  // Buildings 1 and 3 on one motion, building 2 on another: every site differs, two channels.
  const GroundMotion a = record(2.0, 9.0, 101, 0.02), b = record(1.5, 7.0, 101, 0.02);
  check_row({a, b, a}, 2);
}

TEST(FloorGround, RelativeAllIsEachSitesRelativeOnThreeChannels) {
  const GroundMotion a = record(2.0, 9.0, 101, 0.02), b = record(1.5, 7.0, 101, 0.02),
                     c = record(1.0, 5.0, 81, 0.02);
  check_row({a, b, c}, 3);
}

TEST(FloorGround, RelativeAllIsZeroWhereBuildingsShareTheGround) {
  // Buildings 1 and 2 on one motion: pair 1's sites share a channel, pair 2's differ.
  const GroundMotion a = record(2.0, 9.0, 101, 0.02), c = record(1.0, 5.0, 101, 0.02);
  check_row({a, a, c}, 2);
  const AssembledRow row = assemble(three_in_a_row());
  const RowGround ground = RowGround::per_building({a, a, c});
  FloorGround fg(row, &ground);
  std::vector<double> du(4, 1.0), dv(4, 1.0);
  fg.relative_all(1.0, du.data(), dv.data());
  EXPECT_EQ(du[0], 0.0);
  EXPECT_EQ(dv[1], 0.0);
  EXPECT_NE(du[2], 0.0);
}

// The ground is evaluated once per instant (issue 38: the solvers ask again at the same t):
// asked at the same t again, after other instants and in between, every channel's acceleration
// and every site's relative motion are the traces' own numbers at that t, bit for bit.
TEST(FloorGround, AskedAgainAtTheSameTimeGivesThatTimesNumbers) {
  const GroundMotion a = record(2.0, 9.0, 101, 0.02), b = record(1.5, 7.0, 101, 0.02),
                     c = record(1.0, 5.0, 81, 0.02);
  const AssembledRow row = assemble(three_in_a_row());
  const RowGround ground = RowGround::per_building({a, b, c});
  FloorGround fg(row, &ground);
  std::vector<double> du(4), dv(4);
  for (double t : {0.5, 0.5, 1.23456, 0.5, 1.23456, 1.23456, -0.004, -0.004, 0.0, 2.5, 0.0}) {
    fg.relative_all(t, du.data(), dv.data());
    const double* agc = fg.channel_acc(t);
    for (int ch = 0; ch < 3; ++ch) EXPECT_EQ(agc[ch], ground.trace(ch).acc(t)) << "t " << t;
    const double* ag = fg.acc(t);
    for (int i = 0; i < row.dofs(); ++i) EXPECT_EQ(ag[i], agc[fg.channel(i)]);
    for (int s = 0; s < 4; ++s) {
      const auto [l, r] = fg.site_channels(s);
      double vl, ul, vr, ur;
      ground.trace(l).kinematics(t, vl, ul);
      ground.trace(r).kinematics(t, vr, ur);
      EXPECT_EQ(du[s], ul - ur) << "site " << s << " t " << t;
      EXPECT_EQ(dv[s], vl - vr) << "site " << s << " t " << t;
    }
  }
}

}  // namespace
}  // namespace pound

// drive(): one storey through a drift history by its law's incremental form, for every
// registered law (the loop behind `pound hysteresis`).
#include "hysteresis/drive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hysteresis/bilinear.hpp"
#include "hysteresis/registry.hpp"

namespace pound {
namespace {

TEST(Drive, EveryLawFollowsItsReturnMapFromRest) {
  StoreyParameters p;
  p.k0 = 2e7;  // N/m
  p.Fy = 2e5;  // N: uy = 0.01 m
  const std::vector<double> drifts = {0.005, 0.03, 0.03, -0.02, 0.0, -0.04, 0.01, 0.2, -0.1};
  for (const auto& info : storey_laws()) {
    const std::vector<double> v = drive(*info.law, p, drifts);
    ASSERT_EQ(v.size(), drifts.size()) << info.name;
    // The same loop written out: each drift from the one before along one monotone path.
    StoreyState s, t;
    double d0 = 0.0;
    for (std::size_t i = 0; i < drifts.size(); ++i) {
      EXPECT_EQ(v[i], info.law->advance(p, s, d0, drifts[i], t)) << info.name << " " << i;
      s = t;
      d0 = drifts[i];
    }
  }
  // Elastic: k0 d. Bilinear (b = 0.02): yield at 0.01 m, 0.03 m on the upper bounding line,
  // the repeated drift changes nothing, then unloading by k0.
  const auto e = drive(find_storey_law("elastic", ""), p, drifts);
  for (std::size_t i = 0; i < drifts.size(); ++i) EXPECT_EQ(e[i], p.k0 * drifts[i]);
  const auto b = drive(BilinearStorey(), p, {0.03, 0.03, 0.025});
  EXPECT_NEAR(b[0], p.Fy + 0.02 * p.k0 * 0.02, 1e-6);
  EXPECT_EQ(b[1], b[0]);
  EXPECT_NEAR(b[2], b[0] - p.k0 * 0.005, 1e-6);
}

TEST(Drive, AnEmptyHistoryGivesNoShears) {
  StoreyParameters p;
  p.k0 = 1e6;
  EXPECT_TRUE(drive(find_storey_law("elastic", ""), p, {}).empty());
}

}  // namespace
}  // namespace pound

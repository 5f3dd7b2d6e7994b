// Collapse as a limit state in the fragility analysis (issue 23) on a made-up campaign whose
// collapse counts are known: the collapse curves (multiple-stripe maximum likelihood, Baker
// 2015) recover the lognormal the collapses were drawn from, a collapsed building counts as
// exceeding every other limit, and where the study samples the contact model each model's
// curves are the fit of its own analyses.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "fragility/fragility_analysis.hpp"
#include "fragility/lognormal_fit.hpp"
#include "sampling/normal.hpp"

namespace pound {
namespace {

constexpr std::size_t kStripes = 6, kPerStripe = 400;
constexpr double kTheta = 2.0, kBeta = 0.4;  // the collapse fragility drawn from [m/s^2], [-]

// One building of one floor. On stripe l (IM 0.5 .. 16 m/s^2) the k-th of its samples collapses
// when its quantile (k + 0.5) / n lies below Phi(ln(im / theta) / beta): the collapsed share of
// each stripe is that probability to 1 / n. Without pounding, theta is 1.25 times larger. Every
// drift is 0.5 %. Samples alternate between two models, "a" and "b".
CampaignData campaign() {
  CampaignData c;
  c.path = "made-up.h5";
  c.samples = kStripes * kPerStripe;
  c.buildings = 1;
  c.building_names = {"only"};
  for (std::size_t l = 0; l < kStripes; ++l) c.levels.push_back(0.5 * double(1u << l));
  c.status.assign(c.samples, 0);
  c.scale.assign(c.samples, 1.0);
  FloorArray drift{c.samples, 1, 1, std::vector<double>(c.samples, 0.005)};
  std::vector<double> cp(c.samples), cf(c.samples);
  for (std::size_t s = 0; s < c.samples; ++s) {
    const std::size_t l = s % kStripes, k = s / kStripes;
    const double im = c.levels[l], q = (double(k) + 0.5) / double(kPerStripe);
    c.im.push_back(im);
    cp[s] = q < normal_cdf(std::log(im / kTheta) / kBeta) ? 1.0 : 0.0;
    cf[s] = q < normal_cdf(std::log(im / (1.25 * kTheta)) / kBeta) ? 1.0 : 0.0;
    c.model.push_back(k % 2 ? "b" : "a");
  }
  c.floor_arrays["peak_drift_ratio_pounding"] = drift;
  c.floor_arrays["peak_drift_ratio_free"] = drift;
  c.building_arrays["collapsed_pounding"] = cp;
  c.building_arrays["collapsed_free"] = cf;
  c.peak_force = FloorArray{c.samples, 0, 0, {}};
  return c;
}

const FragilityCurve& curve(const FragilityReport& r, Edp e, bool pounding,
                            const std::string& model = "") {
  for (const auto& c : r.curves)
    if (c.edp == e && c.pounding == pounding && c.model == model) return c;
  throw std::runtime_error("no such curve");
}

FragilitySettings settings() {
  FragilitySettings s;
  s.drift_limits = {0.008};
  s.bootstrap.replicates = 20;
  return s;
}

TEST(CollapseFragility, TheCollapseCurvesRecoverTheLognormalTheCollapsesCameFrom) {
  const FragilityReport r = analyse_fragility(campaign(), settings());
  ASSERT_TRUE(r.collapse);
  const FragilityCurve &p = curve(r, Edp::collapse, true), &f = curve(r, Edp::collapse, false);
  ASSERT_TRUE(p.fit.finite() && f.fit.finite());
  EXPECT_NEAR(p.fit.theta, kTheta, 0.01 * kTheta);
  EXPECT_NEAR(p.fit.beta, kBeta, 0.02 * kBeta);
  EXPECT_NEAR(f.fit.theta, 1.25 * kTheta, 0.01 * kTheta);
  // The shift of the median collapse capacity by pounding: 1 / 1.25, and collapse comes first.
  ASSERT_FALSE(r.shifts.empty());
  EXPECT_EQ(r.shifts.front().edp, Edp::collapse);
  EXPECT_NEAR(r.shifts.front().ratio, 0.8, 0.01);
}

TEST(CollapseFragility, ACollapsedBuildingExceedsEveryOtherLimit) {
  // With a drift limit no drift reaches (every drift is 0.5 %), only the collapses exceed it:
  // the drift curve is the collapse curve.
  FragilitySettings s = settings();
  s.drift_limits = {0.5};
  const FragilityReport r = analyse_fragility(campaign(), s);
  const FragilityCurve &d = curve(r, Edp::drift, true), &c = curve(r, Edp::collapse, true);
  ASSERT_EQ(d.observed.size(), c.observed.size());
  for (std::size_t k = 0; k < d.observed.size(); ++k) EXPECT_EQ(d.observed[k].z, c.observed[k].z);
  EXPECT_GT(d.observed.back().z, 0);
  EXPECT_DOUBLE_EQ(d.fit.theta, c.fit.theta);
}

TEST(CollapseFragility, EachSampledModelsCurvesAreTheFitOfItsOwnAnalyses) {
  const CampaignData all = campaign();
  const FragilityReport r = analyse_fragility(all, settings());
  ASSERT_EQ(r.models, (std::vector<std::string>{"a", "b"}));
  // Model "a" alone, as a campaign of its own samples.
  CampaignData a = all;
  std::vector<std::size_t> rows;
  for (std::size_t s = 0; s < all.samples; ++s)
    if (all.model[s] == "a") rows.push_back(s);
  a.samples = rows.size();
  a.im.clear();
  a.status.assign(rows.size(), 0);
  a.scale.assign(rows.size(), 1.0);
  a.model.clear();  // not sampled: pooled only
  for (auto& [name, v] : a.building_arrays) {
    std::vector<double> w;
    for (std::size_t s : rows) w.push_back(all.building_arrays.at(name)[s]);
    v = w;
  }
  for (auto& [name, fa] : a.floor_arrays)
    fa = FloorArray{rows.size(), 1, 1, std::vector<double>(rows.size(), 0.005)};
  for (std::size_t s : rows) a.im.push_back(all.im[s]);
  const FragilityReport ra = analyse_fragility(a, settings());
  EXPECT_TRUE(ra.models.empty());
  for (const bool pounding : {true, false}) {
    const FragilityCurve &x = curve(r, Edp::collapse, pounding, "a"),
                         &y = curve(ra, Edp::collapse, pounding);
    EXPECT_EQ(x.fit.theta, y.fit.theta);
    EXPECT_EQ(x.fit.beta, y.fit.beta);
    ASSERT_EQ(x.observed.size(), y.observed.size());
    for (std::size_t k = 0; k < x.observed.size(); ++k) EXPECT_EQ(x.observed[k].z, y.observed[k].z);
  }
  // Per model off: the pooled curves only, the same as with it.
  FragilitySettings s = settings();
  s.per_model = false;
  const FragilityReport rp = analyse_fragility(all, s);
  EXPECT_TRUE(rp.models.empty());
  EXPECT_EQ(curve(rp, Edp::collapse, true).fit.theta, curve(r, Edp::collapse, true).fit.theta);
}

// Two buildings in one pounding run, which stops at the first collapse. In every third sample
// building 0 collapses; building 1 then stands at the stop, and its later response is unknown:
// the sample is left out of every pounding curve of building 1 (censored), also where its drift
// had passed a limit before the stop (keeping those and not the others would select on its own
// outcome). Building 1's drift is 2 % in the samples 0, 6, 12, ... (all censored) and 1, 11,
// 16, 26, ... (s % 5 = 1, not a multiple of 3), 0.5 % elsewhere. Without pounding nothing is
// censored.
TEST(CollapseFragility, AStandingBuildingIsCensoredWhenThePoundingRunStopsAtItsNeighbour) {
  constexpr std::size_t n = 1200;
  CampaignData c;
  c.path = "made-up.h5";
  c.samples = n;
  c.buildings = 2;
  c.building_names = {"falls", "stands"};
  c.levels = {1.0, 2.0, 4.0, 8.0};
  c.status.assign(n, 0);
  c.scale.assign(n, 1.0);
  FloorArray drift{n, 2, 1, std::vector<double>(2 * n, 0.005)};
  std::vector<double> cp(2 * n, 0.0), cf(2 * n, 0.0);
  std::size_t falls = 0, exceeded = 0, exceeded_standing = 0;
  for (std::size_t s = 0; s < n; ++s) {
    c.im.push_back(c.levels[s % 4]);
    if (s % 3 == 0) {
      cp[2 * s] = 1.0;
      ++falls;
    }
    if (s % 6 == 0 || s % 5 == 1) {
      drift.v[2 * s + 1] = 0.02;
      ++exceeded;
      exceeded_standing += s % 3 != 0;
    }
  }
  c.floor_arrays["peak_drift_ratio_pounding"] = drift;
  c.floor_arrays["peak_drift_ratio_free"] = drift;
  c.building_arrays["collapsed_pounding"] = cp;
  c.building_arrays["collapsed_free"] = cf;
  c.peak_force = FloorArray{n, 0, 0, {}};
  FragilitySettings s = settings();
  s.drift_limits = {0.01};
  const FragilityReport r = analyse_fragility(c, s);
  auto of = [&](std::size_t b, Edp e, bool pounding) -> const FragilityCurve& {
    for (const auto& k : r.curves)
      if (k.building == b && k.edp == e && k.pounding == pounding && k.model.empty()) return k;
    throw std::runtime_error("no such curve");
  };
  auto counted = [](const FragilityCurve& k) {
    long m = 0, z = 0;
    for (const auto& o : k.observed) m += o.n, z += o.z;
    return std::pair<long, long>{m, z};
  };
  // Building 1, drift 1 %: every sample where building 0 fell is left out; the exceedances are
  // those of the others.
  const FragilityCurve& d = of(1, Edp::drift, true);
  EXPECT_EQ(d.censored, falls);
  EXPECT_EQ(d.left_out, falls);
  EXPECT_EQ(counted(d), (std::pair<long, long>{long(n - falls), long(exceeded_standing)}));
  // Its collapse: every sample where building 0 fell is censored.
  const FragilityCurve& k = of(1, Edp::collapse, true);
  EXPECT_EQ(k.censored, falls);
  EXPECT_EQ(counted(k), (std::pair<long, long>{long(n - falls), 0L}));
  // The building that fell and the free runs: nothing censored.
  EXPECT_EQ(of(0, Edp::collapse, true).censored, 0u);
  EXPECT_EQ(counted(of(0, Edp::collapse, true)), (std::pair<long, long>{long(n), long(falls)}));
  EXPECT_EQ(of(1, Edp::drift, false).left_out, 0u);
  EXPECT_EQ(counted(of(1, Edp::drift, false)).second, long(exceeded));
  // The shift takes the free runs of the same analyses.
  for (const auto& x : r.shifts)
    if (x.building == 1 && x.edp == Edp::drift) {
      EXPECT_TRUE(x.same_analyses);
    }
}

// The shift compares like with like: where a neighbour's collapse censored some pounding
// analyses, the free median of the ratio is fitted on the analyses the pounding curve keeps.
// Here building 1's drift is the same with and without pounding, its exceedances drawn from a
// lognormal, and building 0 collapses (with pounding) in each stripe's strongest 30 % of records,
// which are also those where building 1's drift is largest: the censoring is informative. The
// ratio on the same analyses is exactly 1; against the free curve of all the analyses it is not.
TEST(CollapseFragility, TheShiftComparesThePoundingCurveWithTheFreeOneOnTheSameAnalyses) {
  constexpr std::size_t stripes = 5, per = 400, n = stripes * per;
  CampaignData c;
  c.path = "made-up.h5";
  c.samples = n;
  c.buildings = 2;
  c.building_names = {"falls", "stands"};
  for (std::size_t l = 0; l < stripes; ++l) c.levels.push_back(0.5 * double(1u << l));
  c.status.assign(n, 0);
  c.scale.assign(n, 1.0);
  FloorArray drift{n, 2, 1, std::vector<double>(2 * n, 0.001)};
  std::vector<double> cp(2 * n, 0.0), cf(2 * n, 0.0);
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t l = s % stripes, k = s / stripes;
    const double im = c.levels[l], q = (double(k) + 0.5) / double(per);  // q small: strong
    c.im.push_back(im);
    if (q < normal_cdf(std::log(im / kTheta) / kBeta)) drift.v[2 * s + 1] = 0.02;
    if (q < 0.3) cp[2 * s] = 1.0;
  }
  c.floor_arrays["peak_drift_ratio_pounding"] = drift;
  c.floor_arrays["peak_drift_ratio_free"] = drift;
  c.building_arrays["collapsed_pounding"] = cp;
  c.building_arrays["collapsed_free"] = cf;
  c.peak_force = FloorArray{n, 0, 0, {}};
  FragilitySettings st = settings();
  st.drift_limits = {0.01};
  const FragilityReport r = analyse_fragility(c, st);
  const FragilityShift* sh = nullptr;
  for (const auto& x : r.shifts)
    if (x.building == 1 && x.edp == Edp::drift) sh = &x;
  ASSERT_NE(sh, nullptr);
  EXPECT_TRUE(sh->same_analyses);
  EXPECT_DOUBLE_EQ(sh->ratio, 1.0);
  EXPECT_LE(sh->ci.lo, 1.0);
  EXPECT_GE(sh->ci.hi, 1.0);
  const FragilityCurve *p = nullptr, *f = nullptr;
  for (const auto& k : r.curves)
    if (k.building == 1 && k.edp == Edp::drift) {
      (k.pounding ? p : f) = &k;
    }
  ASSERT_TRUE(p && f && p->fit.finite() && f->fit.finite());
  EXPECT_GT(p->censored, 0u);
  EXPECT_DOUBLE_EQ(sh->theta_pounding, p->fit.theta);
  // Without the censored analyses (the strongest records) the pounding curve sees the weaker
  // ones: a larger median than the free curve of all the analyses, whose ratio to it would be a
  // bias (here 1.2), not pounding.
  EXPECT_GT(p->fit.theta, 1.1 * f->fit.theta);
  EXPECT_EQ(sh->theta_free, p->fit.theta);
  // Where nothing is censored (building 0), the free median is the free curve's.
  for (const auto& x : r.shifts) {
    if (x.building == 0) {
      EXPECT_FALSE(x.same_analyses);
    }
  }
}

}  // namespace
}  // namespace pound

// The pounding risk analysis on a made-up campaign whose answers are known in closed form: the
// free-run approach at intensity x (in g) is c x exp(beta eps), so the pounding fragility at gap
// g is lognormal with theta = g / c and beta; on a power-law hazard lambda = k0 x^-k the mean
// annual frequency of pounding is k0 theta^-k exp(k^2 beta^2 / 2) (Cornell et al. 2002) and the
// gap for a target probability follows by inverting it. Each stripe holds the same stratified
// normal eps (Phi^-1 of (i + 1/2) / n), so every fit sees nearly exact fractions.
#include "risk/pounding_risk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "campaign/amplification.hpp"
#include "core/error.hpp"
#include "motion/ground_motion.hpp"
#include "risk/risk_integral.hpp"
#include "sampling/normal.hpp"

namespace pound {
namespace {

constexpr double kC = 0.02;            // approach per g of intensity [m/g]
constexpr double kBeta = 0.4;          // dispersion of the approach [-]
constexpr double kK0 = 1e-4;           // hazard: rate of exceeding 1 g [1/yr]
constexpr double kSlope = 2.5;         // hazard: lambda = k0 x^-k
constexpr double kDriftFactor = 1.25;  // pounding multiplies the drift by this
constexpr int kStripes = 12, kPerStripe = 400;

FloorArray floor_array(std::size_t n, std::size_t a, std::size_t b) {
  FloorArray f;
  f.samples = n;
  f.buildings = a;
  f.floors = b;
  f.v.assign(n * a * b, 0.0);
  return f;
}

double level_g(int j) {  // 0.05 to 1.5 g, log-spaced
  return 0.05 * std::pow(30.0, double(j) / (kStripes - 1));
}

CampaignData made_up_campaign() {
  CampaignData c;
  c.path = "made-up.h5";
  c.intensity_measure = "pga";
  c.building_names = {"left", "right"};
  c.buildings = 2;
  const std::size_t n = kStripes * kPerStripe;
  c.samples = n;
  for (int j = 0; j < kStripes; ++j) c.levels.push_back(level_g(j) * kGravity);
  FloorArray disp_p = floor_array(n, 2, 1), disp_f = floor_array(n, 2, 1);
  FloorArray drift_p = floor_array(n, 2, 1), drift_f = floor_array(n, 2, 1);
  c.approach_free = floor_array(n, 1, 1);
  c.peak_force = floor_array(n, 1, 1);
  c.impacts = floor_array(n, 1, 1);
  for (std::size_t s = 0; s < n; ++s) {
    const int j = int(s % kStripes), i = int(s / kStripes);
    const double x = level_g(j);
    auto eps = [&](int shift) {  // a stratified normal, permuted per quantity
      return normal_quantile((double((i * 7 + shift) % kPerStripe) + 0.5) / kPerStripe);
    };
    c.status.push_back(0);
    c.im.push_back(x * kGravity);
    c.scale.push_back(1.0);
    c.approach_free.v[s] = kC * x * std::exp(kBeta * eps(0));
    disp_f.v[2 * s] = 0.015 * x * std::exp(0.3 * eps(11));
    disp_f.v[2 * s + 1] = 0.010 * x * std::exp(0.3 * eps(23));
    drift_f.v[2 * s] = drift_f.v[2 * s + 1] = 0.01 * x * std::exp(0.35 * eps(5));
    for (std::size_t k : {2 * s, 2 * s + 1}) {
      disp_p.v[k] = disp_f.v[k];
      drift_p.v[k] = kDriftFactor * drift_f.v[k];
    }
  }
  c.floor_arrays.emplace("peak_disp_pounding", disp_p);
  c.floor_arrays.emplace("peak_disp_free", disp_f);
  c.floor_arrays.emplace("peak_drift_ratio_pounding", drift_p);
  c.floor_arrays.emplace("peak_drift_ratio_free", drift_f);
  return c;
}

HazardCurve power_law() {
  std::vector<double> x, r;
  for (double g : {0.01, 0.1, 1.0, 5.0}) x.push_back(g), r.push_back(kK0 * std::pow(g, -kSlope));
  return make_hazard_curve(x, r, "pga", 0.0, "g", "power law");
}

double exact_maf(double gap) {
  const double theta_g = gap / kC;
  return kK0 * std::pow(theta_g, -kSlope) * std::exp(0.5 * kSlope * kSlope * kBeta * kBeta);
}

RiskSettings settings() {
  RiskSettings s;
  s.bootstrap.replicates = 200;
  s.design_im = level_g(6) * kGravity;  // exactly a stripe: the medians are that stripe's
  return s;
}

const std::vector<BuildingMode> kModes = {{0.53, 0.05}, {0.29, 0.05}};

FragilitySettings drift_limit() {
  FragilitySettings f;
  f.drift_limits = {0.01};
  return f;
}

TEST(PoundingRisk, RecoversTheClosedFormFragilityAndMeanAnnualFrequencyAtEveryGap) {
  const CampaignData c = made_up_campaign();
  const RiskReport r = analyse_risk(c, power_law(), settings(), kModes, drift_limit());
  ASSERT_EQ(r.pairs.size(), 1u);
  const PairRisk& p = r.pairs[0];
  ASSERT_EQ(p.grid.size(), 40u);
  EXPECT_EQ(p.grid.front().gap, 0.0);
  int checked = 0;
  for (const auto& e : p.grid) {
    const double theta_g = e.gap / kC;
    if (theta_g < 0.07 || theta_g > 1.3) continue;  // medians well inside the stripes
    ++checked;
    ASSERT_TRUE(e.fit.finite()) << e.gap;
    EXPECT_NEAR(e.fit.theta / kGravity, theta_g, 0.02 * theta_g) << e.gap;
    EXPECT_NEAR(e.fit.beta, kBeta, 0.05 * kBeta) << e.gap;
    EXPECT_NEAR(e.maf, exact_maf(e.gap), 0.05 * exact_maf(e.gap)) << e.gap;
    EXPECT_NEAR(e.probability, probability_in_years(e.maf, 50.0), 1e-15);
    EXPECT_LE(e.probability_band.lo, e.probability);
    EXPECT_GE(e.probability_band.hi, e.probability);
  }
  EXPECT_GE(checked, 10);
  // At gap 0 every sample pounds: no finite estimate, and no numbers.
  EXPECT_EQ(p.grid.front().fit.status, FitStatus::all_exceed);
  EXPECT_TRUE(std::isnan(p.grid.front().maf));
}

TEST(PoundingRisk, GapForTheTargetInvertsTheClosedFormWithinItsBand) {
  const CampaignData c = made_up_campaign();
  const RiskSettings s = settings();
  const RiskReport r = analyse_risk(c, power_law(), s, kModes, drift_limit());
  const PairRisk& p = r.pairs[0];
  // nu(g*) = -ln(1 - P) / T: g* = c (k0 exp(k^2 beta^2 / 2) / nu*)^(1/k).
  const double nu_star = -std::log1p(-s.target_probability) / s.years;
  const double g_star =
      kC * std::pow(kK0 * std::exp(0.5 * kSlope * kSlope * kBeta * kBeta) / nu_star, 1.0 / kSlope);
  ASSERT_EQ(p.target_status, TargetStatus::found);
  EXPECT_NEAR(p.gap_for_target, g_star, 0.02 * g_star);
  EXPECT_LE(p.gap_band.lo, g_star);
  EXPECT_GE(p.gap_band.hi, g_star);
  EXPECT_LT(p.gap_band.hi - p.gap_band.lo, 0.2 * g_star);
  EXPECT_EQ(p.gap_band.finite, 200);
  // The gap found is the smallest of the samples' approaches that meets the target: at it the
  // probability is at most the target, just below it above.
  const auto below = std::find_if(p.grid.begin(), p.grid.end(),
                                  [&](const GapEstimate& e) { return e.gap >= p.gap_for_target; });
  ASSERT_NE(below, p.grid.begin());
  EXPECT_GT(std::prev(below)->probability, s.target_probability);
}

TEST(PoundingRisk, CodeRulesFromTheMedianFreeDisplacementsAtTheDesignIntensity) {
  const CampaignData c = made_up_campaign();
  const RiskSettings s = settings();
  const RiskReport r = analyse_risk(c, power_law(), s, kModes, drift_limit());
  const PairRisk& p = r.pairs[0];
  ASSERT_TRUE(p.rules_computed) << p.rules_note;
  // The medians of stripe 6, as the test computes them.
  std::vector<double> left, right;
  const FloorArray& u = c.floor_array("peak_disp_free");
  for (std::size_t sa = 6; sa < c.samples; sa += kStripes)
    left.push_back(u.at(sa, 0, 0)), right.push_back(u.at(sa, 1, 0));
  const double ml = summarize(left).median, mr = summarize(right).median;
  ASSERT_EQ(p.median_left.size(), 1u);
  EXPECT_DOUBLE_EQ(p.median_left[0], ml);
  EXPECT_DOUBLE_EQ(p.median_right[0], mr);
  EXPECT_DOUBLE_EQ(p.rho, cqc_correlation(0.53, 0.05, 0.29, 0.05));
  ASSERT_EQ(p.rules.size(), 3u);
  for (const auto& k : p.rules) {
    EXPECT_DOUBLE_EQ(k.gap, separation_gap(k.rule, ml, mr, p.rho)) << to_string(k.rule);
    EXPECT_EQ(k.level, 1);
    // Its probability is that of the fitted fragility at that gap.
    ASSERT_TRUE(k.estimate.fit.finite());
    EXPECT_NEAR(k.estimate.maf, exact_maf(k.gap), 0.05 * exact_maf(k.gap));
  }
  EXPECT_GT(p.rules[0].gap, p.rules[1].gap);  // abs > srss > ddc (rho > 0)
  EXPECT_GT(p.rules[1].gap, p.rules[2].gap);
  EXPECT_LT(p.rules[0].estimate.probability, p.rules[2].estimate.probability);
}

TEST(PoundingRisk, DamageLimitRiskWithAndWithoutPounding) {
  // The drift with pounding is 1.25 times the free drift: theta falls by 1.25 and, with the
  // same beta, nu rises by 1.25^k on a power-law hazard.
  const RiskReport r =
      analyse_risk(made_up_campaign(), power_law(), settings(), kModes, drift_limit());
  ASSERT_EQ(r.damage.size(), 2u);  // two buildings, one drift limit
  for (const auto& d : r.damage) {
    EXPECT_EQ(d.edp, Edp::drift);
    ASSERT_TRUE(d.pounding.finite() && d.free.finite());
    EXPECT_NEAR(d.ratio, std::pow(kDriftFactor, kSlope), 0.03 * std::pow(kDriftFactor, kSlope));
    EXPECT_NEAR(d.maf_pounding,
                mean_annual_frequency(power_law(), d.pounding.theta, d.pounding.beta), 1e-15);
  }
}

TEST(PoundingRisk, DefaultDesignIntensityAndBadInput) {
  const CampaignData c = made_up_campaign();
  RiskSettings s = settings();
  s.design_im = 0.0;  // the hazard's 475-year intensity: (k0 475)^(1/k) g
  s.bootstrap.replicates = 10;
  const RiskReport r = analyse_risk(c, power_law(), s, kModes, drift_limit());
  EXPECT_FALSE(r.design_im_given);
  EXPECT_NEAR(r.design_im, std::pow(kK0 * 475.0, 1.0 / kSlope) * kGravity, 1e-9);
  // A given design intensity outside the stripes, a target outside (0, 1), no approach data.
  s.design_im = 2.0 * kGravity;
  EXPECT_THROW(analyse_risk(c, power_law(), s, kModes, drift_limit()), InputError);
  s.design_im = 0.0;
  for (double t : {0.0, 1.0, -0.1, std::nan("")}) {
    RiskSettings b = s;
    b.target_probability = t;
    EXPECT_THROW(analyse_risk(c, power_law(), b, kModes, drift_limit()), InputError) << t;
  }
  CampaignData old = c;
  old.approach_free = FloorArray{};
  try {
    analyse_risk(old, power_law(), s, kModes, drift_limit());
    ADD_FAILURE() << "a file without approach_free was analysed";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("approach_free"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pound

namespace pound {
namespace {

// Collapse in pound risk: the probability in T years is 1 - exp(-nu T) and the collapse margin
// ratio the median collapse intensity over the design (MCE) intensity (FEMA P695, sec. 6.3);
// only the collapse limit is a collapse entry, per model as the damage limits are.
TEST(CollapseRisk, ProbabilityInTYearsAndTheCollapseMarginRatio) {
  DamageRisk collapse;
  collapse.model = "sears";
  collapse.building = 1;
  collapse.edp = Edp::collapse;
  collapse.limit = 1.0;
  collapse.pounding.status = collapse.free.status = FitStatus::ok;
  collapse.pounding.theta = 1.5 * kGravity;
  collapse.free.theta = 2.0 * kGravity;
  collapse.pounding.beta = collapse.free.beta = 0.5;
  collapse.maf_pounding = 2e-4;
  collapse.maf_free = 1e-4;
  collapse.ratio = 2.0;
  DamageRisk drift = collapse;
  drift.edp = Edp::drift;
  RiskSettings s;
  s.years = 50;
  const auto c = collapse_risks({drift, collapse}, s, 0.75 * kGravity);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].model, "sears");
  EXPECT_EQ(c[0].building, 1u);
  EXPECT_DOUBLE_EQ(c[0].probability_pounding, -std::expm1(-2e-4 * 50));
  EXPECT_DOUBLE_EQ(c[0].probability_free, -std::expm1(-1e-4 * 50));
  EXPECT_DOUBLE_EQ(c[0].cmr_pounding, 2.0);
  EXPECT_DOUBLE_EQ(c[0].cmr_free, 2.0 / 0.75);
  EXPECT_DOUBLE_EQ(c[0].ratio, 2.0);
  // Without a design intensity there is no margin ratio.
  const auto d = collapse_risks({collapse}, s, 0.0);
  EXPECT_TRUE(std::isnan(d[0].cmr_pounding) && std::isnan(d[0].cmr_free));
}

TEST(CollapseRisk, WithCensoredAnalysesTheMedianIsTheFreeOneTimesTheLikeForLikeShift) {
  DamageRisk collapse;
  collapse.edp = Edp::collapse;
  collapse.limit = 1.0;
  collapse.pounding.status = collapse.free.status = collapse.free_same.status = FitStatus::ok;
  collapse.pounding.theta = 1.5 * kGravity;
  collapse.free.theta = 2.0 * kGravity;
  collapse.free_same.theta = 1.8 * kGravity;
  collapse.same_analyses = true;
  RiskSettings s;
  const auto c = collapse_risks({collapse}, s, 1.0 * kGravity);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].same_analyses);
  EXPECT_DOUBLE_EQ(c[0].theta_pounding, 2.0 * kGravity * 1.5 / 1.8);
  EXPECT_DOUBLE_EQ(c[0].cmr_pounding, 2.0 * 1.5 / 1.8);
  EXPECT_DOUBLE_EQ(c[0].cmr_free, 2.0);
}

// The made-up campaign with collapse: building "left" collapses in the pounding run in the
// strongest 30 % of each stripe's records (by the drift's eps, so the censoring of "right" is
// informative); without pounding nothing collapses. Within the analyses the pounding curve
// keeps, pounding multiplies every drift by 1.25, so the like-for-like ratio of the drift
// limit's nu is near 1.25^k (theta / 1.25 on a power-law hazard of slope k); the pounding
// curve against the free curve of all the analyses is not.
TEST(PoundingRisk, DamageLimitsCompareLikeWithLikeWhereANeighboursCollapseCensored) {
  CampaignData c = made_up_campaign();
  std::vector<double> cp(2 * c.samples, 0.0), cf(2 * c.samples, 0.0);
  const double strong = normal_quantile(0.7);
  for (std::size_t s = 0; s < c.samples; ++s) {
    const int i = int(s / kStripes);
    const double eps = normal_quantile((double((i * 7 + 5) % kPerStripe) + 0.5) / kPerStripe);
    if (eps > strong) cp[2 * s] = 1.0;
  }
  c.building_arrays["collapsed_pounding"] = cp;
  c.building_arrays["collapsed_free"] = cf;
  FragilitySettings limits = drift_limit();
  limits.collapse = false;
  RiskSettings st = settings();
  st.bootstrap.replicates = 0;
  const RiskReport r = analyse_risk(c, power_law(), st, kModes, limits);
  const DamageRisk* d = nullptr;
  for (const auto& x : r.damage)
    if (x.building == 1 && x.edp == Edp::drift) d = &x;
  ASSERT_NE(d, nullptr);
  ASSERT_TRUE(d->same_analyses);
  ASSERT_TRUE(d->pounding.finite() && d->free.finite() && d->free_same.finite());
  const HazardCurve h = power_law();
  const double same = mean_annual_frequency(h, d->free_same.theta, d->free_same.beta);
  EXPECT_DOUBLE_EQ(d->maf_pounding_kept,
                   mean_annual_frequency(h, d->pounding.theta, d->pounding.beta));
  EXPECT_DOUBLE_EQ(d->ratio, d->maf_pounding_kept / same);
  EXPECT_DOUBLE_EQ(d->maf_pounding, d->maf_free * d->ratio);
  const double expected = std::pow(kDriftFactor, kSlope);
  EXPECT_NEAR(d->ratio, expected, 0.1 * expected);
  EXPECT_GT(std::fabs(d->maf_pounding_kept / d->maf_free / expected - 1.0), 0.1);
  // Building "left" is never censored: its numbers are the plain ones.
  for (const auto& x : r.damage)
    if (x.building == 0 && x.edp == Edp::drift) {
      EXPECT_FALSE(x.same_analyses);
      EXPECT_EQ(x.maf_pounding, x.maf_pounding_kept);
    }
}

}  // namespace
}  // namespace pound

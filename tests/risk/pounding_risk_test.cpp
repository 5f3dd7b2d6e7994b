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
#include "risk/site_displacements.hpp"
#include "risk/study_sites.hpp"
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
const PairSites kAligned = {same_index_sites(1)};  // floor 1 meets floor 1, slab to slab

FragilitySettings drift_limit() {
  FragilitySettings f;
  f.drift_limits = {0.01};
  return f;
}

TEST(PoundingRisk, RecoversTheClosedFormFragilityAndMeanAnnualFrequencyAtEveryGap) {
  const CampaignData c = made_up_campaign();
  const RiskReport r = analyse_risk(c, power_law(), settings(), kModes, kAligned, drift_limit());
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
  const RiskReport r = analyse_risk(c, power_law(), s, kModes, kAligned, drift_limit());
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
  const RiskReport r = analyse_risk(c, power_law(), s, kModes, kAligned, drift_limit());
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
  ASSERT_EQ(p.rules.size(), 4u);
  EXPECT_EQ(p.ec8_case, Ec8Case::floors_coincide);
  for (const auto& k : p.rules) {
    EXPECT_DOUBLE_EQ(k.gap, separation_gap(k.rule, ml, mr, p.rho, p.ec8_case)) << to_string(k.rule);
    EXPECT_EQ(k.level, 1);
    // Its probability is that of the fitted fragility at that gap.
    ASSERT_TRUE(k.estimate.fit.finite());
    EXPECT_NEAR(k.estimate.maf, exact_maf(k.gap), 0.05 * exact_maf(k.gap));
  }
  EXPECT_GT(p.rules[0].gap, p.rules[1].gap);  // abs > srss > ddc (rho > 0)
  EXPECT_GT(p.rules[1].gap, p.rules[2].gap);
  EXPECT_LT(p.rules[0].estimate.probability, p.rules[2].estimate.probability);
  EXPECT_EQ(p.rules[3].rule, SeparationRule::ec8);
  EXPECT_DOUBLE_EQ(p.rules[3].gap, 0.7 * p.rules[1].gap);
  EXPECT_GT(p.rules[3].estimate.probability, p.rules[1].estimate.probability);
  // Without the study's floors: floor 1 against floor 1 as before, to the bit, and no reduction.
  const RiskReport unread = analyse_risk(c, power_law(), s, kModes, {}, drift_limit());
  const PairRisk& q = unread.pairs[0];
  EXPECT_EQ(q.ec8_case, Ec8Case::floors_unknown);
  ASSERT_EQ(q.rules.size(), 4u);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(q.rules[k].gap, p.rules[k].gap) << k;
  EXPECT_EQ(q.rules[3].gap, q.rules[1].gap);
  EXPECT_NE(std::find_if(unread.notes.begin(), unread.notes.end(),
                         [](const std::string& n) {
                           return n.find("floor elevations could not be read") != std::string::npos;
                         }),
            unread.notes.end());
}

TEST(PoundingRisk, DamageLimitRiskWithAndWithoutPounding) {
  // The drift with pounding is 1.25 times the free drift: theta falls by 1.25 and, with the
  // same beta, nu rises by 1.25^k on a power-law hazard.
  const RiskReport r =
      analyse_risk(made_up_campaign(), power_law(), settings(), kModes, kAligned, drift_limit());
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
  const RiskReport r = analyse_risk(c, power_law(), s, kModes, kAligned, drift_limit());
  EXPECT_FALSE(r.design_im_given);
  EXPECT_NEAR(r.design_im, std::pow(kK0 * 475.0, 1.0 / kSlope) * kGravity, 1e-9);
  // A given design intensity outside the stripes, a target outside (0, 1), no approach data.
  s.design_im = 2.0 * kGravity;
  EXPECT_THROW(analyse_risk(c, power_law(), s, kModes, kAligned, drift_limit()), InputError);
  s.design_im = 0.0;
  for (double t : {0.0, 1.0, -0.1, std::nan("")}) {
    RiskSettings b = s;
    b.target_probability = t;
    EXPECT_THROW(analyse_risk(c, power_law(), b, kModes, kAligned, drift_limit()), InputError) << t;
  }
  CampaignData old = c;
  old.approach_free = FloorArray{};
  try {
    analyse_risk(old, power_law(), s, kModes, kAligned, drift_limit());
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
  const RiskReport r = analyse_risk(c, power_law(), st, kModes, kAligned, limits);
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

namespace pound {
namespace {

// The code rules where the floors do not align (issue 36): two 2-storey buildings on three
// stripes of three samples. At the design stripe the median peak floor displacements are, by
// construction, left {0.012, 0.024} m and right {0.006, 0.016} m.
constexpr double kLeft[2][3] = {{0.010, 0.012, 0.014}, {0.020, 0.024, 0.030}};
constexpr double kRight[2][3] = {{0.005, 0.006, 0.009}, {0.015, 0.016, 0.020}};

CampaignData two_storey_campaign(const std::string& heights_left,
                                 const std::string& heights_right) {
  CampaignData c;
  c.path = "two-storey.h5";
  c.intensity_measure = "pga";
  c.building_names = {"left", "right"};
  c.buildings = 2;
  c.study =
      "building1.masses = 1e5, 1e5\nbuilding1.stiffnesses = 1e8, 1e8\n"
      "building1.storey_heights = " +
      heights_left +
      "\nbuilding2.masses = 1e5, 1e5\nbuilding2.stiffnesses = 1e8, 1e8\n"
      "building2.storey_heights = " +
      heights_right + "\npair1.gap = 0.01\n";
  const double factor[3] = {0.5, 1.0, 2.0};  // per stripe, 0.1, 0.2 and 0.4 g
  for (double f : factor) c.levels.push_back(0.2 * f * kGravity);
  const std::size_t n = 9;
  c.samples = n;
  FloorArray u = floor_array(n, 2, 2);
  c.approach_free = floor_array(n, 1, 3);
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t j = s / 3, i = s % 3;
    c.status.push_back(0);
    c.im.push_back(c.levels[j]);
    c.scale.push_back(1.0);
    for (std::size_t fl = 0; fl < 2; ++fl) {
      u.v[(s * 2 + 0) * 2 + fl] = factor[j] * kLeft[fl][i];
      u.v[(s * 2 + 1) * 2 + fl] = factor[j] * kRight[fl][i];
    }
    for (std::size_t l = 0; l < 3; ++l) c.approach_free.v[s * 3 + l] = 0.01 * factor[j] * (i + 1);
  }
  c.floor_arrays.emplace("peak_disp_free", u);
  c.floor_arrays.emplace("peak_disp_pounding", u);
  return c;
}

RiskReport two_storey_risk(const CampaignData& c) {
  RiskSettings s;
  s.bootstrap.replicates = 0;
  s.design_im = 0.2 * kGravity;  // the middle stripe
  FragilitySettings none;
  none.drift_limits.clear();
  none.collapse = false;
  return analyse_risk(c, power_law(), s, kModes, study_pair_sites(c), none);
}

double rule_gap(const PairRisk& p, SeparationRule r, int* level = nullptr) {
  for (const auto& k : p.rules)
    if (k.rule == r) {
      if (level) *level = k.level;
      return k.gap;
    }
  ADD_FAILURE() << "no rule " << to_string(r);
  return 0.0;
}

TEST(PoundingRisk, Ec8IsSevenTenthsOfSrssWhereTheFloorsCoincide) {
  // Equal storeys: floor l against floor l. SRSS per level: sqrt(0.012^2 + 0.006^2) =
  // 0.0134164 and sqrt(0.024^2 + 0.016^2) = sqrt(0.000832) = 0.0288444 (level 2);
  // ec8 = 0.7 x 0.0288444 = 0.0201911; abs 0.040.
  const RiskReport r = two_storey_risk(two_storey_campaign("3, 3", "3, 3"));
  const PairRisk& p = r.pairs[0];
  ASSERT_TRUE(p.rules_computed) << p.rules_note;
  EXPECT_EQ(p.ec8_case, Ec8Case::floors_coincide);
  ASSERT_EQ(p.median_left.size(), 2u);
  EXPECT_EQ(p.median_left[1], 0.024);
  EXPECT_EQ(p.median_right[1], 0.016);
  int level = 0;
  EXPECT_NEAR(rule_gap(p, SeparationRule::srss, &level), 0.0288444, 1e-7);
  EXPECT_EQ(level, 2);
  EXPECT_NEAR(rule_gap(p, SeparationRule::ec8, &level), 0.0201911, 1e-7);
  EXPECT_EQ(level, 2);
  EXPECT_NEAR(rule_gap(p, SeparationRule::abs), 0.040, 1e-15);
}

TEST(PoundingRisk, Ec8IsSrssAtTheStruckPointsWhereTheFloorsAreOffset) {
  // Left floors at 4 and 8 m, right at 2 and 6 m: three slab-to-column sites at xi 0.5 (s 0.5)
  // (tests/risk/study_sites_test.cpp). Site 1: left storey 1's point 0.5 x 0 + 0.5 x 0.012 =
  // 0.006 against right floor 1, 0.006. Site 2: left floor 1, 0.012, against right storey 2's
  // point 0.5 x 0.006 + 0.5 x 0.016 = 0.011. Site 3: left storey 2's point 0.5 x 0.012 + 0.5 x
  // 0.024 = 0.018 against right floor 2, 0.016. SRSS 0.0084853, sqrt(0.000265) = 0.0162788 and
  // sqrt(0.00058) = 0.0240832 (site 3): ec8 = SRSS = 0.0240832, abs 0.034 (site 3).
  const RiskReport r = two_storey_risk(two_storey_campaign("4, 4", "2, 4"));
  const PairRisk& p = r.pairs[0];
  ASSERT_TRUE(p.rules_computed) << p.rules_note;
  EXPECT_EQ(p.ec8_case, Ec8Case::floors_offset);
  const double left[] = {0.006, 0.012, 0.018}, right[] = {0.006, 0.011, 0.016};
  ASSERT_EQ(p.median_left.size(), 3u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(p.median_left[k], left[k], 1e-15) << k;
    EXPECT_NEAR(p.median_right[k], right[k], 1e-15) << k;
  }
  int level = 0;
  EXPECT_NEAR(rule_gap(p, SeparationRule::srss, &level), 0.0240832, 1e-7);
  EXPECT_EQ(level, 3);
  EXPECT_EQ(rule_gap(p, SeparationRule::ec8, &level), rule_gap(p, SeparationRule::srss));
  EXPECT_EQ(level, 3);
  EXPECT_NEAR(rule_gap(p, SeparationRule::abs), 0.034, 1e-15);
}

}  // namespace
}  // namespace pound

// The bootstrap bands of the damage limits in pound risk (issue 36): the same estimator as the
// point value on every replicate of the fragility bootstrap. Made-up campaigns whose bootstrap
// behaviour is known: a well-sampled one (the band holds the point; the ratio of two paired
// rates varies less than either rate), one whose replicates are all the data (one analysis per
// stripe: the band is the point, like for like included), the same analyses repeated four times
// (the band narrows by about 1 / sqrt(4)), and one so thin that some replicates have no finite
// fit (a note counts them).
#include "risk/damage_risk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "motion/ground_motion.hpp"
#include "risk/risk_integral.hpp"
#include "sampling/normal.hpp"

namespace pound {
namespace {

constexpr double kK0 = 1e-4;     // hazard: rate of exceeding 1 g [1/yr]
constexpr double kSlope = 2.5;   // hazard: lambda = k0 x^-k
constexpr double kFactor = 1.1;  // pounding multiplies the drift by this
constexpr double kLimit = 0.01;  // the drift limit [-]
constexpr int kStripes = 10;

HazardCurve power_law() {
  std::vector<double> x, r;
  for (double g : {0.01, 0.1, 1.0, 5.0}) x.push_back(g), r.push_back(kK0 * std::pow(g, -kSlope));
  return make_hazard_curve(x, r, "pga", 0.0, "g", "power law");
}

double level_g(int j, int stripes) {  // 0.05 to 1.5 g, log-spaced
  return 0.05 * std::pow(30.0, double(j) / (stripes - 1));
}

// Two one-storey buildings on kStripes stripes with per_stripe analyses each, every analysis
// repeated `copies` times: the free peak drift at x g is 0.01 x exp(0.4 eps), eps a stratified
// normal permuted per building; pounding multiplies it by 1.1.
CampaignData drift_campaign(int per_stripe, int copies = 1) {
  CampaignData c;
  c.path = "made-up.h5";
  c.intensity_measure = "pga";
  c.building_names = {"left", "right"};
  c.buildings = 2;
  const std::size_t n = std::size_t(kStripes * per_stripe * copies);
  c.samples = n;
  for (int j = 0; j < kStripes; ++j) c.levels.push_back(level_g(j, kStripes) * kGravity);
  FloorArray p{n, 2, 1, std::vector<double>(2 * n)}, f = p;
  std::size_t s = 0;
  for (int copy = 0; copy < copies; ++copy)
    for (int i = 0; i < per_stripe; ++i)
      for (int j = 0; j < kStripes; ++j, ++s) {
        c.status.push_back(0);
        c.im.push_back(level_g(j, kStripes) * kGravity);
        c.scale.push_back(1.0);
        for (std::size_t b = 0; b < 2; ++b) {
          const int k = (i * int(7 + 4 * b) + j) % per_stripe;  // a permutation per building
          const double eps = normal_quantile((double(k) + 0.5) / per_stripe);
          f.v[2 * s + b] = 0.01 * level_g(j, kStripes) * std::exp(0.4 * eps);
          p.v[2 * s + b] = kFactor * f.v[2 * s + b];
        }
      }
  c.floor_arrays.emplace("peak_drift_ratio_pounding", p);
  c.floor_arrays.emplace("peak_drift_ratio_free", f);
  return c;
}

FragilitySettings drift_limit() {
  FragilitySettings f;
  f.drift_limits = {kLimit};
  return f;
}

RiskSettings replicates(int n, std::uint64_t seed = 1) {
  RiskSettings s;
  s.bootstrap.replicates = n;
  s.bootstrap.seed = seed;
  return s;
}

std::vector<DamageRisk> risks(const CampaignData& c, const RiskSettings& s,
                              const FragilitySettings& limits = drift_limit()) {
  const double lo = *std::min_element(c.im.begin(), c.im.end());
  const double hi = *std::max_element(c.im.begin(), c.im.end());
  return damage_risks(c, power_law(), limits, s, lo, hi);
}

double log_width(const Interval& iv) {
  return std::log(iv.hi / iv.lo);
}

// Each estimate of a damage limit with its bootstrap band.
struct PointAndBand {
  double point;
  Interval band;
};
std::vector<PointAndBand> points_and_bands(const DamageRisk& d) {
  return {{d.maf_pounding, d.maf_pounding_band},
          {d.maf_free, d.maf_free_band},
          {d.ratio, d.ratio_band},
          {d.probability_pounding, d.probability_pounding_band},
          {d.probability_free, d.probability_free_band}};
}

TEST(DamageRisk, TheBandHoldsThePointAndTheRatioOfPairedRatesVariesLess) {
  const RiskSettings s = replicates(400);
  const auto damage = risks(drift_campaign(40), s);
  ASSERT_EQ(damage.size(), 2u);  // two buildings, one drift limit
  for (const DamageRisk& d : damage) {
    SCOPED_TRACE(d.building);
    ASSERT_TRUE(d.pounding.finite() && d.free.finite());
    EXPECT_FALSE(d.same_analyses);
    EXPECT_EQ(d.bootstrap_replicates, 400);
    EXPECT_DOUBLE_EQ(d.probability_pounding, probability_in_years(d.maf_pounding, s.years));
    EXPECT_DOUBLE_EQ(d.probability_free, probability_in_years(d.maf_free, s.years));
    for (const PointAndBand& x : points_and_bands(d)) {
      EXPECT_EQ(x.band.finite, 400);
      EXPECT_LT(x.band.lo, x.point);
      EXPECT_GT(x.band.hi, x.point);
    }
    // 400 analyses of beta 0.4 on ten stripes: nu's 90 % band spans about 0.5 in ln (+-25 %);
    // not a degenerate band, not a wild one.
    EXPECT_GT(log_width(d.maf_pounding_band), 0.1);
    EXPECT_LT(log_width(d.maf_pounding_band), 0.6);
    // Every replicate fits both curves on the same redrawn analyses, so a draw that moves one
    // rate moves the other: the ratio's band is narrower than independent draws would make it,
    // about sqrt(w_pounding^2 + w_free^2) in ln. (The drift limit with pounding is the free
    // drift's at 1 / 1.1, a quarter of a beta away: the two curves' counts at a stripe are
    // correlated by about 0.85, which leaves the ratio about 0.4 of the independent width.)
    EXPECT_LT(log_width(d.ratio_band),
              0.7 * std::hypot(log_width(d.maf_pounding_band), log_width(d.maf_free_band)));
    // The ratio is near 1.1^k (theta / 1.1, the same beta), and so is its band.
    EXPECT_LT(d.ratio_band.lo, std::pow(kFactor, kSlope) * 1.05);
    EXPECT_GT(d.ratio_band.hi, std::pow(kFactor, kSlope) * 0.95);
  }
  std::vector<std::string> notes;
  add_damage_notes(damage, notes);
  EXPECT_TRUE(notes.empty()) << notes.front();
}

TEST(DamageRisk, TheSameSeedGivesTheSameBandAnotherSeedAnother) {
  const CampaignData c = drift_campaign(20);
  const auto a = risks(c, replicates(100, 7)), b = risks(c, replicates(100, 7));
  const auto other = risks(c, replicates(100, 8));
  ASSERT_EQ(a.size(), 2u);
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].maf_pounding_band.lo, b[k].maf_pounding_band.lo);
    EXPECT_EQ(a[k].maf_pounding_band.hi, b[k].maf_pounding_band.hi);
    EXPECT_EQ(a[k].probability_free_band.lo, b[k].probability_free_band.lo);
    EXPECT_EQ(a[k].ratio_band.hi, b[k].ratio_band.hi);
    EXPECT_NE(a[k].maf_pounding_band.lo, other[k].maf_pounding_band.lo);
    EXPECT_EQ(a[k].maf_pounding, other[k].maf_pounding);  // the point does not depend on it
  }
  // Without replicates, no band, and the same points.
  const auto none = risks(c, replicates(0));
  EXPECT_EQ(none[0].bootstrap_replicates, 0);
  EXPECT_TRUE(std::isnan(none[0].maf_pounding_band.lo) && none[0].maf_pounding_band.finite == 0);
  EXPECT_EQ(none[0].maf_pounding, a[0].maf_pounding);
}

TEST(DamageRisk, EveryStripesAnalysesFourTimesNarrowTheBandByAboutHalf) {
  // The empirical distribution of each stripe is unchanged, its size four times: the
  // bootstrap's spread falls as 1 / sqrt(n), to 0.5 (within the noise of 1000 replicates).
  const RiskSettings s = replicates(1000);
  const auto once = risks(drift_campaign(30, 1), s), four = risks(drift_campaign(30, 4), s);
  ASSERT_EQ(once.size(), 2u);
  ASSERT_EQ(four.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    SCOPED_TRACE(k);
    // The same fractions at every stripe: the same points.
    EXPECT_NEAR(four[k].maf_pounding, once[k].maf_pounding, 1e-7 * once[k].maf_pounding);
    for (auto band : {&DamageRisk::maf_pounding_band, &DamageRisk::maf_free_band,
                      &DamageRisk::probability_pounding_band}) {
      const double r = log_width(four[k].*band) / log_width(once[k].*band);
      EXPECT_GT(r, 0.4);
      EXPECT_LT(r, 0.6);
    }
  }
}

// One analysis per stripe: a replicate redraws each stripe's one analysis, so every replicate
// is the data, its fits the point's, and the band the point to the bit. Building "left"
// collapses in the pounding run on the two strongest stripes, which censors "right" there: its
// rate with pounding is then the like-for-like estimate, maf_free x nu(pounding) /
// nu(free on the kept analyses), on every replicate as on the point.
TEST(DamageRisk, ReplicatesThatAreTheDataGiveABandThatIsThePointLikeForLikeIncluded) {
  constexpr int n = 16;
  const char free_exceeds[] = "0001001011011111", pounding_exceeds[] = "0010011011011111";
  CampaignData c;
  c.path = "one-per-stripe.h5";
  c.intensity_measure = "pga";
  c.building_names = {"left", "right"};
  c.buildings = 2;
  c.samples = n;
  FloorArray p{n, 2, 1, std::vector<double>(2 * n)}, f = p;
  std::vector<double> collapsed_p(2 * n, 0.0), collapsed_f(2 * n, 0.0);
  for (int j = 0; j < n; ++j) {
    c.levels.push_back(level_g(j, n) * kGravity);
    c.im.push_back(c.levels.back());
    c.status.push_back(0);
    c.scale.push_back(1.0);
    for (std::size_t b = 0; b < 2; ++b) {
      f.v[2 * j + b] = free_exceeds[j] == '1' ? 2 * kLimit : 0.5 * kLimit;
      p.v[2 * j + b] = pounding_exceeds[j] == '1' ? 2 * kLimit : 0.5 * kLimit;
    }
    if (j >= n - 2) collapsed_p[2 * j] = 1.0;
  }
  c.floor_arrays.emplace("peak_drift_ratio_pounding", p);
  c.floor_arrays.emplace("peak_drift_ratio_free", f);
  c.building_arrays["collapsed_pounding"] = collapsed_p;
  c.building_arrays["collapsed_free"] = collapsed_f;
  FragilitySettings limits = drift_limit();
  limits.collapse = false;
  const auto damage = risks(c, replicates(50), limits);
  ASSERT_EQ(damage.size(), 2u);
  EXPECT_FALSE(damage[0].same_analyses);
  EXPECT_TRUE(damage[1].same_analyses);
  for (const DamageRisk& d : damage) {
    SCOPED_TRACE(d.building);
    ASSERT_TRUE(d.pounding.finite() && d.free.finite() && d.free_same.finite());
    for (const PointAndBand& x : points_and_bands(d)) {
      EXPECT_EQ(x.band.finite, 50);
      EXPECT_DOUBLE_EQ(x.band.lo, x.point);
      EXPECT_DOUBLE_EQ(x.band.hi, x.point);
    }
  }
  // Like for like on "right": its band is maf_free x nu(pounding kept) / nu(free same), not the
  // kept pounding curve's own rate, which differs.
  const DamageRisk& r = damage[1];
  const HazardCurve h = power_law();
  EXPECT_DOUBLE_EQ(r.maf_pounding_band.lo,
                   r.maf_free * mean_annual_frequency(h, r.pounding.theta, r.pounding.beta) /
                       mean_annual_frequency(h, r.free_same.theta, r.free_same.beta));
  EXPECT_GT(std::fabs(r.maf_pounding_band.lo / r.maf_pounding_kept - 1.0), 0.01);
}

TEST(DamageRisk, ANoteCountsTheReplicatesOfABandWhereSomeHaveNoFiniteFit) {
  // Three analyses a stripe: some replicates redraw stripes that leave the outcomes separated
  // (no finite maximum-likelihood estimate); the band comes from the others, and a note says
  // from how many.
  const auto damage = risks(drift_campaign(3), replicates(200));
  int partial = 0;
  for (const DamageRisk& d : damage)
    if (std::isfinite(d.maf_pounding) && d.maf_pounding_band.finite < 200) {
      ++partial;
      EXPECT_GT(d.maf_pounding_band.finite, 0);
      EXPECT_LE(d.maf_pounding_band.lo, d.maf_pounding_band.hi);
    }
  ASSERT_GT(partial, 0) << "no replicate without a finite fit: the case is not tested";
  std::vector<std::string> notes;
  add_damage_notes(damage, notes);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("fewer than all 200 bootstrap replicates"), std::string::npos)
      << notes[0];
  for (const DamageRisk& d : damage) {
    if (!std::isfinite(d.maf_pounding) || d.maf_pounding_band.finite == 200) continue;
    EXPECT_NE(notes[0].find(std::to_string(d.maf_pounding_band.finite) + " with pounding"),
              std::string::npos)
        << notes[0];
  }
}

}  // namespace
}  // namespace pound

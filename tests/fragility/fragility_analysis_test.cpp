// The residual drift and ductility EDPs on a made-up campaign whose exceedance counts are
// known: the maximum over the storeys, analyses without a finite value left out of the curve
// and counted, and a file without the datasets refused only when their curves are asked for.
#include "fragility/fragility_analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace pound {
namespace {

constexpr double kNaN = NAN;
constexpr std::size_t kSamples = 90;  // 3 stripes x 30

// Sample s sits on stripe s % 3 (1, 2, 4 m/s^2) with the spread u = (s / 3 + 0.5) / 30.
double im_of(std::size_t s) {
  return double(1u << (s % 3));
}
double u_of(std::size_t s) {
  return (double(s / 3) + 0.5) / 30.0;
}

// Two buildings of two floors. Ductility: building 1 has 0.5 im (0.5 + u) on storey 1 and
// im (0.5 + u) on storey 2; building 2 the same on storey 1 (its storey 2 does not exist: NaN)
// except for every third sample of a stripe, where it is NaN (no finite value). Without
// pounding the values are 0.8 times those. Residual drift: 0.001 im u and 0.002 im u.
CampaignData campaign(bool with_new_arrays = true) {
  CampaignData c;
  c.path = "made-up.h5";
  c.samples = kSamples;
  c.buildings = 2;
  c.building_names = {"left", "right"};
  c.levels = {1.0, 2.0, 4.0};
  c.status.assign(kSamples, 0);
  c.scale.assign(kSamples, 1.0);
  auto array = [] { return FloorArray{kSamples, 2, 2, std::vector<double>(kSamples * 4, kNaN)}; };
  FloorArray dp = array(), df = array(), rp = array(), rf = array(), drift = array();
  for (std::size_t s = 0; s < kSamples; ++s) {
    const double im = im_of(s), u = u_of(s);
    c.im.push_back(im);
    const bool none = (s / 3) % 3 == 0;
    const double mu[4] = {0.5 * im * (0.5 + u), im * (0.5 + u), none ? kNaN : im * (0.5 + u), kNaN};
    for (std::size_t i = 0; i < 4; ++i) {
      dp.v[s * 4 + i] = mu[i];
      df.v[s * 4 + i] = 0.8 * mu[i];
      drift.v[s * 4 + i] = 0.01;
    }
    for (std::size_t i : {0u, 1u, 2u}) {
      rp.v[s * 4 + i] = 0.001 * double(i % 2 + 1) * im * u;
      rf.v[s * 4 + i] = 0.5 * rp.v[s * 4 + i];
    }
  }
  for (const char* name :
       {"peak_drift_ratio_pounding", "peak_drift_ratio_free", "peak_disp_pounding",
        "peak_disp_free", "peak_accel_pounding", "peak_accel_free"})
    c.floor_arrays[name] = drift;
  if (with_new_arrays) {
    c.floor_arrays["ductility_pounding"] = dp;
    c.floor_arrays["ductility_free"] = df;
    c.floor_arrays["residual_drift_pounding"] = rp;
    c.floor_arrays["residual_drift_free"] = rf;
  }
  c.peak_force = FloorArray{kSamples, 1, 2, std::vector<double>(kSamples * 2, 0.0)};
  return c;
}

FragilitySettings settings() {
  FragilitySettings s;
  s.drift_limits.clear();
  s.bootstrap.replicates = 20;
  return s;
}

const FragilityCurve& curve(const FragilityReport& r, std::size_t b, Edp e, double limit,
                            bool pounding) {
  for (const auto& c : r.curves)
    if (c.building == b && c.edp == e && c.limit == limit && c.pounding == pounding) return c;
  throw std::logic_error("no such curve");
}

long analyses(const FragilityCurve& c) {
  long n = 0;
  for (const auto& o : c.observed) n += o.n;
  return n;
}
long exceedances(const FragilityCurve& c) {
  long z = 0;
  for (const auto& o : c.observed) z += o.z;
  return z;
}

TEST(FragilityAnalysis, EdpsAreTheMaximumOverTheStoreys) {
  const CampaignData c = campaign();
  for (std::size_t s : {0u, 1u, 44u, 89u}) {
    const double im = im_of(s), u = u_of(s);
    EXPECT_EQ(edp_value(c, Edp::ductility, true, s, 0), im * (0.5 + u)) << s;
    EXPECT_EQ(edp_value(c, Edp::ductility, false, s, 0), 0.8 * (im * (0.5 + u))) << s;
    EXPECT_EQ(edp_value(c, Edp::residual_drift, true, s, 0), 0.002 * im * u) << s;
    EXPECT_EQ(edp_value(c, Edp::residual_drift, false, s, 1), 0.5 * (0.001 * im * u)) << s;
  }
  EXPECT_TRUE(std::isnan(edp_value(c, Edp::ductility, true, 0, 1)));  // no finite storey
  EXPECT_EQ(std::string(to_string(Edp::residual_drift)), "residual_drift");
  EXPECT_EQ(std::string(to_string(Edp::ductility)), "ductility");
  EXPECT_EQ(dataset_of(Edp::ductility, false), "ductility_free");
  EXPECT_EQ(dataset_of(Edp::drift, true), "peak_drift_ratio_pounding");
}

TEST(FragilityAnalysis, DuctilityCountsLeaveOutTheAnalysesWithoutAFiniteValue) {
  FragilitySettings s = settings();
  s.ductility_limits = {2.0};
  s.residual_drift_limits = {0.004};
  const FragilityReport r = analyse_fragility(campaign(), s);
  ASSERT_EQ(r.curves.size(), 2u * 2u * 2u);  // buildings x EDPs x (pounding, free)
  // Building 1 at mu > 2: none at 1 m/s^2, u > 0.5 (15) at 2, all 30 at 4; without pounding
  // 0.8 mu > 2: u > 0.75 (7) at 2 and u > 0.125 (26) at 4.
  const auto& b0 = curve(r, 0, Edp::ductility, 2.0, true);
  EXPECT_EQ(b0.left_out, 0u);
  EXPECT_EQ(analyses(b0), 90);
  EXPECT_EQ(exceedances(b0), 45);
  EXPECT_EQ(exceedances(curve(r, 0, Edp::ductility, 2.0, false)), 33);
  // Building 2: a third of the analyses has no finite ductility; of the other 20 per stripe,
  // 0, 10 and 20 exceed.
  const auto& b1 = curve(r, 1, Edp::ductility, 2.0, true);
  EXPECT_EQ(b1.left_out, 30u);
  ASSERT_EQ(b1.observed.size(), 3u);
  for (std::size_t j = 0; j < 3; ++j) {
    EXPECT_EQ(b1.observed[j].n, 20) << j;
    EXPECT_EQ(b1.observed[j].z, long(10 * j)) << j;
  }
  EXPECT_EQ(curve(r, 1, Edp::ductility, 2.0, false).left_out, 30u);
  // Residual drift 0.002 im u > 0.004 only at 4 m/s^2 with u > 0.5.
  const auto& rd = curve(r, 0, Edp::residual_drift, 0.004, true);
  EXPECT_EQ(rd.left_out, 0u);
  EXPECT_EQ(exceedances(rd), 15);
  EXPECT_EQ(exceedances(curve(r, 0, Edp::residual_drift, 0.004, false)), 0);
  // Shifts pair each EDP's pounding and free curves, as for drift.
  int shifts = 0;
  for (const auto& sh : r.shifts)
    shifts += sh.edp == Edp::ductility || sh.edp == Edp::residual_drift;
  EXPECT_EQ(shifts, 4);
}

TEST(FragilityAnalysis, AFileWithoutTheDatasetsFailsOnlyWhenTheirCurvesAreAskedFor) {
  const CampaignData old = campaign(false);
  FragilitySettings s = settings();
  s.drift_limits = {0.005};
  EXPECT_NO_THROW(analyse_fragility(old, s));
  s.ductility_limits = {2.0};
  try {
    analyse_fragility(old, s);
    ADD_FAILURE() << "ductility curves without ductility data";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("made-up.h5"), std::string::npos) << m;
    EXPECT_NE(m.find("/response/ductility_pounding"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  s.ductility_limits.clear();
  s.residual_drift_limits = {0.01};
  EXPECT_THROW(analyse_fragility(old, s), InputError);
}

// A continuous intensity: a free curve's observed fractions use its pounding curve's IM bins,
// so that observations.csv sets bin j of one beside bin j of the other, even when the pounding
// curve leaves analyses out (censored) and so bins fewer of them.
TEST(FragilityAnalysis, AFreeCurveIsBinnedInItsPoundingCurvesBins) {
  ExceedanceDesign d;  // no stripes: IM i + 1 for analysis i
  const std::size_t n = 400;
  std::vector<char> pounding(n), free(n);
  for (std::size_t i = 0; i < n; ++i) {
    d.im.push_back(double(i + 1));
    d.stripe.push_back(-1);
    free[i] = i % 3 == 0;
    pounding[i] = i >= 200 && i % 2 ? kLeftOut : char(i % 4 == 0);  // 100 of the strong left out
  }
  const auto p = observed_fractions(d, pounding), f = observed_fractions(d, free, &pounding);
  ASSERT_EQ(p.size(), 10u);  // 300 analyses: ten bins of 30
  ASSERT_EQ(f.size(), p.size());
  // The pounding bins: 30 analyses each, IM 1-30, 31-60, ..., 151-180, then IM 181-200 with
  // the odd 201-219 (the strong analyses with an even IM are left out), then from IM 221 on.
  // Bin k of the free curve counts its analyses from the pounding bin's smallest IM up to the
  // next one's: bins 0-5 the same 30 (IM 1-180), bin 6 the 40 of IM 181-220, ...
  long total = 0;
  for (std::size_t k = 0; k < f.size(); ++k) {
    EXPECT_EQ(p[k].n, 30) << k;
    if (k < 6) {
      EXPECT_EQ(f[k].n, 30) << k;
      EXPECT_NEAR(f[k].im, p[k].im, 1e-12 * p[k].im) << k;  // the same analyses
    }
    total += f[k].n;
  }
  EXPECT_EQ(f[6].n, 40);      // IM 181 to 220
  EXPECT_EQ(total, long(n));  // every free analysis in some bin
}

}  // namespace
}  // namespace pound

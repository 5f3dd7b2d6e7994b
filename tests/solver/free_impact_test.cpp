#include "solver/free_impact.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "contact/registry.hpp"
#include "contact/restitution.hpp"

namespace pound {
namespace {

ImpactResult impact(const std::string& model, double e, double k, double m1 = 2.0, double m2 = 3.0,
                    double v0 = 0.5) {
  ContactParameters p;
  p.k = k;
  p.e = e;
  p.m1 = m1;
  p.m2 = m2;
  p.v0_min = 1e-9;
  const auto law = find_contact_model(model, "test").make(p);
  FreeImpactSpec s{m1, m2, v0};
  IntegratorSettings integ;
  integ.rtol = 1e-11;
  integ.atol = 1e-14;
  return simulate_free_impact(*law, s, integ);
}

TEST(FreeImpact, MomentumIsConservedForEveryModel) {
  for (const auto& m : contact_models()) {
    const double k = m.stiffness_unit == "N/m^1.5" ? 1e9 : 1e6;
    const ImpactResult r = impact(m.name, 0.6, k);
    EXPECT_NEAR(2.0 * r.v1_after + 3.0 * r.v2_after, 2.0 * 0.5, 1e-12) << m.name;
    // And the impulse equals the momentum change of either body.
    EXPECT_NEAR(r.impulse_Ns, 2.0 * (0.5 - r.v1_after), 1e-10) << m.name;
    EXPECT_GT(r.e_eff, 0.0) << m.name;
  }
}

TEST(FreeImpact, LveReturnsNominalRestitutionAndDampedHalfPeriod) {
  for (double e : {0.2, 0.4, 0.8}) {
    const ImpactResult r = impact("lve", e, 1e6);
    EXPECT_NEAR(r.e_eff, e, 1e-7);
    const double mstar = 1.2, w = std::sqrt(1e6 / mstar), xi = lve_damping_ratio(e);
    EXPECT_NEAR(r.contact_duration_s, M_PI / (w * std::sqrt(1 - xi * xi)), 1e-9);
  }
}

TEST(FreeImpact, StereomechanicalAppliesRestitutionExactly) {
  const ImpactResult r = impact("stereomechanical", 0.4, 0.0);
  EXPECT_NEAR(r.e_eff, 0.4, 1e-14);
  EXPECT_NEAR(r.v1_after, 0.5 - 1.4 * 0.5 * 3.0 / 5.0, 1e-14);
}

TEST(FreeImpact, ExactHuntCrossleyReturnsNominalRestitutionWithinPointOnePercent) {
  for (const char* model : {"hc-linear", "hc-hertz"}) {
    for (double e : {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95}) {
      const double k = std::string(model) == "hc-hertz" ? 1e9 : 1e6;
      const ImpactResult r = impact(model, e, k);
      EXPECT_NEAR(r.e_eff / e, 1.0, 1e-3) << model << " e = " << e;
    }
  }
}

TEST(FreeImpact, MlveExactRelationReturnsNominalRestitution) {
  for (double e : {0.2, 0.5, 0.9}) EXPECT_NEAR(impact("mlve", e, 1e6).e_eff, e, 1e-6);
}

TEST(FreeImpact, ApproximateHertzdampOverestimatesRestitutionIncreasinglyAsEFalls) {
  // Lankarani-Nikravesh assumes e near 1 (Khatiwada et al. 2014): the returned e is too high,
  // and the error grows as e falls.
  const double err_hi = impact("hertzdamp", 0.9, 1e9).e_eff - 0.9;
  const double err_lo = impact("hertzdamp", 0.4, 1e9).e_eff - 0.4;
  EXPECT_GT(err_hi, 0.0);
  EXPECT_GT(err_lo, 3.0 * err_hi);
}

TEST(FreeImpact, ElasticHertzImpactDurationMatchesClosedForm) {
  // Hertz contact of two masses (Goldsmith 1960): delta_max = (5 m v0^2 / (4 k))^(2/5) and
  // duration 2.9432 delta_max / v0. With e = 1 the Hunt-Crossley damping vanishes.
  const double k = 1e9, v0 = 0.5, mstar = 1.2;
  const ImpactResult r = impact("hc-hertz", 1.0, k, 2.0, 3.0, v0);
  const double dmax = std::pow(5.0 * mstar * v0 * v0 / (4.0 * k), 0.4);
  EXPECT_NEAR(r.max_penetration_m / dmax, 1.0, 1e-9);
  EXPECT_NEAR(r.contact_duration_s / (2.9432 * dmax / v0), 1.0, 1e-4);
  // The constant is 0.8 Gamma(2/5) Gamma(1/2) / Gamma(9/10) = 2.94327518432...
  EXPECT_NEAR(r.contact_duration_s / (2.9432751843247 * dmax / v0), 1.0, 1e-8);
  EXPECT_NEAR(r.e_eff, 1.0, 1e-8);
  EXPECT_NEAR(r.peak_force_N / (k * std::pow(dmax, 1.5)), 1.0, 2e-3);  // sampled at step ends
}

}  // namespace
}  // namespace pound

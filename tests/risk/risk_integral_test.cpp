// The mean annual frequency integral: Cornell et al. (2002)'s closed form for a power-law hazard
// and a lognormal fragility, and a brute-force quadrature of integral P |d lambda| on a curve
// that is no power law (the Los Angeles curve of studies/hazard-los-angeles-pga.csv).
#include "risk/risk_integral.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fragility/lognormal_fit.hpp"
#include "motion/ground_motion.hpp"

namespace pound {
namespace {

// lambda = k0 x^-k [x in g] given by points from 0.05 to 2 g.
HazardCurve power_law(double k0, double k) {
  std::vector<double> x, r;
  for (double g : {0.05, 0.1, 0.3, 0.7, 2.0}) {
    x.push_back(g);
    r.push_back(k0 * std::pow(g, -k));
  }
  return make_hazard_curve(x, r, "pga", 0.0, "g", "power law");
}

TEST(RiskIntegral, MatchesCornellsClosedFormForAPowerLawHazard) {
  // nu = k0 theta^-k exp(k^2 beta^2 / 2) (Cornell, Jalayer, Hamburger & Foutch 2002, eq. 11
  // with the demand at the capacity), theta in the hazard's unit.
  for (double k : {1.5, 2.5, 3.0, 4.0})
    for (double beta : {0.2, 0.4, 0.6})
      for (double theta_g : {0.02, 0.3, 1.2, 3.0}) {  // inside and beyond the points
        const double k0 = 1e-4;
        const HazardCurve h = power_law(k0, k);
        const double exact = k0 * std::pow(theta_g, -k) * std::exp(0.5 * k * k * beta * beta);
        const double nu = mean_annual_frequency(h, theta_g * kGravity, beta);
        EXPECT_NEAR(nu, exact, 0.005 * exact)
            << "k " << k << " beta " << beta << " theta " << theta_g;
        EXPECT_NEAR(nu, exact, 1e-9 * exact);  // the segments integrate exactly
      }
}

TEST(RiskIntegral, AgreesWithQuadratureOnACurveThatIsNoPowerLaw) {
  // USGS 2008 NSHM, Los Angeles (studies/hazard-los-angeles-pga.csv): slopes from 0.3 to 15.
  const std::vector<double> x = {0.0025, 0.0045, 0.0075, 0.0113, 0.0169, 0.0253, 0.038,
                                 0.057,  0.0854, 0.128,  0.192,  0.288,  0.432,  0.649,
                                 0.973,  1.46,   2.19,   3.28,   4.92};
  const std::vector<double> r = {5.65751194e-01, 4.60546107e-01, 3.52846533e-01, 2.68589324e-01,
                                 1.96755851e-01, 1.38892991e-01, 9.39674734e-02, 6.03017357e-02,
                                 3.61972876e-02, 2.02823160e-02, 1.07017814e-02, 5.31887461e-03,
                                 2.43349159e-03, 9.74954193e-04, 3.19112149e-04, 7.58898203e-05,
                                 1.14905519e-05, 6.54934393e-07, 4.68235108e-09};
  const HazardCurve h = make_hazard_curve(x, r, "pga", 0.0, "g", "LA");
  for (double theta_g : {0.1, 0.5, 1.0, 2.0})
    for (double beta : {0.25, 0.5}) {
      // integral P(x) |d lambda / dx| dx by the midpoint rule in ln x, 400,000 intervals from
      // 1e-7 to 1e3 g: P from ln Phi, d lambda / d ln x = b lambda on each segment.
      const double lo = std::log(1e-7 * kGravity), hi = std::log(1e3 * kGravity);
      const int n = 400000;
      double q = 0.0;
      const auto segs = h.segments();
      for (int i = 0; i < n; ++i) {
        const double u = lo + (i + 0.5) * (hi - lo) / n;
        for (const auto& s : segs)
          if (u <= s.hi) {
            const double p = std::exp(log_normal_cdf((u - std::log(theta_g * kGravity)) / beta));
            q += p * (-s.b) * std::exp(s.ln_rate(u)) * (hi - lo) / n;
            break;
          }
      }
      const double nu = mean_annual_frequency(h, theta_g * kGravity, beta);
      EXPECT_NEAR(nu, q, 0.005 * q) << theta_g << " " << beta;
    }
}

// integral_{x_lo}^{x_hi} Phi(ln(x / theta) / beta) (-d lambda / dx) dx by composite Simpson in
// u = ln x with 20,000 intervals on each segment's part of [ln x_lo, ln x_hi] (finite bounds):
// on a segment, -d lambda / dx dx = -b lambda(u) du. The integrand is smooth on a segment.
double simpson_part(const HazardCurve& h, double theta, double beta, double x_lo, double x_hi) {
  const double mu = std::log(theta);
  auto f = [&](const HazardCurve::Segment& s, double u) {
    return std::exp(log_normal_cdf((u - mu) / beta)) * (-s.b) * std::exp(s.ln_rate(u));
  };
  double q = 0.0;
  for (const auto& s : h.segments()) {
    const double lo = std::max(s.lo, std::log(x_lo)), hi = std::min(s.hi, std::log(x_hi));
    if (!(hi > lo)) continue;
    const int n = 20000;  // even
    const double dh = (hi - lo) / n;
    double sum = f(s, lo) + f(s, hi);
    for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(s, lo + i * dh);
    q += sum * dh / 3.0;
  }
  return q;
}

// The part of nu from intensities in [x_lo, x_hi] is integral_lo^hi P |d lambda|, which by parts
// is integral_lo^hi lambda dP + P(lo) lambda(lo) - P(hi) lambda(hi) (risk_integral.hpp); the
// by-parts form alone (as computed before) is not that part, and the parts of a partition did
// not add up to nu. On the Los Angeles curve (18 segments, slopes 0.3-15), read from the file.
TEST(RiskIntegral, ThePartFromARangeOfIntensitiesIsThatRangesShareOfTheIntegral) {
  const HazardCurve h =
      read_hazard_curve(std::string(POUND_SOURCE_DIR) + "/studies/hazard-los-angeles-pga.csv");
  ASSERT_EQ(h.im.size(), 19u);
  const double inf = std::numeric_limits<double>::infinity();
  // Ranges in g: the default study's stripes (0.05-1.5), one segment exactly, one reaching
  // below the first point (0.0025 g) and one above the last (4.92 g): the extensions.
  const double ranges[][2] = {{0.05, 1.5}, {0.0854, 0.128}, {0.001, 0.3}, {0.2, 8.0}};
  for (double theta_g : {0.1, 0.5, 2.0})
    for (double beta : {0.3, 0.7})
      for (const auto& r : ranges) {
        const double theta = theta_g * kGravity, lo = r[0] * kGravity, hi = r[1] * kGravity;
        const double part = mean_annual_frequency(h, theta, beta, lo, hi);
        const double q = simpson_part(h, theta, beta, lo, hi);
        EXPECT_NEAR(part, q, 1e-6 * q)
            << "theta " << theta_g << " g, beta " << beta << ", " << r[0] << "-" << r[1] << " g";
        // Below, inside and above the range add up to nu: the boundary terms cancel.
        const double nu = mean_annual_frequency(h, theta, beta);
        const double below = mean_annual_frequency(h, theta, beta, 0.0, lo);
        const double above = mean_annual_frequency(h, theta, beta, hi, inf);
        EXPECT_NEAR(below + part + above, nu, 1e-12 * nu)
            << "theta " << theta_g << " g, beta " << beta << ", " << r[0] << "-" << r[1] << " g";
      }
  // An empty or reversed range holds nothing.
  EXPECT_EQ(mean_annual_frequency(h, kGravity, 0.5, 3.0, 3.0), 0.0);
  EXPECT_EQ(mean_annual_frequency(h, kGravity, 0.5, 3.0, 2.0), 0.0);
}

TEST(RiskIntegral, ProbabilityInYearsIsPoisson) {
  EXPECT_NEAR(probability_in_years(std::log(2.0) / 50.0, 50.0), 0.5, 1e-15);
  EXPECT_NEAR(probability_in_years(1e-9, 50.0), 5e-8 * (1 - 2.5e-8), 1e-22);  // nu T (1 - nu T / 2)
  EXPECT_EQ(probability_in_years(0.0, 50.0), 0.0);
  EXPECT_TRUE(std::isnan(probability_in_years(NAN, 50.0)));
}

}  // namespace
}  // namespace pound

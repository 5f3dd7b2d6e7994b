// Storey hysteresis laws on prescribed drift histories: the bilinear return map and its
// switching functions, Bouc-Wen against an independent integration of its ODE (and its closed
// form for n = 1), and the energy properties the solvers rely on.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/error.hpp"
#include "hysteresis/bilinear.hpp"
#include "hysteresis/bouc_wen.hpp"
#include "hysteresis/registry.hpp"

namespace pound {
namespace {

StoreyParameters storey(double b, double n = 2.0) {
  StoreyParameters p;
  p.k0 = 2e7;  // N/m
  p.Fy = 2e5;  // N: uy = 0.01 m
  p.b = b;
  p.bw_n = n;
  return p;
}

// The drift history d(t) = A sin(2 pi t / T) sampled at `per_cycle` points per cycle.
std::vector<double> sine_drift(double amplitude, int cycles, int per_cycle) {
  std::vector<double> d;
  for (int i = 0; i <= cycles * per_cycle; ++i)
    d.push_back(amplitude * std::sin(2.0 * M_PI * i / per_cycle));
  return d;
}

TEST(Bilinear, ReturnMapFollowsTheKinematicHardeningLoop) {
  // Load to 3 uy, unload to -3 uy, reload to 3 uy with b = 0.1: the shear follows
  // V = k0 d up to Fy, then Fy + b k0 (d - uy); unloading has slope k0 over 2 (1 - b) Fy of
  // shear (the bounding lines V = b k0 d +- (1 - b) Fy, Steel01 without isotropic hardening).
  const StoreyParameters p = storey(0.1);
  const BilinearStorey law;
  const double uy = p.uy(), k0 = p.k0, b = p.b, Fy = p.Fy;
  StoreyState s;
  double d0 = 0.0, V = 0.0;
  auto go = [&](double d1) {
    StoreyState t;
    V = law.advance(p, s, d0, d1, t);
    s = t;
    d0 = d1;
  };
  go(0.5 * uy);
  EXPECT_NEAR(V, 0.5 * Fy, 1e-9 * Fy);
  go(3 * uy);
  EXPECT_NEAR(V, Fy + b * k0 * 2 * uy, 1e-9 * Fy);
  go(1 * uy);  // unloading: elastic, 2 uy back from the peak
  EXPECT_NEAR(V, Fy + b * k0 * 2 * uy - k0 * 2 * uy, 1e-9 * Fy);
  go(-3 * uy);  // onto the lower bounding line
  EXPECT_NEAR(V, b * k0 * (-3 * uy) - (1 - b) * Fy, 1e-9 * Fy);
  // Dissipated: the EPP part's plastic work (1 - b) Fy times its plastic drift, 2 uy on the
  // way up and 4 uy on the way down (it starts unloading at z = +uy and must travel 2 uy
  // elastically before yielding again over the remaining 6 - 2 = 4 uy).
  EXPECT_NEAR(law.dissipated(p, s, d0, s.x), (1 - b) * Fy * (2 * uy + 4 * uy), 1e-9 * Fy * uy);
}

TEST(Bilinear, SwitchingFunctionsMarkYieldAndUnloading) {
  const StoreyParameters p = storey(0.02);
  const BilinearStorey law;
  StoreyState s;  // elastic from rest
  const double uy = p.uy();
  // Elastic branch: the function is (z^2 - uy^2) / (2 uy): negative inside, zero at +-uy.
  EXPECT_LT(law.switch_value(0, p, s, 0.5 * uy, 1.0, 0.0).value, 0.0);
  EXPECT_NEAR(law.switch_value(0, p, s, uy, 1.0, 0.0).value, 0.0, 1e-18);
  EXPECT_NEAR(law.switch_value(0, p, s, -uy, 1.0, 0.0).value, 0.0, 1e-18);
  EXPECT_GT(law.switch_value(0, p, s, 1.01 * uy, 1.0, 0.0).value, 0.0);
  // Its rate is z dd / uy (the time derivative of the function).
  EXPECT_DOUBLE_EQ(law.switch_value(0, p, s, 0.5 * uy, 0.2, 0.0).rate, 0.5 * 0.2);
  law.on_switch(0, p, s, uy, nullptr);
  EXPECT_EQ(s.branch, 1);
  // Yielding branch: the function is -dd, so the switch is where the drift rate reverses.
  EXPECT_LT(law.switch_value(0, p, s, 2 * uy, 0.3, 0.0).value, 0.0);
  EXPECT_GT(law.switch_value(0, p, s, 2 * uy, -0.3, 0.0).value, 0.0);
  EXPECT_NEAR(law.shear(p, s, 2 * uy, nullptr), p.Fy + p.b * p.k0 * uy, 1e-6);
  law.on_switch(0, p, s, 2 * uy, nullptr);
  EXPECT_EQ(s.branch, 0);
  EXPECT_NEAR(law.dissipated(p, s, 2 * uy, nullptr), (1 - p.b) * p.Fy * uy, 1e-9);
  // Unloading by k0 from the peak.
  EXPECT_NEAR(law.shear(p, s, 1.5 * uy, nullptr), p.Fy + p.b * p.k0 * uy - p.k0 * 0.5 * uy, 1e-6);
}

TEST(Bilinear, ContinuousAndIncrementalFormsAgreeAndEnergyIsNonNegative) {
  // The same sinusoidal drift, once by advance() at every sample and once in the continuous
  // form with its switches applied where the sampled function crosses zero (exact here: the
  // drift is monotone between samples and both forms are piecewise linear in d).
  const StoreyParameters p = storey(0.05);
  const BilinearStorey law;
  const auto d = sine_drift(4 * p.uy(), 3, 4000);
  StoreyState inc, cont;
  double last_e = 0.0;
  for (std::size_t i = 1; i < d.size(); ++i) {
    StoreyState t;
    const double V = law.advance(p, inc, d[i - 1], d[i], t);
    inc = t;
    const double dd = d[i] - d[i - 1];
    if (law.switch_value(0, p, cont, d[i], dd, 0.0).value > 0.0)
      law.on_switch(
          0, p, cont,
          cont.branch == 0 ? std::copysign(p.uy(), dd) + (cont.d_anchor - cont.z_anchor) : d[i - 1],
          nullptr);
    EXPECT_NEAR(law.shear(p, cont, d[i], nullptr), V, 1e-6 * p.Fy) << i;
    const double e = law.dissipated(p, inc, d[i], nullptr);
    EXPECT_GE(e, last_e - 1e-9);
    last_e = e;
    // V^2 <= 2 k0 U (sears/translation_bound.hpp relies on it).
    EXPECT_LE(V * V, 2 * p.k0 * law.stored(p, inc, d[i], nullptr) * (1 + 1e-12));
  }
  EXPECT_NEAR(law.dissipated(p, cont, d.back(), nullptr), last_e, 1e-6 * last_e);
}

// dz/dt of Bouc-Wen written out from Wen (1976) with beta = gamma = 1 / (2 uy^n), for the
// reference integration below (independent of the law's code).
double wen_rate(double z, double dd, double uy, double n) {
  const double g = 1.0 / (2.0 * std::pow(uy, n));
  const double sgn = dd * z > 0 ? 1.0 : (dd * z < 0 ? -1.0 : 0.0);
  return dd * (1.0 - std::pow(std::fabs(z), n) * (g + g * sgn));
}

TEST(BoucWen, SinusoidalDriftLoopMatchesAReferenceIntegrationAndZStaysBelowUy) {
  for (double n : {1.0, 2.0, 5.0}) {
    const StoreyParameters p = storey(0.05, n);
    const BoucWenStorey law;
    const double uy = p.uy(), A = 3 * uy, T = 1.0;
    // Reference: classical Runge-Kutta in time with 200,000 steps per cycle on
    // z' = wen_rate(z, d'(t)), d(t) = A sin(2 pi t / T).
    const int cycles = 2, fine = 200000, coarse = 400;
    std::vector<double> z_ref(cycles * coarse + 1);
    double z = 0.0, zmax = 0.0;
    const double h = T / fine;
    auto ddot = [&](double t) { return A * 2 * M_PI / T * std::cos(2 * M_PI * t / T); };
    for (int i = 0; i < cycles * fine; ++i) {
      if (i % (fine / coarse) == 0) z_ref[i / (fine / coarse)] = z;
      const double t = i * h;
      const double k1 = wen_rate(z, ddot(t), uy, n);
      const double k2 = wen_rate(z + 0.5 * h * k1, ddot(t + 0.5 * h), uy, n);
      const double k3 = wen_rate(z + 0.5 * h * k2, ddot(t + 0.5 * h), uy, n);
      const double k4 = wen_rate(z + h * k3, ddot(t + h), uy, n);
      z += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      zmax = std::max(zmax, std::fabs(z));
    }
    z_ref.back() = z;
    EXPECT_LE(zmax, uy) << "n = " << n;
    // The law's incremental form on 400 samples per cycle.
    const auto d = sine_drift(A, cycles, coarse);
    StoreyState s;
    double worst = 0.0, law_zmax = 0.0;
    for (std::size_t i = 1; i < d.size(); ++i) {
      StoreyState t;
      const double V = law.advance(p, s, d[i - 1], d[i], t);
      s = t;
      worst = std::max(worst, std::fabs(s.x[0] - z_ref[i]));
      law_zmax = std::max(law_zmax, std::fabs(s.x[0]));
      EXPECT_NEAR(V, p.k0 * (p.b * d[i] + (1 - p.b) * s.x[0]), 1e-9 * p.Fy);
    }
    // The loop's sampling points lie on the drift extrema, so the monotone-path integration
    // is exact up to the Runge-Kutta error in d.
    EXPECT_LT(worst, 1e-5 * uy) << "n = " << n;
    EXPECT_LE(law_zmax, uy) << "n = " << n;
    EXPECT_GT(law_zmax, 0.9 * uy) << "n = " << n;  // it did yield
    // The continuous form's rates are the same ODE.
    double x[2] = {0.7 * uy, 0.0}, dx[2];
    law.rates(p, s, 0.0, -0.3, x, dx);
    EXPECT_NEAR(dx[0], wen_rate(x[0], -0.3, uy, n), 1e-12);
    law.rates(p, s, 0.0, 0.3, x, dx);
    EXPECT_NEAR(dx[0], wen_rate(x[0], 0.3, uy, n), 1e-12);
    EXPECT_GE(dx[1], 0.0);
  }
}

TEST(BoucWen, ExponentOneHasTheClosedFormLoadingCurve) {
  // n = 1, beta = gamma = 1 / (2 uy): loading from z0 >= 0, dz/dd = 1 - z / uy, so
  // z = uy - (uy - z0) exp(-(d - d0) / uy); unloading (dd < 0, z > 0) has dz/dd = 1.
  const StoreyParameters p = storey(0.0, 1.0);
  const BoucWenStorey law;
  const double uy = p.uy();
  StoreyState s, t;
  law.advance(p, s, 0.0, 2.5 * uy, t);
  EXPECT_NEAR(t.x[0], uy * (1 - std::exp(-2.5)), 1e-8 * uy);
  // Hysteretic energy along the way: integral of k0 z (1 - dz/dd) dd = k0 integral z^2/uy dd.
  const double zf = t.x[0];
  // With w = z/uy: dd = uy dw / (1 - w), so the integral is k0 uy^2 integral w^2 / (1 - w) dw.
  const double wf = zf / uy;
  const double exact = p.k0 * uy * uy * (-std::log(1 - wf) - wf - 0.5 * wf * wf);
  EXPECT_NEAR(t.x[1], exact, 1e-6 * exact);
  s = t;
  law.advance(p, s, 2.5 * uy, 2.0 * uy, t);  // unloading by 0.5 uy
  EXPECT_NEAR(t.x[0], zf - 0.5 * uy, 1e-12 * uy);
  EXPECT_NEAR(t.x[1], s.x[1], 1e-12 * exact);  // no dissipation while unloading
}

TEST(StoreyLawRegistry, NamesTheValidLawsForAnUnknownOne) {
  EXPECT_STREQ(find_storey_law("bouc-wen", "here").name(), "bouc-wen");
  try {
    find_storey_law("takeda", "study.ini:3: key 'building1.hysteresis'");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "study.ini:3: key 'building1.hysteresis': unknown hysteresis law 'takeda'; valid: "
              "elastic, bilinear, bouc-wen, imk");
  }
}

}  // namespace
}  // namespace pound

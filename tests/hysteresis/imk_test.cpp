// The peak-oriented modified Ibarra-Medina-Krawinkler storey (hysteresis/imk.hpp) on prescribed
// drift histories: its backbone in closed form in both forms, cyclic strength deterioration
// against the recursion of beta computed here from the energies the law reports, the bilinear
// limit (and an independent peak-oriented Clough reference for cycles), the energy bookkeeping
// against the work integral, the continuous form against advance(), and every failure.
#include "hysteresis/imk.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "hysteresis/bilinear.hpp"

namespace pound {
namespace {

// A storey of k0 = 2e7 N/m, Fy = 2e5 N (uy = 0.01 m), h = 3 m, Fc / Fy = 1.2, theta_p = 0.06
// (cap at 0.19 m), theta_pc = 0.1 (Kpc = 8e5 N/m), lambda = 100, c = 1, Fr = 0, no theta_u.
StoreyParameters imk_storey() {
  StoreyParameters p;
  p.k0 = 2e7;
  p.Fy = 2e5;
  p.h = 3.0;
  p.cap_strength_ratio = 1.2;
  p.plastic_drift_ratio = 0.06;
  p.post_cap_drift_ratio = 0.1;
  p.residual_strength_ratio = 0.0;
  p.energy_capacity = 100.0;
  p.energy_exponent = 1.0;
  return p;
}

// The backbone of imk.hpp in closed form, toward either side, at drift d [m].
double backbone(const StoreyParameters& p, double d) {
  const double s = d < 0 ? -1.0 : 1.0, x = std::fabs(d), uy = p.uy();
  const double fc = p.cap_strength_ratio * p.Fy, dc = uy + p.plastic_drift_ratio * p.h;
  const double kp = (fc - p.Fy) / (p.plastic_drift_ratio * p.h);
  const double kpc = fc / (p.post_cap_drift_ratio * p.h), fr = p.residual_strength_ratio * p.Fy;
  if (x >= p.ultimate_drift_ratio * p.h) return 0.0;  // failed on reaching theta_u h
  if (x <= uy) return s * p.k0 * x;
  if (x <= dc) return s * (p.Fy + kp * (x - uy));
  return s * std::max(fc - kpc * (x - dc), fr);
}

// The incremental form along a path: advance() from the committed state to each drift.
struct Incremental {
  const StoreyLaw& law;
  const StoreyParameters& p;
  StoreyState s;
  double d = 0.0;
  double go(double d1) {
    StoreyState t;
    const double v = law.advance(p, s, d, d1, t);
    s = t;
    d = d1;
    return v;
  }
};

// The continuous form driven along a piecewise-linear drift path as the row solver drives it:
// at a turning point the switches already across (the drift rate reversing) are applied; along
// a segment the earliest switching function to rise through zero is located (bisection on the
// drift: along a monotone segment every function is exact in d) and applied just across.
struct Continuous {
  const StoreyLaw& law;
  const StoreyParameters& p;
  StoreyState s;
  double d = 0.0;
  int events = 0;

  double value(int i, double x, double rate) const {
    return law.switch_value(i, p, s, x, rate, 0.0).value;
  }
  void apply_across(double x, double rate) {
    for (int guard = 0; guard < 100; ++guard) {
      int fired = -1;
      for (int i = 0; i < law.switches() && fired < 0; ++i)
        if (value(i, x, rate) > 0.0) fired = i;
      if (fired < 0) return;
      law.on_switch(fired, p, s, x, nullptr);
      ++events;
    }
    ADD_FAILURE() << "switches keep firing at " << x;
  }
  double go(double d1) {
    if (d1 == d) return law.shear(p, s, d, nullptr);
    const double rate = d1 > d ? 1.0 : -1.0;  // m/s along the segment
    apply_across(d, rate);
    double a = d;
    for (int guard = 0; guard < 1000; ++guard) {
      double first = d1;
      int which = -1;
      for (int i = 0; i < law.switches(); ++i) {
        if (!(value(i, d1, rate) > 0.0)) continue;
        double lo = a, hi = d1;  // value(lo) <= 0 < value(hi)
        for (int it = 0; it < 200 && std::fabs(hi - lo) > 1e-15 * (1.0 + std::fabs(hi)); ++it) {
          const double mid = 0.5 * (lo + hi);
          (value(i, mid, rate) > 0.0 ? hi : lo) = mid;
        }
        if (rate * (hi - first) < 0.0 || which < 0) {
          first = hi;
          which = i;
        }
      }
      if (which < 0) break;
      law.on_switch(which, p, s, first, nullptr);
      ++events;
      a = first;
    }
    d = d1;
    return law.shear(p, s, d, nullptr);
  }
};

// A drift path through the turning points, `per_unit` samples per metre of travel at least.
std::vector<double> path(const std::vector<double>& turns, double step) {
  std::vector<double> out;
  double from = 0.0;
  for (double to : turns) {
    const int n = std::max(1, static_cast<int>(std::ceil(std::fabs(to - from) / step)));
    for (int i = 1; i <= n; ++i) out.push_back(from + (to - from) * i / n);
    from = to;
  }
  return out;
}

TEST(Imk, MonotonicPushFollowsTheBackboneExactlyInBothForms) {
  // Elastic to (uy, Fy), post-yield to the cap (0.19 m, 2.4e5 N), post-capping down to
  // Fr = 0.3 Fy at 0.415 m, residual to theta_u h = 0.6 m, nothing beyond; both directions.
  StoreyParameters p = imk_storey();
  p.residual_strength_ratio = 0.3;
  p.ultimate_drift_ratio = 0.2;
  const ImkStorey law;
  for (double sign : {1.0, -1.0}) {
    Incremental inc{law, p, {}};
    Continuous cont{law, p, {}};
    for (int i = 1; i <= 8000; ++i) {
      const double d = sign * 0.8 * i / 8000;
      const double expected = backbone(p, d);
      const double v = inc.go(d), vc = cont.go(d);
      ASSERT_NEAR(v, expected, 1e-9 * p.Fy) << d;
      ASSERT_NEAR(vc, expected, 1e-9 * p.Fy) << d;
      EXPECT_EQ(law.failed(p, inc.s), std::fabs(d) >= p.ultimate_drift_ratio * p.h) << d;
      EXPECT_EQ(law.failed(p, cont.s), std::fabs(d) >= p.ultimate_drift_ratio * p.h) << d;
    }
    EXPECT_EQ(cont.events, 4);  // the corners: yield, cap, residual, theta_u
  }
  // One step over every corner gives the same as the path of small steps.
  for (double d : {0.005, 0.1, 0.3, 0.5, 0.7, -0.3}) {
    StoreyState t;
    EXPECT_NEAR(law.advance(p, StoreyState{}, 0.0, d, t), backbone(p, d), 1e-9 * p.Fy) << d;
  }
  // Fr = 0: the post-capping line reaches zero shear at 0.19 + 0.3 = 0.49 m and the storey
  // fails there (no theta_u).
  const StoreyParameters q = imk_storey();
  StoreyState t;
  EXPECT_NEAR(law.advance(q, StoreyState{}, 0.0, 0.48, t), 2.4e5 - 8e5 * 0.29, 1e-6);
  EXPECT_FALSE(law.failed(q, t));
  StoreyState u;
  EXPECT_EQ(law.advance(q, t, 0.48, 0.5, u), 0.0);
  EXPECT_TRUE(law.failed(q, u));
}

// The hysteretic energy the law reports at drift d of state s [J].
double e_h(const StoreyLaw& law, const StoreyParameters& p, const StoreyState& s, double d) {
  return law.dissipated(p, s, d, nullptr);
}

TEST(Imk, ConstantAmplitudeCyclesDeteriorateAsTheRecursionOfBeta) {
  // Cycles at +-5 uy; at every new excursion (the shear changing sign) this test computes
  // beta = (E_i / (E_t - sum E_j))^c from the hysteretic energy the law reports (constant on the
  // unloading line, so its value at the last sample before the sign change is the value at the
  // crossing) and deteriorates its own copy of the backbone of that side (once the side has
  // yielded) by the rules of Ibarra et al. (2005): Fy and Kp times (1 - beta), the
  // post-capping intercept times (1 - beta), the global peak drift times (1 + beta). At every
  // reversal the unloading slope the law shows must be Ku (1 - beta_K), beta_K from the energy
  // less V^2 / (2 Ku). A final push then meets the deteriorated post-yield and post-capping
  // lines.
  StoreyParameters p = imk_storey();
  p.energy_capacity = 100.0;
  p.energy_exponent = 1.3;
  const ImkStorey law;
  const double uy = p.uy(), A = 5 * uy, et = p.energy_capacity * p.Fy * uy, c = 1.3;
  ASSERT_EQ(p.energy_exponent, c);
  const double kpc = 1.2 * p.Fy / (0.1 * 3.0);
  struct Bb {
    double fy, kp, dcap, fcap, dglobal;
    bool yielded;
  };
  const double kp0 = 0.2 * p.Fy / (0.06 * 3.0);
  Bb side[2] = {{p.Fy, kp0, uy + 0.18, 1.2 * p.Fy, uy, false},
                {p.Fy, kp0, uy + 0.18, 1.2 * p.Fy, uy, false}};  // [0] +, [1] -
  double e_excursion = 0.0, ku = p.k0;
  int excursions = 0, checked_slopes = 0;
  Incremental inc{law, p, {}};
  const auto d = path({A, -A, A, -A, A, -A, A, -A, A, -A, A, -A}, uy / 200);
  double d_prev = 0.0, v_prev = 0.0, e_prev = 0.0;
  for (std::size_t i = 0; i < d.size(); ++i) {
    const bool turned = i >= 2 && (d[i] - d[i - 1]) * (d[i - 1] - d[i - 2]) < 0.0;
    if (turned) {                        // unloading from the turning point d_prev: Ku (1 - beta_K)
      Bb& b = side[v_prev > 0 ? 0 : 1];  // the turning point is the global peak beyond it
      b.dglobal = std::max(b.dglobal, std::fabs(d_prev));
      const double eh = e_prev;  // dissipated() counts without the stored V^2 / (2 Ku)
      const double bk = std::pow(std::max(0.0, eh - e_excursion) / (et - eh), c);
      ku *= 1 - bk;
    }
    const double v = inc.go(d[i]);
    if (turned) {
      EXPECT_NEAR((v - v_prev) / (d[i] - d_prev), ku, 1e-7 * p.k0) << i;
      ++checked_slopes;
    }
    if (v * v_prev < 0.0) {  // a new excursion toward n
      const int n = v > 0 ? 0 : 1;
      const double eh = e_prev;  // constant along the unloading line
      const double beta = std::pow((eh - e_excursion) / (et - eh), c);
      e_excursion = eh;
      Bb& b = side[n];
      if (b.yielded) {
        b.fy *= 1 - beta;
        b.kp *= 1 - beta;
        const double uyn = b.fy / p.k0;
        const double intercept = (1 - beta) * (b.fcap + kpc * b.dcap);
        b.dcap = (intercept - (b.fy - b.kp * uyn)) / (b.kp + kpc);
        b.fcap = b.fy + b.kp * (b.dcap - uyn);
        b.dglobal *= 1 + beta;
      }
      ++excursions;
    }
    if (d[i] > uy) side[0].yielded = true;
    if (d[i] < -uy) side[1].yielded = true;
    d_prev = d[i];
    v_prev = v;
    e_prev = e_h(law, p, inc.s, d[i]);
  }
  EXPECT_EQ(excursions, 11);
  EXPECT_EQ(checked_slopes, 11);
  EXPECT_FALSE(law.failed(p, inc.s));
  // The force at the turning points has fallen by a tenth or more: deterioration is tested.
  EXPECT_LT(side[0].fy, 0.9 * p.Fy);
  // Final push toward + (one more excursion): past the amplified global peak onto the
  // deteriorated post-yield line, then past the moved cap onto the post-capping line.
  double beta = 0.0;
  for (double x = -A + uy / 200; x <= 0.3; x += uy / 200) {
    const double v = inc.go(x);
    if (v * v_prev < 0.0) {
      beta = std::pow((e_prev - e_excursion) / (et - e_prev), c);
      Bb& b = side[0];
      b.fy *= 1 - beta;
      b.kp *= 1 - beta;
      const double uyn = b.fy / p.k0;
      const double intercept = (1 - beta) * (b.fcap + kpc * b.dcap);
      b.dcap = (intercept - (b.fy - b.kp * uyn)) / (b.kp + kpc);
      b.fcap = b.fy + b.kp * (b.dcap - uyn);
      b.dglobal *= 1 + beta;
    }
    v_prev = v;
    e_prev = e_h(law, p, inc.s, x);
    const Bb& b = side[0];
    if (beta > 0.0 && x > b.dglobal + uy / 100 && x < b.dcap) {
      EXPECT_NEAR(v, b.fy + b.kp * (x - b.fy / p.k0), 1e-6 * p.Fy) << x;
    } else if (beta > 0.0 && x > b.dcap && x > b.dglobal + uy / 100) {
      EXPECT_NEAR(v, b.fcap - kpc * (x - b.dcap), 1e-6 * p.Fy) << x;
    }
  }
  EXPECT_GT(beta, 0.01);
  EXPECT_GT(side[0].dglobal, 1.1 * A);   // the accelerated reloading moved the target
  EXPECT_LT(side[0].dcap, 0.19 - 0.01);  // and the cap came nearer
}

// An independent peak-oriented bilinear (Clough) loop for cycles that cross zero every half
// cycle: unloading along k0 to zero shear at u0, reloading straight toward the largest
// excursion of that side (initially the yield point), then the bilinear backbone.
struct Clough {
  double k0, fy, kp;
  double peak_d[2], peak_v[2];  // [0] +, [1] -
  double from_d = 0.0, from_v = 0.0;
  bool first = true;
  // The shear along the half cycle from the last turn toward the turn at `to`.
  double at(double d, double to) const {
    const int n = to > 0 ? 0 : 1;
    const double s = to > 0 ? 1.0 : -1.0;
    const double bb = s * (fy + kp * (std::fabs(d) - fy / k0));
    if (first) return std::fabs(d) <= fy / k0 ? k0 * d : bb;
    const double u0 = from_d - from_v / k0;
    if (s * (d - u0) <= 0.0) return from_v + k0 * (d - from_d);
    if (s * (d - peak_d[n]) <= 0.0) return peak_v[n] * (d - u0) / (peak_d[n] - u0);
    return bb;
  }
  void turn(double d, double v) {
    const int n = d > 0 ? 0 : 1;
    if (std::fabs(d) >= std::fabs(peak_d[n])) {
      peak_d[n] = d;
      peak_v[n] = v;
    }
    from_d = d;
    from_v = v;
    first = false;
  }
};

TEST(Imk, LargeCapacitiesGiveTheBilinearLawAndPeakOrientedLoops) {
  // theta_p = theta_pc = 10 and lambda = 1e12 with Fc chosen for Kp = b k0: no cap, no
  // deterioration within reach. The monotonic push and the first unloading (down to zero
  // shear) are the existing bilinear law's with hardening b. The cycles after that differ from
  // kinematic hardening by design (the IMK law is peak-oriented): they are checked against the
  // independent Clough reference above.
  const double b = 0.03;
  StoreyParameters p = imk_storey();
  p.b = b;
  p.plastic_drift_ratio = 10.0;
  p.post_cap_drift_ratio = 10.0;
  p.cap_strength_ratio = 1.0 + b * p.k0 * p.plastic_drift_ratio * p.h / p.Fy;
  p.energy_capacity = 1e12;
  const ImkStorey imk;
  const BilinearStorey bilinear;
  const double uy = p.uy();
  Incremental a{imk, p, {}}, r{bilinear, p, {}};
  for (double d : path({20 * uy}, uy / 50)) ASSERT_NEAR(a.go(d), r.go(d), 1e-9 * p.Fy) << d;
  int unloading = 0;
  for (double d = 20 * uy - uy / 50;; d -= uy / 50, ++unloading) {
    const double v = a.go(d);
    if (v < 0.0) break;  // beyond zero shear the IMK law reloads toward (-uy, -Fy)
    ASSERT_NEAR(v, r.go(d), 1e-9 * p.Fy) << d;
  }
  EXPECT_GT(unloading, 70);
  // Cycles of growing amplitude, two at each, against Clough's rules.
  Incremental c{imk, p, {}};
  Clough ref{p.k0, p.Fy, b * p.k0, {uy, -uy}, {p.Fy, -p.Fy}};
  double from = 0.0;
  int compared = 0;
  for (double amp : {2.0, 2.0, 4.0, 4.0, 6.0, 6.0, 9.0, 9.0}) {
    for (double to : {amp * uy, -amp * uy}) {
      double v = 0.0;
      for (double d : path({to - from}, uy / 40)) {
        v = c.go(from + d);
        ASSERT_NEAR(v, ref.at(from + d, to), 1e-6 * p.Fy) << from + d << " toward " << to;
        ++compared;
      }
      ref.turn(to, v);
      from = to;
    }
  }
  EXPECT_GT(compared, 4000);
}

// A random drift path of `turns` turning points within +-amplitude [m] (partial reversals and
// zero crossings in any order).
std::vector<double> random_turns(int turns, double amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amplitude, amplitude);
  std::vector<double> t;
  double last = 0.0;
  for (int i = 0; i < turns; ++i) {
    double x = u(rng);
    if (std::fabs(x - last) < 0.05 * amplitude) x = -last;
    t.push_back(x);
    last = x;
  }
  return t;
}

TEST(Imk, DissipatedPlusStoredIsTheWorkAndDissipationFallsOnlyWhereKuIsReduced) {
  // Along random cyclic paths E_h + U equals the work of the shear (trapezoidal rule on steps of
  // uy / 1000: exact on every line, off by k uy^2 / 8e6 at each corner). E_h never decreases
  // except at a reduction of Ku at a reversal, where it falls by V^2 (1/Ku' - 1/Ku) / 2 (no
  // work done, U rising as much); those falls are measured here. V^2 <= 2 k0 U throughout.
  StoreyParameters p = imk_storey();
  p.energy_capacity = 80.0;
  p.residual_strength_ratio = 0.2;
  const ImkStorey law;
  const double uy = p.uy();
  double worst_fall_fraction = 0.0, worst_other_fall = 0.0, worst_balance = 0.0;
  int falls = 0;
  for (unsigned seed : {1u, 2u, 3u}) {
    Incremental inc{law, p, {}};
    const auto d = path(random_turns(40, 12 * uy, seed), uy / 1000);
    double w = 0.0, v_prev = 0.0, d_prev = 0.0, e_prev = 0.0, ku_prev = p.k0;
    for (std::size_t i = 0; i < d.size(); ++i) {
      const double v = inc.go(d[i]);
      w += 0.5 * (v + v_prev) * (d[i] - d_prev);
      const double e = e_h(law, p, inc.s, d[i]), u = law.stored(p, inc.s, d[i], nullptr);
      worst_balance = std::max(worst_balance, std::fabs(e + u - w));
      EXPECT_LE(v * v, 2 * p.k0 * u * (1 + 1e-12) + 1e-12) << i;
      const double ku = ImkStorey::unloading_stiffness(p, inc.s);
      if (ku < ku_prev) {  // a reversal reduced Ku in this step
        // The fall at the reversal: V_r^2 (1/Ku' - 1/Ku) / 2 at the turning point d_prev.
        const double jump = 0.5 * v_prev * v_prev * (1 / ku - 1 / ku_prev);
        EXPECT_NEAR(e_prev - e, jump, 1e-6 * jump + 1e-3) << i;
        worst_fall_fraction = std::max(worst_fall_fraction, jump / std::max(e_prev, 1e-30));
        ++falls;
      } else {
        worst_other_fall = std::max(worst_other_fall, e_prev - e);
      }
      v_prev = v;
      d_prev = d[i];
      e_prev = e;
      ku_prev = ku;
    }
    EXPECT_FALSE(law.failed(p, inc.s)) << seed;
    EXPECT_GT(e_prev, 10 * p.Fy * uy) << seed;
  }
  EXPECT_LT(worst_balance, 1e-9 * p.Fy * 12 * uy * 100);
  EXPECT_LT(worst_other_fall, 1e-9 * p.Fy * uy);
  EXPECT_GT(falls, 50);
  // The falls are small against the energy dissipated before them (reported in the docs).
  EXPECT_LT(worst_fall_fraction, 0.02);
  RecordProperty("largest_fall_fraction_of_E_h", std::to_string(worst_fall_fraction));
}

TEST(Imk, ContinuousFormAndAdvanceAgreeOnTheSamePath) {
  // Random cyclic paths (partial reversals, zero crossings, the post-capping and residual
  // branches) through both forms: the same shear, energies and state at every sample.
  StoreyParameters p = imk_storey();
  p.energy_capacity = 60.0;
  p.residual_strength_ratio = 0.25;
  p.plastic_drift_ratio = 0.02;  // cap at 0.07 m: the paths reach the post-capping branch
  const ImkStorey law;
  const double uy = p.uy();
  for (unsigned seed : {11u, 12u, 13u, 14u}) {
    Incremental inc{law, p, {}};
    Continuous cont{law, p, {}};
    int samples = 0;
    for (double d : path(random_turns(30, 15 * uy, seed), uy / 20)) {
      const double v = inc.go(d), vc = cont.go(d);
      ASSERT_NEAR(vc, v, 1e-9 * p.Fy) << seed << " at " << d;
      ASSERT_NEAR(law.dissipated(p, cont.s, d, nullptr), e_h(law, p, inc.s, d),
                  1e-9 * p.Fy * uy * 100)
          << seed;
      ASSERT_EQ(cont.s.branch, inc.s.branch) << seed << " at " << d;
      ++samples;
    }
    EXPECT_GT(cont.events, 25) << seed;
    EXPECT_GT(samples, 5000);
  }
}

TEST(Imk, EveryFailureLeavesTheStoreyWithoutShearForEver) {
  const ImkStorey law;
  // Each case: a path that must fail (at the first sample past drift `expected`), then more drift
  // both ways with zero shear and nothing stored; e_h_before is the law's hysteretic energy at
  // the last sample before the failure.
  auto check = [&](const StoreyParameters& p, const std::vector<double>& turns, double expected,
                   const char* what, double* e_h_before = nullptr) {
    for (int form = 0; form < 2; ++form) {
      Incremental inc{law, p, {}};
      Continuous cont{law, p, {}};
      bool failed = false;
      double at = 0.0, e_before = 0.0;
      for (double d : path(turns, p.uy() / 20)) {
        const double v = form == 0 ? inc.go(d) : cont.go(d);
        const StoreyState& s = form == 0 ? inc.s : cont.s;
        if (failed) {
          ASSERT_EQ(v, 0.0) << what << " at " << d;
          ASSERT_TRUE(law.failed(p, s)) << what;
          ASSERT_EQ(law.stored(p, s, d, nullptr), 0.0);
        } else if (law.failed(p, s)) {
          failed = true;
          at = d;
          EXPECT_EQ(v, 0.0) << what;
        } else {
          e_before = law.dissipated(p, s, d, nullptr);
        }
      }
      EXPECT_TRUE(failed) << what << " (form " << form << ")";
      EXPECT_NEAR(at, expected, 1.01 * p.uy() / 20) << what << " (form " << form << ")";
      if (e_h_before) *e_h_before = e_before;
    }
  };
  StoreyParameters p = imk_storey();
  p.energy_capacity = 1e6;  // no cyclic deterioration to speak of
  p.residual_strength_ratio = 0.3;
  p.ultimate_drift_ratio = 0.1;  // 0.3 m, beyond the cap (0.19 m)
  check(p, {0.25, -0.1, 0.35, -0.35}, 0.3, "theta_u on the residual branch");
  p.residual_strength_ratio = 0.0;  // the post-capping line reaches zero at 0.19 + 0.3 = 0.49 m
  p.ultimate_drift_ratio = std::numeric_limits<double>::infinity();
  check(p, {0.3, -0.05, 0.6, -0.6}, 0.49, "residual branch at zero shear");
  // lambda = 100: the excursion after 0.3 m and back deteriorates the + backbone (beta about
  // 0.35) so far that the amplified global peak (0.3 x 1.35 m) has no strength left: the
  // storey fails where the shear crosses zero on the way back.
  p.energy_capacity = 100.0;
  check(p, {0.3, -0.05, 0.6, -0.6}, -0.0205, "no strength at the target peak");
  // Energy: the first unloading from 0.04 m (E_h about 6e3 J) with E_t = lambda Fy uy.
  const double fy_uy = p.Fy * p.uy();
  double e_before = 0.0;
  p.energy_capacity = 4.0;  // E_t = 8e3 J: beta_K = E_h / (E_t - E_h) above 1
  check(p, {0.04, -0.04, 0.04}, 0.0395, "beta above 1", &e_before);
  EXPECT_LT(e_before, 4.0 * fy_uy);
  EXPECT_GT(e_before / (4.0 * fy_uy - e_before), 1.0);
  p.energy_capacity = 2.5;  // E_t = 5e3 J: spent before the first unloading
  check(p, {0.04, -0.04, 0.04}, 0.0395, "energy spent", &e_before);
  EXPECT_GT(e_before, 2.5 * fy_uy);
}

TEST(Imk, ReloadingAimsAtTheLastReversalPointWhenItLiesAboveTheLineToThePeak) {
  // No deterioration within reach (lambda = 1e12): Ku = k0. Peaks at +5 uy and -5 uy, then a
  // reload toward +5 uy turned back at +2 uy (the last reversal point L, on that reloading
  // line), a shallower excursion to -3 uy, and the reload toward +: from the new zero crossing
  // u0, to the right of the last one, the line to the global peak G passes below L, so the
  // storey aims at L first, then at G, then follows the backbone (the peak-oriented rule with
  // the last reversal point).
  StoreyParameters p = imk_storey();
  p.energy_capacity = 1e12;
  const ImkStorey law;
  const double uy = p.uy();
  Incremental inc{law, p, {}};
  double vg = 0.0, vl = 0.0, vr = 0.0;
  for (double d : path({5 * uy}, uy / 50)) vg = inc.go(d);
  for (double d : path({-5 * uy}, uy / 50)) inc.go(5 * uy + d);
  for (double d : path({7 * uy}, uy / 50)) vl = inc.go(-5 * uy + d);  // up to +2 uy
  for (double d : path({-5 * uy}, uy / 50)) vr = inc.go(2 * uy + d);  // down to -3 uy
  const double u0 = -3 * uy - vr / p.k0;
  const double kl = vl / (2 * uy - u0), kg = vg / (5 * uy - u0);
  ASSERT_GT(kl, kg);  // L lies above the line from u0 to G
  int checked = 0;
  for (double d : path({12 * uy}, uy / 50)) {
    const double x = -3 * uy + d, v = inc.go(x);
    double expected;
    if (x <= u0)
      expected = vr + p.k0 * (x + 3 * uy);  // unloading along Ku = k0
    else if (x <= 2 * uy)
      expected = kl * (x - u0);  // toward L
    else if (x <= 5 * uy)
      expected = vl + (vg - vl) / (3 * uy) * (x - 2 * uy);  // from L toward G
    else
      expected = backbone(p, x);
    ASSERT_NEAR(v, expected, 1e-6 * p.Fy) << x;
    ++checked;
  }
  EXPECT_EQ(checked, 600);
}

// The storey of issue 31's comparison with OpenSees: k0 = 1.2e8 N/m, Fy = 8e5 N (uy = 1/150 m),
// h = 3 m, Fc / Fy = 1.15, theta_p = 0.025, theta_pc = 0.08, theta_u = 0.12 (theta_u h = 0.36 m
// exactly in binary: 0.12 * 3 == 0.36), Fr / Fy = 0.2, lambda = 60, c = 1. Its backbone: the cap
// at uy + 0.075 m (9.2e5 N), Kpc = 9.2e5 / 0.24 N/m, Fr = 1.6e5 N from uy + 0.075 + 7.6e5 / Kpc
// = 0.27993 m to 0.36 m.
StoreyParameters issue31_storey() {
  StoreyParameters p;
  p.k0 = 1.2e8;
  p.Fy = 8e5;
  p.h = 3.0;
  p.cap_strength_ratio = 1.15;
  p.plastic_drift_ratio = 0.025;
  p.post_cap_drift_ratio = 0.08;
  p.ultimate_drift_ratio = 0.12;
  p.residual_strength_ratio = 0.2;
  p.energy_capacity = 60.0;
  p.energy_exponent = 1.0;
  return p;
}

TEST(Imk, ReachingTheUltimateDriftFailsTheStoreyAsInOpenSees) {
  // OpenSees' IMKPeakOriented fails the storey at a drift Ui >= Uu (September 2023 code:
  // dU > 0 && Ui >= posUu_0): the shear at exactly theta_u h = 0.36 m is zero, and so it is
  // here, in one step from rest or along a path, either way; a hair short of it the storey
  // still carries Fr = 1.6e5 N on its residual plateau.
  const StoreyParameters p = issue31_storey();
  ASSERT_EQ(p.ultimate_drift_ratio * p.h, 0.36);
  const double fr = 1.6e5;
  const ImkStorey law;
  for (double sign : {1.0, -1.0}) {
    StoreyState t;
    EXPECT_EQ(law.advance(p, StoreyState{}, 0.0, sign * 0.36, t), 0.0);
    EXPECT_TRUE(law.failed(p, t));
    EXPECT_EQ(law.stored(p, t, sign * 0.36, nullptr), 0.0);
    StoreyState short_of;
    EXPECT_NEAR(law.advance(p, StoreyState{}, 0.0, sign * 0.359999, short_of), sign * fr, 1e-6);
    EXPECT_FALSE(law.failed(p, short_of));
    // Along a path of steps of 1 mm (the last one lands on 0.36 exactly), and on from a
    // committed state on the plateau to 0.36 in one step.
    Incremental inc{law, p, {}};
    for (int i = 1; i <= 360; ++i) {
      const double d = sign * (i == 360 ? 0.36 : i * 1e-3);
      const double v = inc.go(d);
      ASSERT_EQ(law.failed(p, inc.s), i == 360) << d;
      if (i >= 290 && i < 360) {
        ASSERT_NEAR(v, sign * fr, 1e-6) << d;
      }
      if (i == 360) {
        EXPECT_EQ(v, 0.0);
      }
    }
    StoreyState after;
    EXPECT_EQ(law.advance(p, short_of, sign * 0.359999, sign * 0.36, after), 0.0);
    EXPECT_TRUE(law.failed(p, after));
    // The continuous form: the end switch of the residual branch is zero at 0.36 m and rises
    // through zero there; applied there (as the solver does where it locates the crossing) it
    // fails the storey.
    StoreyState s = short_of;
    EXPECT_EQ(std::abs(s.branch), 7);  // residual
    EXPECT_NEAR(law.switch_value(0, p, s, sign * 0.36, sign, 0.0).value, 0.0, 1e-15);
    EXPECT_LT(law.switch_value(0, p, s, sign * 0.3599, sign, 0.0).value, 0.0);
    law.on_switch(0, p, s, sign * 0.36, nullptr);
    EXPECT_TRUE(law.failed(p, s));
    EXPECT_EQ(law.shear(p, s, sign * 0.36, nullptr), 0.0);
  }
}

TEST(Imk, ReloadingTowardAResidualPlateauWithATieAimsAtTheGlobalPeakAsInOpenSees) {
  // The last reversal point L and the global peak G both on the residual plateau at Fr: a tie
  // of their shears. OpenSees aims the reloading at L only when posFlocal < posFglobal
  // (strictly), so it aims at G, and so does this law. Every number below follows in closed
  // form from the rules of imk.hpp (c = 1, lambda = 75: E_t = 75 Fy uy = 4e5 J):
  //   push to +0.32 m on the plateau (shear Fr): the work W1 is the area under the backbone;
  //   reversal 1 at 0.32 m: beta_K1 = E_h / (E_t - E_h), E_h = W1 - Fr^2 / (2 k0);
  //     Ku1 = k0 (1 - beta_K1); the shear crosses zero at u01 = 0.32 - Fr / Ku1;
  //   excursion toward - at u01: E_exc = W(u01) = W1 - Fr^2 / (2 Ku1); the - side has not
  //     yielded, so its backbone stays and the target is (-uy, -Fy): slope Kn = Fy / (u01 + uy);
  //   down to 0.20 m: V2 = -Kn (u01 - 0.20), W2 = E_exc + Kn (u01 - 0.20)^2 / 2;
  //   reversal 2 at 0.20 m: beta_K2 = (E_h - E_exc) / (E_t - E_h), E_h = W2 - V2^2 / (2 Ku1);
  //     Ku2 = Ku1 (1 - beta_K2); zero shear at u02 = 0.20 - V2 / Ku2;
  //   excursion toward + at u02: beta = (E_h - E_exc) / (E_t - E_h), E_h = W2 - V2^2 / (2 Ku2);
  //     G's drift 0.32 (1 + beta) on the deteriorated backbone, past its residual drift: shear
  //     Fr, as L's (0.32 m, Fr): the tie. L lies above the line from u02 to G; the reload
  //     follows that line to G all the same, then the plateau.
  // The mirrored path gives the mirrored shears, in advance() and in the continuous form.
  StoreyParameters p = issue31_storey();
  p.energy_capacity = 75.0;
  const ImkStorey law;
  const double k0 = p.k0, fy = p.Fy, uy = p.uy(), h = p.h, fr = 0.2 * fy, et = 75.0 * fy * uy;
  const double fc = 1.15 * fy, dcap = uy + 0.025 * h, kpc = fc / (0.08 * h);
  const double dres = dcap + (fc - fr) / kpc;
  const double w1 = 0.5 * fy * uy + 0.5 * (fy + fc) * (dcap - uy) +
                    0.5 * (fc + fr) * (dres - dcap) + fr * (0.32 - dres);
  const double eh1 = w1 - fr * fr / (2 * k0);
  const double ku1 = k0 * (1 - eh1 / (et - eh1));
  const double u01 = 0.32 - fr / ku1;
  const double e_exc = w1 - fr * fr / (2 * ku1);
  const double kn = fy / (u01 + uy);
  const double v2 = -kn * (u01 - 0.20);
  const double w2 = e_exc + 0.5 * kn * (u01 - 0.20) * (u01 - 0.20);
  const double eh2 = w2 - v2 * v2 / (2 * ku1);
  const double ku2 = ku1 * (1 - (eh2 - e_exc) / (et - eh2));
  const double u02 = 0.20 - v2 / ku2;
  const double eh3 = w2 - v2 * v2 / (2 * ku2);
  const double beta = (eh3 - e_exc) / (et - eh3);
  const double dg = 0.32 * (1 + beta);
  // The numbers: beta_K1 = 0.82, the - excursion's beta = e_exc / (et - e_exc) = 0.82 (below 1),
  // beta = 0.067, G at 0.3415 m; the + backbone after it reaches Fr at 0.258 m (0.280 m before).
  ASSERT_GT(beta, 0.05);
  ASSERT_LT(e_exc / (et - e_exc), 1.0);
  ASSERT_GT(dg, dres);
  ASSERT_GT(fr / (0.32 - u02), fr / (dg - u02));  // L above the line from u02 to G
  for (double sign : {1.0, -1.0}) {
    for (int form = 0; form < 2; ++form) {
      Incremental inc{law, p, {}};
      Continuous cont{law, p, {}};
      auto go = [&](double d) { return form == 0 ? inc.go(sign * d) : cont.go(sign * d); };
      for (double d : path({0.32, 0.20}, 1e-3)) go(d);
      int checked = 0;
      double largest_gap_to_l = 0.0;
      for (int i = 1; i <= 150; ++i) {  // 0.20 m to 0.35 m in steps of 1 mm
        const double d = 0.20 + i * 1e-3, v = sign * go(d);
        double expected;
        if (d <= u02)
          expected = v2 + ku2 * (d - 0.20);  // unloading along Ku2
        else if (d <= dg)
          expected = fr * (d - u02) / (dg - u02);  // the line from u02 to G
        else
          expected = fr;  // the plateau
        ASSERT_NEAR(v, expected, 1e-6 * fy) << "form " << form << " sign " << sign << " at " << d;
        if (d > u02 && d < 0.32)  // the line to L (the rule before issue 31) lies above
          largest_gap_to_l = std::max(largest_gap_to_l, fr * (d - u02) / (0.32 - u02) - v);
        ++checked;
      }
      EXPECT_EQ(checked, 150);
      EXPECT_GT(largest_gap_to_l, 0.025 * fy);  // so the check tells the two rules apart
    }
  }
}

TEST(Imk, SwitchesAndSafeIntervals) {
  // Elastic: one drift switch (|d| reaching uy), the interval (-uy, uy) safe; a loading branch:
  // its end on the drift and the drift-rate reversal; unloading: both ends on the drift and safe.
  const StoreyParameters p = imk_storey();
  const ImkStorey law;
  const double uy = p.uy();
  StoreyState s;
  double lo, hi;
  ASSERT_TRUE(law.safe_drift(p, s, lo, hi));
  EXPECT_DOUBLE_EQ(lo, -uy);
  EXPECT_DOUBLE_EQ(hi, uy);
  EXPECT_LT(law.switch_value(0, p, s, 0.5 * uy, 1.0, 0.0).value, 0.0);
  EXPECT_GT(law.switch_value(0, p, s, 1.01 * uy, 1.0, 0.0).value, 0.0);
  EXPECT_LT(law.switch_value(1, p, s, -0.5 * uy, -1.0, 0.0).value, 0.0);
  EXPECT_GT(law.switch_value(1, p, s, -1.01 * uy, -1.0, 0.0).value, 0.0);
  EXPECT_DOUBLE_EQ(law.switch_value(1, p, s, -0.5 * uy, -0.2, 0.0).rate, 0.2);
  double slope, offset;
  ASSERT_TRUE(law.branch_line(p, s, slope, offset));
  EXPECT_EQ(slope, p.k0);
  law.on_switch(0, p, s, 1.0000001 * uy, nullptr);  // yield toward +
  EXPECT_EQ(s.branch, 5);
  EXPECT_FALSE(law.safe_drift(p, s, lo, hi));
  ASSERT_TRUE(law.branch_line(p, s, slope, offset));
  EXPECT_NEAR(slope, 0.2 * p.Fy / 0.18, 1e-6);
  EXPECT_NEAR(slope * uy + offset, p.Fy, 1e-6);
  EXPECT_NEAR(law.switch_value(0, p, s, 0.19, 1.0, 0.0).value, 0.0, 1e-15);  // the cap
  EXPECT_LT(law.switch_value(1, p, s, 0.05, 0.3, 0.0).value, 0.0);
  EXPECT_GT(law.switch_value(1, p, s, 0.05, -0.3, 0.0).value, 0.0);  // reversing
  law.on_switch(1, p, s, 0.05, nullptr);
  EXPECT_EQ(s.branch, 1);  // unloading toward -, on the + side's line
  ASSERT_TRUE(law.safe_drift(p, s, lo, hi));
  EXPECT_DOUBLE_EQ(hi, 0.05);
  const double ku = ImkStorey::unloading_stiffness(p, s);
  EXPECT_LT(ku, p.k0);  // reduced at the reversal
  EXPECT_NEAR(lo, 0.05 - law.shear(p, s, 0.05, nullptr) / ku, 1e-15);
  // Back up past the reversal point (switch 0, exactly 0 where the line starts), or down past
  // the zero crossing (switch 1).
  EXPECT_EQ(law.switch_value(0, p, s, 0.05, -1.0, 0.0).value, 0.0);
  EXPECT_GT(law.switch_value(0, p, s, 0.0501, 1.0, 0.0).value, 0.0);
  EXPECT_LT(law.switch_value(1, p, s, lo + 1e-6, -1.0, 0.0).value, 0.0);
  EXPECT_GT(law.switch_value(1, p, s, lo - 1e-6, -1.0, 0.0).value, 0.0);
  law.on_switch(1, p, s, lo - 1e-12, nullptr);  // the shear crosses zero: toward -
  EXPECT_TRUE(s.branch == -3 || s.branch == -4) << s.branch;
}

}  // namespace
}  // namespace pound

// Two SDOF buildings on two different ground motions pounding through a lumped contact law
// (issue 28): the row solver (simulate_row on RowGround::per_building) against an independent
// integration written here: classical RK4 at a fixed step of 1/400 of the record spacing, its
// own integrals of the piecewise-linear ground accelerations (ground states integrated from
// rest at t = -dt, ground_trace.hpp), the contact force on absolute displacements (physics.md
// section 5a: delta = (u_L + ug_L) - (u_R + ug_R) - gap) with v0 the penetration rate where the
// contact starts, and every contact start and end located by bisection of the RK4 step.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "../support/buildings.hpp"
#include "../support/reference_inputs.hpp"
#include "ground/row_ground.hpp"
#include "motion/motion_reader.hpp"
#include "simulation/simulate_row.hpp"

namespace pound {
namespace {

using test::elcentro_first;
using test::hunt_crossley_a;

// A contact law written here from physics.md section 2: F(delta, ddelta, v0) [N].
using Law = std::function<double(double, double, double)>;

// hc-linear: F = k delta (1 + a ddelta / max(v0, v0_min)), clamped at 0 (v0_min = 1e-3 m/s).
Law hc_linear(double k, double e) {
  const double a = hunt_crossley_a(e);
  return [=](double d, double dd, double v0) {
    return std::max(k * d * (1 + a * dd / std::max(v0, 1e-3)), 0.0);
  };
}

// LVe (Anagnostopoulos): F = k delta + c ddelta, c = 2 xi sqrt(k m1 m2 / (m1 + m2)),
// xi = -ln e / sqrt(pi^2 + ln^2 e), tension kept.
Law lve(double k, double e, double m1, double m2) {
  const double l = std::log(e), xi = -l / std::sqrt(M_PI * M_PI + l * l);
  const double c = 2 * xi * std::sqrt(k * m1 * m2 / (m1 + m2));
  return [=](double d, double dd, double) { return k * d + c * dd; };
}

struct Sdof {
  double m, k, xi;
};

struct Reference {
  std::array<double, 2> peak{0.0, 0.0};  // max |u_b| relative to its own ground [m]
  int impacts = 0;
};

// State: u1, v1, u2, v2 (relative to each building's ground), ug1, vg1, ug2, vg2.
using State = std::array<double, 8>;

class Rk4Pair {
 public:
  Rk4Pair(Sdof b1, Sdof b2, const GroundMotion& g1, const GroundMotion& g2, double gap, Law law)
      : b_{b1, b2}, g_{&g1, &g2}, gap_(gap), law_(std::move(law)), dt_(g1.dt) {}

  // Runs from rest at t = -dt to the last sample of the longer record.
  Reference run(bool pounding) {
    pounding_ = pounding;
    Reference r;
    State y{};
    on_ = false;
    const long last = static_cast<long>(std::max(g_[0]->accel.size(), g_[1]->accel.size())) - 1;
    const int sub = 400;
    for (long k = -1; k < last; ++k) {  // sample interval k: [k dt, (k + 1) dt]
      double s = 0.0;
      for (int j = 1; j <= sub; ++j) {
        const double target = j == sub ? dt_ : dt_ * j / sub;
        while (s < target) {
          const double h = target - s;
          State y1 = step(y, k, s, h);
          const double d1 = delta(y1);
          const bool crosses = pounding_ && (on_ ? !(d1 > 0.0) : d1 > 0.0);
          if (!crosses) {
            y = y1;
            s = target;
            continue;
          }
          // Bisection on the step length for delta = 0; land just across.
          double lo = 0.0, hi = h;
          for (int it = 0; it < 200 && hi - lo > 1e-16; ++it) {
            const double mid = 0.5 * (lo + hi);
            const double dm = delta(step(y, k, s, mid));
            ((on_ ? !(dm > 0.0) : dm > 0.0) ? hi : lo) = mid;
          }
          y = step(y, k, s, hi);
          s += hi;
          on_ = !on_;
          if (on_) {
            ++r.impacts;
            v0_ = std::max(rate(y), 0.0);
          }
        }
        r.peak[0] = std::max(r.peak[0], std::fabs(y[0]));
        r.peak[1] = std::max(r.peak[1], std::fabs(y[2]));
      }
    }
    return r;
  }

 private:
  double delta(const State& y) const { return (y[0] + y[4]) - (y[2] + y[6]) - gap_; }
  double rate(const State& y) const { return (y[1] + y[5]) - (y[3] + y[7]); }

  // Ground acceleration of record b at s into interval k: linear from a_k to a_k+1, rising
  // from 0 at -dt (k = -1), 0 from the last sample on.
  double ground_acc(int b, long k, double s) const {
    const std::vector<double>& a = g_[b]->accel;
    const long n = static_cast<long>(a.size());
    if (k >= n - 1) return 0.0;
    const double a0 = k < 0 ? 0.0 : a[k], a1 = a[k + 1];
    return a0 + (a1 - a0) * s / dt_;
  }

  State rhs(const State& y, long k, double s) const {
    const double F = pounding_ && on_ ? law_(delta(y), rate(y), v0_) : 0.0;
    State d{};
    for (int b = 0; b < 2; ++b) {
      const double ag = ground_acc(b, k, s);
      const double c = 2 * b_[b].xi * std::sqrt(b_[b].k * b_[b].m);
      const double sign = b == 0 ? -1.0 : 1.0;  // the force pushes the left building left
      d[2 * b] = y[2 * b + 1];
      // The structure feels no ground before t = 0 (GroundMotion::at), the ground rises from
      // rest at -dt.
      d[2 * b + 1] = -(c * y[2 * b + 1] + b_[b].k * y[2 * b]) / b_[b].m - (k < 0 ? 0.0 : ag) +
                     sign * F / b_[b].m;
      d[4 + 2 * b] = y[4 + 2 * b + 1];
      d[4 + 2 * b + 1] = ag;
    }
    return d;
  }

  State step(const State& y, long k, double s, double h) const {
    auto add = [](const State& a, const State& b, double f) {
      State r;
      for (int i = 0; i < 8; ++i) r[i] = a[i] + f * b[i];
      return r;
    };
    const State k1 = rhs(y, k, s);
    const State k2 = rhs(add(y, k1, h / 2), k, s + h / 2);
    const State k3 = rhs(add(y, k2, h / 2), k, s + h / 2);
    const State k4 = rhs(add(y, k3, h), k, s + h);
    State r;
    for (int i = 0; i < 8; ++i) r[i] = y[i] + h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    return r;
  }

  std::array<Sdof, 2> b_;
  std::array<const GroundMotion*, 2> g_;
  double gap_;
  Law law_;
  double dt_;
  bool pounding_ = false, on_ = false;
  double v0_ = 0.0;
};

// Building 1: 10 t, T = 0.5 s; building 2: 12 t, T = 0.8 s; 5 % damping. Records: the first
// 10 s of El Centro NS under building 1; under building 2 the first 9 s of it times 0.8 and
// 0.14 s (7 samples) later, plus a 2.3 Hz sine of 0.6 m/s^2: a different record that ends
// earlier (its ground then drifts at its final velocity).
TEST(GroundContact, PairOnDifferentRecordsMatchesAnIndependentIntegration) {
  const Sdof b1{1e4, 4 * M_PI * M_PI * 1e4 / 0.25, 0.05},
      b2{1.2e4, 4 * M_PI * M_PI * 1.2e4 / 0.64, 0.05};
  const GroundMotion g1 = elcentro_first(501);
  GroundMotion g2 = g1;
  g2.name = "other";
  g2.accel.assign(7, 0.0);
  for (int i = 0; i + 7 <= 450; ++i)
    g2.accel.push_back(0.8 * g1.accel[i] + 0.6 * std::sin(2 * M_PI * 2.3 * g1.dt * (i + 7)));
  const RowGround ground = RowGround::per_building({g1, g2});
  ASSERT_EQ(ground.channels(), 2);

  BuildingRow row;
  row.buildings = {test::uniform_building(1, b1.m, b1.k, b1.xi, DampingKind::modal),
                   test::uniform_building(1, b2.m, b2.k, b2.xi, DampingKind::modal)};
  const double gap = 0.01, kc = 50 * b1.k, e = 0.6;
  row.gaps = {{gap}};
  struct Case {
    std::string model;
    Law law;
  };
  const std::vector<Case> cases = {{"hc-linear", hc_linear(kc, e)},
                                   {"lve", lve(kc, e, b1.m, b2.m)}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.model);
    ContactSpec contact;
    contact.model = c.model;
    contact.params.k = kc;
    contact.params.e = e;
    const RowSimulation s = simulate_row(row, ground, contact, IntegratorSettings{});
    Rk4Pair ref(b1, b2, g1, g2, gap, c.law);
    const Reference pounding = ref.run(true), free = ref.run(false);
    ASSERT_EQ(s.sites.size(), 1u);
    EXPECT_GE(pounding.impacts, 3);
    EXPECT_EQ(s.sites[0].impacts, pounding.impacts);
    double worst = 0.0;
    for (int b = 0; b < 2; ++b) {
      const double dp = std::fabs(s.floors[b].disp_pounding / pounding.peak[b] - 1);
      const double df = std::fabs(s.floors[b].disp_free / free.peak[b] - 1);
      EXPECT_LT(dp, 1e-4) << "building " << b + 1;
      EXPECT_LT(df, 1e-4) << "building " << b + 1;
      worst = std::max({worst, dp, df});
      // Pounding changes the response (the comparison is not of two free runs).
      EXPECT_GT(std::fabs(pounding.peak[b] / free.peak[b] - 1), 1e-3) << "building " << b + 1;
    }
    char note[160];
    std::snprintf(note, sizeof note,
                  "impacts %d, peaks %.6g %.6g m (free %.6g %.6g), worst relative difference %.3g",
                  pounding.impacts, pounding.peak[0], pounding.peak[1], free.peak[0], free.peak[1],
                  worst);
    RecordProperty(c.model, note);
    // The pair's relative ground displacement is what the gap also takes up (issue 28).
    EXPECT_GT(s.ground_relative.at(0), gap);
  }
}

}  // namespace
}  // namespace pound

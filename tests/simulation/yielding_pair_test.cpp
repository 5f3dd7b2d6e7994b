// A yielding 3 + 2 storey pair with pounding against an independent reference integrator written
// here: explicit central differences at 0.5 us with its own bilinear return map, Rayleigh
// damping and linear viscoelastic contact, sharing nothing with the library but the input
// numbers. The peer-program comparison expects better than 1 % in peak displacements;
// the two agree to 0.1 %.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <string>
#include <vector>

#include "motion/motion_processing.hpp"
#include "motion/motion_reader.hpp"
#include "simulation/simulate_row.hpp"

namespace pound {
namespace {

struct Storeys {
  std::vector<double> m, k, Fy;  // kg, N/m, N
  double b;                      // hardening
};
const Storeys kLeft{{4e4, 4e4, 3e4}, {6e7, 5e7, 4e7}, {4.0e5, 3.2e5, 2.2e5}, 0.03};
const Storeys kRight{{3e4, 2.5e4}, {4.5e7, 3.5e7}, {2.5e5, 1.8e5}, 0.05};
constexpr double kGap = 0.01, kContactK = 1e9, kE = 0.6, kXi = 0.05;

// Rayleigh C = a0 M + a1 K on modes 1 and 2 of one building (Chopra 11.4.1), computed here.
Eigen::MatrixXd rayleigh(const Storeys& s, Eigen::MatrixXd& M, Eigen::MatrixXd& K) {
  const int n = static_cast<int>(s.m.size());
  M = Eigen::MatrixXd::Zero(n, n);
  K = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    M(j, j) = s.m[j];
    K(j, j) += s.k[j];
    if (j > 0) {
      K(j - 1, j - 1) += s.k[j];
      K(j - 1, j) -= s.k[j];
      K(j, j - 1) -= s.k[j];
    }
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K, M);
  const double w1 = std::sqrt(eig.eigenvalues()(0)), w2 = std::sqrt(eig.eigenvalues()(1));
  return (2 * kXi * w1 * w2 / (w1 + w2)) * M + (2 * kXi / (w1 + w2)) * K;
}

struct Peaks {
  std::vector<double> disp, residual;  // per floor, left building first [m]
};

// Central differences with a second-order velocity estimate for the damping and contact
// forces: v_i+1/2 = v_i-1/2 + h a_i, u_i+1 = u_i + h v_i+1/2, a_i from u_i and
// v_i ~ v_i-1/2 + h/2 a_i-1; the storeys' EPP parts return-mapped every step.
Peaks reference(const GroundMotion& g, double t_end, bool pounding) {
  Eigen::MatrixXd ML, KL, MR, KR;
  const Eigen::MatrixXd CL = rayleigh(kLeft, ML, KL), CR = rayleigh(kRight, MR, KR);
  const int nl = 3, n = 5;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(n, n);
  C.topLeftCorner(nl, nl) = CL;
  C.bottomRightCorner(2, 2) = CR;
  std::vector<double> m(kLeft.m), k(kLeft.k), Fy(kLeft.Fy), b(3, kLeft.b);
  for (int j = 0; j < 2; ++j) {
    m.push_back(kRight.m[j]);
    k.push_back(kRight.k[j]);
    Fy.push_back(kRight.Fy[j]);
    b.push_back(kRight.b);
  }
  auto below = [&](int i) { return i == 0 || i == nl ? -1 : i - 1; };
  const double le = std::log(kE), xi_c = -le / std::sqrt(M_PI * M_PI + le * le);
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), vh = u, a = u, z = u, d_prev = u;
  Peaks out;
  out.disp.assign(n, 0.0);
  const double h = 5e-7;
  const long steps = std::lround(t_end / h);
  Eigen::VectorXd f(n), v(n);
  for (long i = 0; i <= steps; ++i) {
    const double t = i * h;
    v = vh + 0.5 * h * a;  // velocity at t (second order)
    f.setZero();
    for (int s = 0; s < n; ++s) {  // storey s below floor s
      const double d = u(s) - (below(s) >= 0 ? u(below(s)) : 0.0);
      const double uy = Fy[s] / k[s];
      z(s) = std::clamp(z(s) + d - d_prev(s), -uy, uy);
      d_prev(s) = d;
      const double V = k[s] * (b[s] * d + (1 - b[s]) * z(s));
      f(s) += V;
      if (below(s) >= 0) f(below(s)) -= V;
    }
    f += C * v;
    if (pounding)
      for (int lev = 0; lev < 2; ++lev) {
        const int L = lev, R = nl + lev;
        const double delta = u(L) - u(R) - kGap;
        if (delta > 0) {
          const double mu = m[L] * m[R] / (m[L] + m[R]);
          const double F = kContactK * delta + 2 * xi_c * std::sqrt(kContactK * mu) * (v(L) - v(R));
          f(L) += F;
          f(R) -= F;
        }
      }
    const double ag = g.at(t);
    for (int s = 0; s < n; ++s) {
      a(s) = -f(s) / m[s] - ag;
      out.disp[s] = std::max(out.disp[s], std::fabs(u(s)));
    }
    if (i == steps) break;
    vh += h * a;
    u += h * vh;
  }
  for (int s = 0; s < n; ++s) out.residual.push_back(u(s) - (below(s) >= 0 ? u(below(s)) : 0.0));
  return out;
}

BuildingRow pair() {
  auto building = [](const Storeys& s) {
    Building b;
    b.masses = s.m;
    b.stiffnesses = s.k;
    b.storey_heights.assign(s.m.size(), 3.0);
    b.damping_ratio = kXi;
    b.hysteresis = "bilinear";
    b.yield_shears = s.Fy;
    b.hardening.assign(s.m.size(), s.b);
    return b;
  };
  BuildingRow row;
  row.buildings = {building(kLeft), building(kRight)};
  row.gaps = {{kGap, kGap}};
  return row;
}

TEST(YieldingPair, AgreesWithAnIndependentCentralDifferenceIntegration) {
  MotionFileSpec spec;
  spec.path = std::string(POUND_SOURCE_DIR) + "/motions/elcentro-1940-ns.dat";
  GroundMotion g = scale(truncate(read_motion(spec), 6.0), 2.0);
  const double t_end = g.duration();
  ContactSpec c;
  c.model = "lve";
  c.params.k = kContactK;
  c.params.e = kE;
  IntegratorSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-12;
  const RowSimulation sim = simulate_row(pair(), g, c, s);
  int impacts = 0;
  for (const auto& site : sim.sites) impacts += site.impacts;
  ASSERT_GT(impacts, 5);
  for (bool pounding : {true, false}) {
    const Peaks ref = reference(g, t_end, pounding);
    const RowResult& r = pounding ? sim.pounding : sim.free;
    double duct = 0.0;
    for (int i = 0; i < 5; ++i) {
      EXPECT_NEAR(r.peak_disp(i), ref.disp[i], 1e-3 * ref.disp[i])
          << (pounding ? "pounding" : "free") << ", floor DOF " << i;
      const int below = i == 0 || i == 3 ? -1 : i - 1;
      const double res = r.u_end(i) - (below >= 0 ? r.u_end(below) : 0.0);
      EXPECT_NEAR(res, ref.residual[i], 2e-3 * r.peak_drift(i)) << "residual drift, DOF " << i;
      duct = std::max(duct, sim.floors[i].ductility_pounding);
    }
    EXPECT_GT(duct, 2.0);  // the comparison is about yielding storeys
  }
}

}  // namespace
}  // namespace pound

// The exact step of a linear system with inputs linear over the step (solver/linear_step.hpp):
// the damped oscillator's closed forms (free vibration, constant and ramped ground acceleration)
// for steps that need no halving and many, and the group property of a multi-DOF system.
#include "solver/linear_step.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace pound {
namespace {

// u'' + 2 zeta w u' + w^2 u = -ag: z = [u; v], A = [[0, 1], [-w^2, -2 zeta w]], B = [0; -1].
struct Oscillator {
  double w, zeta;
  Eigen::MatrixXd A() const {
    Eigen::MatrixXd a(2, 2);
    a << 0.0, 1.0, -w * w, -2.0 * zeta * w;
    return a;
  }
  static Eigen::MatrixXd B() { return (Eigen::MatrixXd(2, 1) << 0.0, -1.0).finished(); }
  Eigen::VectorXd scale() const { return (Eigen::VectorXd(2) << 1.0 / w, 1.0).finished(); }
  // Free vibration from (u0, v0) after t (Chopra, Dynamics of Structures, eq. 2.2.4).
  Eigen::Vector2d free(double u0, double v0, double t) const {
    const double wd = w * std::sqrt(1.0 - zeta * zeta), e = std::exp(-zeta * w * t);
    const double c = std::cos(wd * t), s = std::sin(wd * t);
    const double b = (v0 + zeta * w * u0) / wd;
    const double u = e * (u0 * c + b * s);
    const double v = -zeta * w * u + e * (-u0 * wd * s + b * wd * c);
    return {u, v};
  }
  // ag = a0 + r s: the particular solution u_p(s) = -(a0 + r s) / w^2 + 2 zeta r / w^3, with
  // u_p' = -r / w^2; the motion is the free vibration of z0 - z_p(0), plus z_p(t).
  Eigen::Vector2d ramp(double u0, double v0, double a0, double a1, double t) const {
    const double r = (a1 - a0) / t;
    auto up = [&](double s) { return -(a0 + r * s) / (w * w) + 2.0 * zeta * r / (w * w * w); };
    const double vp = -r / (w * w);
    const Eigen::Vector2d h = free(u0 - up(0.0), v0 - vp, t);
    return {h(0) + up(t), h(1) + vp};
  }
};

Eigen::Vector2d step(const LinearStep& L, const Eigen::Vector2d& z0, double a0, double a1) {
  return L.phi * z0 + L.p1 * a0 + L.p2 * (a1 - a0);
}

TEST(LinearStep, DampedOscillatorMatchesItsClosedForms) {
  const Oscillator o{2.0 * M_PI / 0.3, 0.05};  // T = 0.3 s
  // h = 2 ms needs no halving (w h = 0.04); 0.25 s and 3 s need several and many.
  for (double h : {0.002, 0.25, 3.0}) {
    const LinearStep L = linear_step(o.A(), o.B(), h, o.scale());
    EXPECT_EQ(L.h, h);
    const Eigen::Vector2d z0(0.012, -0.3);
    const Eigen::Vector2d f = o.free(z0(0), z0(1), h);
    const Eigen::Vector2d zf = step(L, z0, 0.0, 0.0);
    EXPECT_NEAR(zf(0), f(0), 1e-13) << "h = " << h;
    EXPECT_NEAR(zf(1), f(1), 1e-12) << "h = " << h;
    const Eigen::Vector2d r = o.ramp(z0(0), z0(1), 1.7, -2.4, h);
    const Eigen::Vector2d zr = step(L, z0, 1.7, -2.4);
    EXPECT_NEAR(zr(0), r(0), 1e-13 + 1e-12 * std::fabs(r(0))) << "h = " << h;
    EXPECT_NEAR(zr(1), r(1), 1e-12 + 1e-12 * std::fabs(r(1))) << "h = " << h;
    // Held at its static deflection under a constant ag, the oscillator stays there.
    const Eigen::Vector2d zs(-1.7 / (o.w * o.w), 0.0);
    const Eigen::Vector2d zc = step(L, zs, 1.7, 1.7);
    EXPECT_NEAR(zc(0), zs(0), 1e-15) << "h = " << h;
    EXPECT_NEAR(zc(1), 0.0, 1e-13) << "h = " << h;
  }
}

TEST(LinearStep, TwoHalfStepsOfARampAreOneStep) {
  // A 3-DOF shear building with non-proportional damping and two inputs (a held force on the
  // top floor and the ground ramp): one step of 2h equals two of h, the ramp split at its middle.
  const int n = 3;
  Eigen::MatrixXd K(n, n), C(n, n);
  K << 4e7, -2e7, 0, -2e7, 3.5e7, -1.5e7, 0, -1.5e7, 1.5e7;
  C << 9e4, -3e4, 0, -3e4, 3e4, 0, 0, 0, 1e4;
  const Eigen::Vector3d m(3e4, 2.5e4, 2e4);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -(m.cwiseInverse().asDiagonal() * K);
  A.bottomRightCorner(n, n) = -(m.cwiseInverse().asDiagonal() * C);
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(2 * n, 2);
  B(2 * n - 1, 0) = 1.0 / m(2);
  B.block(n, 1, n, 1).setConstant(-1.0);
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(2 * n);
  scale.head(n).setConstant(1.0 / 60.0);
  const double h = 0.004;
  const LinearStep L1 = linear_step(A, B, h, scale), L2 = linear_step(A, B, 2 * h, scale);
  Eigen::VectorXd z0(2 * n);
  z0 << 0.01, 0.02, 0.025, -0.1, 0.05, 0.3;
  const double F = 5e4, a0 = 2.0, a2 = -3.0, a1 = 0.5 * (a0 + a2);
  auto go = [](const LinearStep& L, const Eigen::VectorXd& z, double F0, double g0, double g1) {
    Eigen::Vector2d w0(F0, g0), dw(0.0, g1 - g0);
    return Eigen::VectorXd(L.phi * z + L.p1 * w0 + L.p2 * dw);
  };
  const Eigen::VectorXd two = go(L1, go(L1, z0, F, a0, a1), F, a1, a2);
  const Eigen::VectorXd one = go(L2, z0, F, a0, a2);
  EXPECT_LT((two - one).cwiseAbs().maxCoeff(), 1e-14 * one.cwiseAbs().maxCoeff() + 1e-16);
  EXPECT_GT((one - z0).cwiseAbs().maxCoeff(), 1e-3);  // the state did move
  // And the apply kernel gives the same numbers, the held input folded into c.
  Eigen::VectorXd c = L2.p1.col(0) * F, z1(2 * n);
  linear_step_apply(L2, 1, &a0, &a2, c.data(), z0.data(), z1.data());
  EXPECT_LT((z1 - one).cwiseAbs().maxCoeff(), 1e-15 * one.cwiseAbs().maxCoeff() + 1e-17);
}

TEST(LinearStep, BadArgumentsAreRefused) {
  const Oscillator o{10.0, 0.05};
  EXPECT_THROW(linear_step(o.A(), o.B(), 0.0, o.scale()), std::invalid_argument);
  EXPECT_THROW(linear_step(o.A(), Eigen::MatrixXd::Zero(3, 1), 0.01, o.scale()),
               std::invalid_argument);
  Eigen::MatrixXd bad = o.A();
  bad(1, 0) = std::nan("");
  EXPECT_THROW(linear_step(bad, o.B(), 0.01, o.scale()), std::invalid_argument);
}

}  // namespace
}  // namespace pound

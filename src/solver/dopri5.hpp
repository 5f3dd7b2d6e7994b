#pragma once
// One step of the Dormand-Prince 5(4) Runge-Kutta pair (Dormand & Prince 1980; Hairer,
// Norsett & Wanner, Solving ODEs I, Table 5.2): fifth-order solution with local
// extrapolation, an embedded fourth-order estimate of the local error, and FSAL (the
// derivative at the end of an accepted step is the first stage of the next).
#include <Eigen/Dense>

namespace pound {

struct Dopri5Work {
  Eigen::VectorXd k2, k3, k4, k5, k6, k7, tmp;
  void resize(Eigen::Index n) {
    for (auto* v : {&k2, &k3, &k4, &k5, &k6, &k7, &tmp}) v->resize(n);
  }
};

/// Advances y' = f(t, y) from (t, y, k1 = f(t, y)) by h into y1, with k7 = f(t + h, y1) and
/// err = y5 - y4 (the local error estimate). `f(t, y, dydt)` writes the derivative.
template <class F>
void dopri5_step(F&& f, double t, double h, const Eigen::VectorXd& y, const Eigen::VectorXd& k1,
                 Eigen::VectorXd& y1, Eigen::VectorXd& err, Dopri5Work& w) {
  constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  constexpr double a21 = 1.0 / 5;
  constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                   a54 = -212.0 / 729;
  constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                   a65 = -5103.0 / 18656;
  constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                   b6 = 11.0 / 84;
  // e_i = b_i - bhat_i (fifth minus fourth order weights).
  constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                   e6 = 22.0 / 525, e7 = -1.0 / 40;
  // Element loops over raw storage: the vectors are short (2 n + sites), where the dynamic-size
  // expression templates cost more than the arithmetic.
  const Eigen::Index n = y.size();
  if (w.tmp.size() != n) w.resize(n);
  y1.resize(n);
  err.resize(n);
  const double* y0 = y.data();
  const double* q1 = k1.data();
  const double *q2 = w.k2.data(), *q3 = w.k3.data(), *q4 = w.k4.data(), *q5 = w.k5.data(),
               *q6 = w.k6.data(), *q7 = w.k7.data();
  double* tmp = w.tmp.data();
  for (Eigen::Index i = 0; i < n; ++i) tmp[i] = y0[i] + h * a21 * q1[i];
  f(t + c2 * h, w.tmp, w.k2);
  for (Eigen::Index i = 0; i < n; ++i) tmp[i] = y0[i] + h * (a31 * q1[i] + a32 * q2[i]);
  f(t + c3 * h, w.tmp, w.k3);
  for (Eigen::Index i = 0; i < n; ++i)
    tmp[i] = y0[i] + h * (a41 * q1[i] + a42 * q2[i] + a43 * q3[i]);
  f(t + c4 * h, w.tmp, w.k4);
  for (Eigen::Index i = 0; i < n; ++i)
    tmp[i] = y0[i] + h * (a51 * q1[i] + a52 * q2[i] + a53 * q3[i] + a54 * q4[i]);
  f(t + c5 * h, w.tmp, w.k5);
  for (Eigen::Index i = 0; i < n; ++i)
    tmp[i] = y0[i] + h * (a61 * q1[i] + a62 * q2[i] + a63 * q3[i] + a64 * q4[i] + a65 * q5[i]);
  f(t + h, w.tmp, w.k6);
  double* out = y1.data();
  for (Eigen::Index i = 0; i < n; ++i)
    out[i] = y0[i] + h * (b1 * q1[i] + b3 * q3[i] + b4 * q4[i] + b5 * q5[i] + b6 * q6[i]);
  f(t + h, y1, w.k7);
  double* e = err.data();
  for (Eigen::Index i = 0; i < n; ++i)
    e[i] = h * (e1 * q1[i] + e3 * q3[i] + e4 * q4[i] + e5 * q5[i] + e6 * q6[i] + e7 * q7[i]);
}

}  // namespace pound

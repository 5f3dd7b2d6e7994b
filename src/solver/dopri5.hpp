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

/// The stage sums of dopri5_step over n states, y0 + h sum_j a_ij k_j for stage i = 2..6,
/// the fifth-order solution (i = 7) and the error estimate h sum_j e_j k_j (i = 8), into out.
/// k = {k1, ..., k7}. Compiled for AVX2 and for the baseline (the same operations in the same
/// order on both, no fused multiply-add: the same bits), chosen at load time.
void dopri5_combine(int i, Eigen::Index n, double h, const double* y0, const double* const* k,
                    double* out);

/// Advances y' = f(t, y) from (t, y, k1 = f(t, y)) by h into y1, with k7 = f(t + h, y1) and
/// err = y5 - y4 (the local error estimate). `f(t, y, dydt)` writes the derivative.
template <class F>
void dopri5_step(F&& f, double t, double h, const Eigen::VectorXd& y, const Eigen::VectorXd& k1,
                 Eigen::VectorXd& y1, Eigen::VectorXd& err, Dopri5Work& w) {
  constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  const Eigen::Index n = y.size();
  if (w.tmp.size() != n) w.resize(n);
  y1.resize(n);
  err.resize(n);
  const double* y0 = y.data();
  const double* k[7] = {k1.data(),   w.k2.data(), w.k3.data(), w.k4.data(),
                        w.k5.data(), w.k6.data(), w.k7.data()};
  double* tmp = w.tmp.data();
  dopri5_combine(2, n, h, y0, k, tmp);
  f(t + c2 * h, w.tmp, w.k2);
  dopri5_combine(3, n, h, y0, k, tmp);
  f(t + c3 * h, w.tmp, w.k3);
  dopri5_combine(4, n, h, y0, k, tmp);
  f(t + c4 * h, w.tmp, w.k4);
  dopri5_combine(5, n, h, y0, k, tmp);
  f(t + c5 * h, w.tmp, w.k5);
  dopri5_combine(6, n, h, y0, k, tmp);
  f(t + h, w.tmp, w.k6);
  dopri5_combine(7, n, h, y0, k, y1.data());
  f(t + h, y1, w.k7);
  dopri5_combine(8, n, h, y0, k, err.data());
}

}  // namespace pound

#include "solver/linear_step.hpp"

#include <cmath>
#include <stdexcept>

namespace pound {

LinearStep linear_step(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double h,
                       const Eigen::VectorXd& scale) {
  const Eigen::Index n = A.rows();
  if (A.cols() != n || B.rows() != n || scale.size() != n || !(h > 0.0))
    throw std::invalid_argument("linear_step: A n x n, B n x m, scale n, h > 0 expected");
  if (!A.allFinite() || !B.allFinite() || !(scale.array() > 0.0).all())
    throw std::invalid_argument("linear_step: A, B not finite or scale not positive");
  // ||D A D^-1||_inf with D = diag(1 / scale): row i sums |A_ij| scale_j / scale_i.
  double norm = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    double row = 0.0;
    for (Eigen::Index j = 0; j < n; ++j) row += std::fabs(A(i, j)) * scale(j) / scale(i);
    norm = std::max(norm, row);
  }
  int squarings = 0;
  double hs = h;
  while (hs * norm > 0.5 && squarings < 60) {
    hs *= 0.5;
    ++squarings;
  }
  // Terms while theta^k / k! > 1e-18 (theta = hs ||D A D^-1|| <= 1/2; at most 14 terms).
  const double theta = hs * norm;
  int terms = 1;
  for (double t = 1.0; terms < 30; ++terms) {
    t *= theta / terms;
    if (t < 1e-18) break;
  }
  const Eigen::MatrixXd X = A * hs;
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(n, n);
  Eigen::MatrixXd phi = I, psi1 = I, psi2 = 0.5 * I, T = I;
  // T = X^k; coefficients 1 / k!, 1 / (k+1)!, 1 / (k+2)!.
  double f0 = 1.0, f1 = 1.0, f2 = 0.5;
  for (int k = 1; k <= terms; ++k) {
    T = T * X;
    f0 /= k;
    f1 /= k + 1;
    f2 /= k + 2;
    phi += f0 * T;
    psi1 += f1 * T;
    psi2 += f2 * T;
  }
  psi1 *= hs;
  psi2 *= hs * hs;
  for (int s = 0; s < squarings; ++s) {
    const Eigen::MatrixXd ipphi = I + phi;
    psi2 = ipphi * psi2 + hs * psi1;  // Psi2(2hs) = (I + Phi) Psi2 + hs Psi1
    psi1 = ipphi * psi1;              // Psi1(2hs) = (I + Phi) Psi1
    phi = phi * phi;                  // Phi(2hs) = Phi^2
    hs *= 2.0;
  }
  LinearStep out;
  out.h = h;
  out.phi = std::move(phi);
  out.p1 = psi1 * B;
  out.p2 = psi2 * B / h;
  return out;
}

namespace {
__attribute__((target_clones("avx2", "default"))) void apply_kernel(
    Eigen::Index n, const double* __restrict phi, const double* __restrict c,
    const double* __restrict q1, const double* __restrict q2, double a0, double da,
    const double* __restrict z0, double* __restrict z1) {
  for (Eigen::Index i = 0; i < n; ++i) z1[i] = c[i] + q1[i] * a0 + q2[i] * da;
  for (Eigen::Index j = 0; j < n; ++j) {  // Phi is column-major: add its columns
    const double zj = z0[j];
    const double* col = phi + j * n;
    for (Eigen::Index i = 0; i < n; ++i) z1[i] += col[i] * zj;
  }
}

// A further ramped input (k >= 1), added after apply_kernel's first input and Phi z0.
__attribute__((target_clones("avx2", "default"))) void add_input(Eigen::Index n,
                                                                 const double* __restrict q1,
                                                                 const double* __restrict q2,
                                                                 double a0, double da,
                                                                 double* __restrict z1) {
  for (Eigen::Index i = 0; i < n; ++i) z1[i] += q1[i] * a0 + q2[i] * da;
}
}  // namespace

void linear_step_apply(const LinearStep& L, int r, const double* a0, const double* a1,
                       const double* c, const double* z0, double* z1) {
  const Eigen::Index n = L.phi.rows(), m = L.p1.cols();
  const Eigen::Index first = m - r;
  apply_kernel(n, L.phi.data(), c, L.p1.col(first).data(), L.p2.col(first).data(), a0[0],
               a1[0] - a0[0], z0, z1);
  for (int k = 1; k < r; ++k)
    add_input(n, L.p1.col(first + k).data(), L.p2.col(first + k).data(), a0[k], a1[k] - a0[k], z1);
}

}  // namespace pound

#pragma once
// The exact step of a linear time-invariant system whose inputs vary linearly over the step:
//   z' = A z + B w(t),  w(t) = w0 + (w1 - w0) s / h on [t, t + h]  (s = time into the step),
//   z(t + h) = Phi z(t) + P1 w0 + P2 (w1 - w0),
//   Phi = e^{A h},  P1 = Psi1 B,  P2 = Psi2 B / h,
//   Psi1 = int_0^h e^{A r} dr = sum_k A^k h^{k+1} / (k+1)!,
//   Psi2 = int_0^h e^{A (h - s)} s ds = sum_k A^k h^{k+2} / (k+2)!
// (Van Loan 1978, "Computing integrals involving the matrix exponential"; the same propagator
// as Nigam & Jennings' for a piecewise-linear ground acceleration, for a whole row of floors).
// Exact for piecewise-linear inputs up to round-off: the row solver steps a building row with
// it between contacts and yield events (docs/integration.md, "Exact steps"). Kernel only.
#include <Eigen/Dense>

namespace pound {

struct LinearStep {
  double h = 0.0;       ///< step [s]
  Eigen::MatrixXd phi;  ///< e^{A h}
  Eigen::MatrixXd p1;   ///< Psi1 B: response to inputs held at w0
  Eigen::MatrixXd p2;   ///< Psi2 B / h: response to the inputs' ramp w1 - w0
};

/// Phi, P1 and P2 for the step h > 0 [s] by the Taylor series with scaling and squaring
/// (Moler & Van Loan 2003, "Nineteen dubious ways", method 3): h is halved until
/// h ||D A D^-1||_inf <= 1/2 for a diagonal balancing D, the series is summed to 1e-18 of its
/// first term, and the halves are doubled back by
///   Phi(2h) = Phi^2,  Psi1(2h) = (I + Phi) Psi1,  Psi2(2h) = (I + Phi) Psi2 + h Psi1.
/// `scale` (size of z) balances the state's units: D = diag(1 / scale).
LinearStep linear_step(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double h,
                       const Eigen::VectorXd& scale);

/// z1 = Phi z0 + c + sum_k [P1(:, m-r+k) a0_k + P2(:, m-r+k) (a1_k - a0_k)]: the step with the
/// last r inputs ramping from a0_k to a1_k (k = 0..r-1; the ground accelerations of a row's
/// channels) and the others held, their response P1 w (constant) given as c. z0, c and z1 hold
/// n = Phi.rows() values; z1 must not alias z0. Compiled for AVX2 and the baseline (the same
/// operations in the same order, no fused multiply-add: the same bits; one ramped input gives
/// the bits of the one-input form before issue 28).
void linear_step_apply(const LinearStep& L, int r, const double* a0, const double* a1,
                       const double* c, const double* z0, double* z1);

}  // namespace pound

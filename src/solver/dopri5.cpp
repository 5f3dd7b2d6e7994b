#include "solver/dopri5.hpp"

namespace pound {

// Butcher tableau of Dormand & Prince (1980) (Hairer, Norsett & Wanner I, Table 5.2). The loops
// are the element loops dopri5_step had inline, term for term in the same order.
__attribute__((target_clones("avx2", "default"))) void dopri5_combine(int i, Eigen::Index n,
                                                                      double h,
                                                                      const double* __restrict y0,
                                                                      const double* const* k,
                                                                      double* __restrict out) {
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
  const double* __restrict q1 = k[0];
  const double* __restrict q2 = k[1];
  const double* __restrict q3 = k[2];
  const double* __restrict q4 = k[3];
  const double* __restrict q5 = k[4];
  const double* __restrict q6 = k[5];
  const double* __restrict q7 = k[6];
  switch (i) {
    case 2:
      for (Eigen::Index j = 0; j < n; ++j) out[j] = y0[j] + h * a21 * q1[j];
      break;
    case 3:
      for (Eigen::Index j = 0; j < n; ++j) out[j] = y0[j] + h * (a31 * q1[j] + a32 * q2[j]);
      break;
    case 4:
      for (Eigen::Index j = 0; j < n; ++j)
        out[j] = y0[j] + h * (a41 * q1[j] + a42 * q2[j] + a43 * q3[j]);
      break;
    case 5:
      for (Eigen::Index j = 0; j < n; ++j)
        out[j] = y0[j] + h * (a51 * q1[j] + a52 * q2[j] + a53 * q3[j] + a54 * q4[j]);
      break;
    case 6:
      for (Eigen::Index j = 0; j < n; ++j)
        out[j] = y0[j] + h * (a61 * q1[j] + a62 * q2[j] + a63 * q3[j] + a64 * q4[j] + a65 * q5[j]);
      break;
    case 7:
      for (Eigen::Index j = 0; j < n; ++j)
        out[j] = y0[j] + h * (b1 * q1[j] + b3 * q3[j] + b4 * q4[j] + b5 * q5[j] + b6 * q6[j]);
      break;
    default:
      for (Eigen::Index j = 0; j < n; ++j)
        out[j] = h * (e1 * q1[j] + e3 * q3[j] + e4 * q4[j] + e5 * q5[j] + e6 * q6[j] + e7 * q7[j]);
      break;
  }
}

}  // namespace pound

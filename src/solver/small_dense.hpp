#pragma once
// Small dense matrix-vector products of a building's block of a row (issue 38): the exact
// steps' padded propagators (solver/exact_steps.cpp) and the accelerations of a linear row on
// flexible foundations (solver/row_forces.cpp). Rows padded to a multiple of 4 go by whole
// vectors of four (GCC's vector extension: AVX2, or two SSE2 halves in the baseline clone of
// the callers' target_clones kernels), element by element without fused multiply-add, so the
// sums are those of the scalar loops in the same order. Kernel only.
#include <cstddef>

namespace pound::dense {

typedef double V4 __attribute__((vector_size(32), aligned(8)));  // unaligned loads and stores

// z += sum_j M(:, j) y[idx[j]] over NV vectors of rows (M column-major, leading dimension
// 4 NV), the sums held in registers.
template <int NV>
__attribute__((always_inline)) inline void add_columns(int ns, const double* __restrict m,
                                                       const double* __restrict y,
                                                       const int* __restrict idx, V4* z) {
  V4 a[NV];
  for (int i = 0; i < NV; ++i) a[i] = z[i];
  for (int j = 0; j < ns; ++j) {
    const double zj = y[idx[j]];
    const V4* col = reinterpret_cast<const V4*>(m + static_cast<std::ptrdiff_t>(j) * 4 * NV);
    for (int i = 0; i < NV; ++i) a[i] += col[i] * zj;
  }
  for (int i = 0; i < NV; ++i) z[i] = a[i];
}

// The same for ld = 4 NV of any size (registers up to NV = 6).
__attribute__((always_inline)) inline void add_columns_any(int ns, int ld,
                                                           const double* __restrict m,
                                                           const double* __restrict y,
                                                           const int* __restrict idx, V4* z) {
  switch (ld / 4) {
    case 1:
      return add_columns<1>(ns, m, y, idx, z);
    case 2:
      return add_columns<2>(ns, m, y, idx, z);
    case 3:
      return add_columns<3>(ns, m, y, idx, z);
    case 4:
      return add_columns<4>(ns, m, y, idx, z);
    case 5:
      return add_columns<5>(ns, m, y, idx, z);
    case 6:
      return add_columns<6>(ns, m, y, idx, z);
    default:
      break;
  }
  for (int j = 0; j < ns; ++j) {
    const double zj = y[idx[j]];
    const V4* col = reinterpret_cast<const V4*>(m + static_cast<std::ptrdiff_t>(j) * ld);
    for (int i = 0; i < ld / 4; ++i) z[i] += col[i] * zj;
  }
}

}  // namespace pound::dense

#pragma once
// Four doubles as one vector (GCC/Clang vector extension), for the kernels compiled twice with
// __attribute__((target_clones("avx2", "default"))): the modal bank's steps
// (src/sears/modal_bank.cpp) and the response-spectrum oscillators
// (src/motion/response_spectrum.cpp). Each lane does the operations of the scalar code in the
// same order and no FMA is enabled, so both clones give the same bits on any x86-64 machine.
// The helpers are always inlined (also at -O0): a call would pass the 32-byte vector with the
// default ABI into the AVX2 clone and crash, so GCC's note on that ABI (-Wpsabi) does not apply.
#include <emmintrin.h>

#include <cstring>

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

namespace pound::simd {

typedef double V4 __attribute__((vector_size(32)));
typedef long long I4 __attribute__((vector_size(32)));

__attribute__((always_inline)) inline V4 load(const double* p) {
  V4 r;
  std::memcpy(&r, p, sizeof r);
  return r;
}
__attribute__((always_inline)) inline void store(double* p, const V4& x) {
  std::memcpy(p, &x, sizeof x);
}
/// |x| lane by lane: clears the sign bits, like std::fabs.
__attribute__((always_inline)) inline V4 vabs(const V4& x) {
  const I4 magnitude = {0x7fffffffffffffffLL, 0x7fffffffffffffffLL, 0x7fffffffffffffffLL,
                        0x7fffffffffffffffLL};
  return (V4)((I4)x & magnitude);
}
/// std::max(m, x) lane by lane: (m < x) ? x : m.
__attribute__((always_inline)) inline V4 vmax(const V4& m, const V4& x) {
  return m < x ? x : m;
}

/// std::sqrt lane by lane (two SSE2 sqrtpd, correctly rounded as std::sqrt is).
__attribute__((always_inline)) inline V4 vsqrt(const V4& x) {
  __m128d lo, hi;
  std::memcpy(&lo, &x, sizeof lo);
  std::memcpy(&hi, reinterpret_cast<const char*>(&x) + sizeof lo, sizeof hi);
  lo = _mm_sqrt_pd(lo);
  hi = _mm_sqrt_pd(hi);
  V4 r;
  std::memcpy(&r, &lo, sizeof lo);
  std::memcpy(reinterpret_cast<char*>(&r) + sizeof lo, &hi, sizeof hi);
  return r;
}

}  // namespace pound::simd

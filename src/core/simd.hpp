#pragma once
// Vectors of doubles of any width (GCC/Clang vector extension) for kernels written once and
// compiled per instruction set: V2 (two doubles) for the SSE2 baseline, V4 (four) for the AVX2
// path, V8 (eight) for the AVX-512 path, each in a function with its own target attribute and one
// dispatch on the running CPU (e.g. src/motion/response_spectrum.cpp). Each lane does the
// operations of the scalar code in the same order and POUND_NO_CONTRACT keeps a * b + c two
// roundings (the avx512f target would otherwise fuse them), so every path gives the same bits
// on any x86-64 machine. A width is only used where the target handles it natively: GCC 12
// lowers the comparisons of a 512-bit vector into scalar code on AVX2. The helpers are always
// inlined (also at -O0), so no vector is passed by the default ABI into a wider target and
// GCC's note on that ABI (-Wpsabi) does not apply. (core/vec4.hpp: the same for V4 alone.)
#include <cmath>
#include <cstddef>
#include <cstring>

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#define POUND_NO_CONTRACT __attribute__((optimize("fp-contract=off")))
#else
#define POUND_NO_CONTRACT
#endif

namespace pound::simd {

typedef double V2 __attribute__((vector_size(16)));
typedef double V4 __attribute__((vector_size(32)));
typedef double V8 __attribute__((vector_size(64)));

/// Doubles in a vector type.
template <class V>
inline constexpr std::size_t kWidth = sizeof(V) / sizeof(double);

template <class V>
__attribute__((always_inline)) inline V vload(const double* p) {
  V r;
  std::memcpy(&r, p, sizeof r);
  return r;
}
template <class V>
__attribute__((always_inline)) inline void vstore(double* p, const V& x) {
  std::memcpy(p, &x, sizeof x);
}
/// x in every lane (x - 0 is x for every x, -0 included: one broadcast).
template <class V>
__attribute__((always_inline)) inline V vsplat(double x) {
  return x - V{};
}
/// |x| lane by lane: clears the sign bits, like std::fabs.
template <class V>
__attribute__((always_inline)) inline V vfabs(const V& x) {
  using I = decltype(x < x);  // the integer vector of the same width
  const I magnitude = I{} + 0x7fffffffffffffffLL;
  return (V)((I)x & magnitude);
}
/// a * b + c lane by lane with one rounding (IEEE fused multiply-add). On the AVX-512 and AVX2
/// paths the instruction (inline assembly: an intrinsic could not be inlined into these
/// templates, which are compiled for no particular target), on the SSE2 baseline std::fma,
/// which glibc rounds correctly too; so every path gives the same bits.
#if defined(__clang__)
// Clang checks an asm operand's width against the function's target, and these templates have
// none (the fuzz build, fuzz/): lane by lane std::fma there, the same bits, slower.
__attribute__((always_inline)) inline V8 vfma(V8 a, V8 b, V8 c) {
  for (std::size_t i = 0; i < 8; ++i) c[i] = std::fma(a[i], b[i], c[i]);
  return c;
}
__attribute__((always_inline)) inline V4 vfma(V4 a, V4 b, V4 c) {
  for (std::size_t i = 0; i < 4; ++i) c[i] = std::fma(a[i], b[i], c[i]);
  return c;
}
#else
__attribute__((always_inline)) inline V8 vfma(V8 a, V8 b, V8 c) {
  asm("vfmadd231pd %2, %1, %0" : "+v"(c) : "v"(a), "v"(b));
  return c;
}
__attribute__((always_inline)) inline V4 vfma(V4 a, V4 b, V4 c) {
  asm("vfmadd231pd %2, %1, %0" : "+v"(c) : "v"(a), "v"(b));
  return c;
}
#endif
__attribute__((always_inline)) inline V2 vfma(V2 a, V2 b, V2 c) {
  return V2{std::fma(a[0], b[0], c[0]), std::fma(a[1], b[1], c[1])};
}
/// std::max(m, x) lane by lane: (m < x) ? x : m.
template <class V>
__attribute__((always_inline)) inline V vfmax(const V& m, const V& x) {
  return m < x ? x : m;
}

}  // namespace pound::simd

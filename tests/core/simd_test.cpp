// core/simd.hpp: every helper gives, lane by lane, the bits of the scalar code it stands for,
// on the SSE2 baseline (V2) and in functions compiled for AVX2 (V4) and AVX-512 (V8) as the
// kernels use them (each run only where the CPU has the instructions); and POUND_NO_CONTRACT
// keeps a * b + c two roundings where the target could fuse them.
#include "core/simd.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace pound::simd {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// Awkward values: signed zeros, a subnormal, huge, infinite, NaN, and inexact ones.
const std::vector<double> kValues = {1.5,    -0.0,  0.0,  -3.25, 4.9e-322, -1.7e308,
                                     kInf,   -kInf, kNaN, 0.1,   1.0 / 3,  -2.0 / 7,
                                     1e-300, 7.0,   -0.5, 2.5e10};

// The results of each helper on W lanes, from x (and y, z) at offset k of kValues.
struct Lanes {
  std::vector<double> fabs, fmax, fma, splat, two_roundings;
};

template <class V>
__attribute__((always_inline)) inline Lanes run_helpers(std::size_t k) {
  constexpr std::size_t W = kWidth<V>;
  double x[W], y[W], z[W];
  for (std::size_t i = 0; i < W; ++i) {
    x[i] = kValues[(k + i) % kValues.size()];
    y[i] = kValues[(k + 3 * i + 5) % kValues.size()];
    z[i] = kValues[(k + 7 * i + 2) % kValues.size()];
  }
  const V vx = vload<V>(x), vy = vload<V>(y), vz = vload<V>(z);
  double out[W];
  Lanes r;
  vstore(out, vfabs(vx));
  r.fabs.assign(out, out + W);
  vstore(out, vfmax(vx, vy));
  r.fmax.assign(out, out + W);
  vstore(out, vfma(vx, vy, vz));
  r.fma.assign(out, out + W);
  vstore(out, vsplat<V>(x[0]));
  r.splat.assign(out, out + W);
  vstore(out, vx * vy + vz);
  r.two_roundings.assign(out, out + W);
  return r;
}

POUND_NO_CONTRACT Lanes baseline_lanes(std::size_t k) {
  return run_helpers<V2>(k);
}
__attribute__((target("avx2,fma"))) POUND_NO_CONTRACT Lanes avx2_lanes(std::size_t k) {
  return run_helpers<V4>(k);
}
__attribute__((target("avx512f"))) POUND_NO_CONTRACT Lanes avx512_lanes(std::size_t k) {
  return run_helpers<V8>(k);
}

// The scalar code each helper stands for, lane by lane (compiled for the baseline, which has
// no fused multiply-add to contract a * b + c into).
void expect_scalar_bits(const Lanes& r, std::size_t k, std::size_t width) {
  for (std::size_t i = 0; i < width; ++i) {
    const double x = kValues[(k + i) % kValues.size()];
    const double y = kValues[(k + 3 * i + 5) % kValues.size()];
    const double z = kValues[(k + 7 * i + 2) % kValues.size()];
    EXPECT_EQ(bits(r.fabs[i]), bits(std::fabs(x))) << "vfabs lane " << i << " of " << x;
    EXPECT_EQ(bits(r.fmax[i]), bits(std::max(x, y))) << "vfmax " << x << ", " << y;
    const double fused = std::fma(x, y, z), unfused = x * y + z;
    EXPECT_EQ(bits(r.fma[i]), bits(fused)) << "vfma " << x << " " << y << " " << z;
    EXPECT_EQ(bits(r.two_roundings[i]), bits(unfused)) << x << " * " << y << " + " << z;
    EXPECT_EQ(bits(r.splat[i]), bits(kValues[k % kValues.size()])) << "vsplat lane " << i;
  }
}

TEST(Simd, TheBaselineHelpersGiveTheScalarBits) {
  for (std::size_t k = 0; k < kValues.size(); ++k) expect_scalar_bits(baseline_lanes(k), k, 2);
}

TEST(Simd, TheAvx2HelpersGiveTheScalarBits) {
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma"))
    GTEST_SKIP() << "this CPU has no AVX2 and FMA";
  for (std::size_t k = 0; k < kValues.size(); ++k) expect_scalar_bits(avx2_lanes(k), k, 4);
}

TEST(Simd, TheAvx512HelpersGiveTheScalarBits) {
  if (!__builtin_cpu_supports("avx512f")) GTEST_SKIP() << "this CPU has no AVX-512";
  for (std::size_t k = 0; k < kValues.size(); ++k) expect_scalar_bits(avx512_lanes(k), k, 8);
}

TEST(Simd, FusedAndTwoRoundingsDifferWhereTheTestLooks) {
  // (1 + 2^-30)^2 - 1: the product's 2^-60 is lost when rounded first, kept by a fused
  // multiply-add. So the test above could tell vfma from a * b + c, and a contracted
  // a * b + c from two roundings.
  const double a = 1.0 + std::ldexp(1.0, -30);
  EXPECT_EQ(a * a - 1.0, std::ldexp(1.0, -29));
  EXPECT_EQ(std::fma(a, a, -1.0), std::ldexp(1.0, -29) + std::ldexp(1.0, -60));
  double x[8], y[8], z[8];
  for (int i = 0; i < 8; ++i) x[i] = y[i] = a, z[i] = -1.0;
  // In the AVX-512 function, where GCC would fuse a * b + c without POUND_NO_CONTRACT.
  if (__builtin_cpu_supports("avx512f")) {
    struct Probe {
      __attribute__((target("avx512f"))) POUND_NO_CONTRACT static void run(const double* x,
                                                                           const double* y,
                                                                           const double* z,
                                                                           double* out) {
        vstore(out, vload<V8>(x) * vload<V8>(y) + vload<V8>(z));
      }
    };
    double out[8];
    Probe::run(x, y, z, out);
    for (double v : out) EXPECT_EQ(v, std::ldexp(1.0, -29));
  }
  double out[2];
  vstore(out, vfma(vload<V2>(x), vload<V2>(y), vload<V2>(z)));
  for (double v : out) EXPECT_EQ(v, std::ldexp(1.0, -29) + std::ldexp(1.0, -60));
  EXPECT_EQ(kWidth<V2>, 2u);
  EXPECT_EQ(kWidth<V4>, 4u);
  EXPECT_EQ(kWidth<V8>, 8u);
}

}  // namespace
}  // namespace pound::simd

// core/vec4.hpp: four doubles as one vector, for the kernels compiled twice (default and
// AVX2: target_clones). Each helper and each operation gives, lane by lane, the bits of the
// scalar code, in both compilations.
#include "core/vec4.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

const std::vector<double> kValues = {2.0,      -0.0,  0.0,  -3.25,     4.9e-322, 1.7e308,
                                     kInf,     -kInf, kNaN, 0.1,       1e-3,     1.0 / 3,
                                     -2.0 / 7, 9.0,   0.25, 123456.789};

struct Results {
  double abs[4], max[4], sqrt[4], sum[4], diff[4], prod[4], quot[4], mixed[4];
};

__attribute__((always_inline)) inline Results run(std::size_t k) {
  double x[4], y[4];
  for (std::size_t i = 0; i < 4; ++i) {
    x[i] = kValues[(k + i) % kValues.size()];
    y[i] = kValues[(k + 5 * i + 3) % kValues.size()];
  }
  const V4 a = load(x), b = load(y);
  Results r;
  store(r.abs, vabs(a));
  store(r.max, vmax(a, b));
  store(r.sqrt, vsqrt(vabs(a)));
  store(r.sum, a + b);
  store(r.diff, a - b);
  store(r.prod, a * b);
  store(r.quot, a / b);
  store(r.mixed, a * b + a);  // no FMA enabled in either compilation: two roundings
  return r;
}

Results default_results(std::size_t k) {
  return run(k);
}
__attribute__((target("avx2"))) Results avx2_results(std::size_t k) {
  return run(k);
}

void expect_scalar_bits(const Results& r, std::size_t k) {
  for (std::size_t i = 0; i < 4; ++i) {
    const double x = kValues[(k + i) % kValues.size()];
    const double y = kValues[(k + 5 * i + 3) % kValues.size()];
    EXPECT_EQ(bits(r.abs[i]), bits(std::fabs(x))) << "vabs " << x;
    EXPECT_EQ(bits(r.max[i]), bits(std::max(x, y))) << "vmax " << x << ", " << y;
    EXPECT_EQ(bits(r.sqrt[i]), bits(std::sqrt(std::fabs(x)))) << "vsqrt " << x;
    EXPECT_EQ(bits(r.sum[i]), bits(x + y)) << x << " + " << y;
    EXPECT_EQ(bits(r.diff[i]), bits(x - y)) << x << " - " << y;
    EXPECT_EQ(bits(r.prod[i]), bits(x * y)) << x << " * " << y;
    EXPECT_EQ(bits(r.quot[i]), bits(x / y)) << x << " / " << y;
    EXPECT_EQ(bits(r.mixed[i]), bits(x * y + x)) << x << " * " << y << " + " << x;
  }
}

TEST(Vec4, TheDefaultCompilationGivesTheScalarBits) {
  for (std::size_t k = 0; k < kValues.size(); ++k) expect_scalar_bits(default_results(k), k);
}

TEST(Vec4, TheAvx2CompilationGivesTheScalarBits) {
  if (!__builtin_cpu_supports("avx2")) GTEST_SKIP() << "this CPU has no AVX2";
  for (std::size_t k = 0; k < kValues.size(); ++k) expect_scalar_bits(avx2_results(k), k);
}

TEST(Vec4, LoadAndStoreKeepEveryBitAndTheLaneOrder) {
  const double in[4] = {-0.0, kNaN, 4.9e-322, -kInf};
  double out[4];
  store(out, load(in));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(bits(out[i]), bits(in[i])) << i;
  const V4 v = load(in);
  EXPECT_EQ(bits(v[2]), bits(4.9e-322));  // lane i is element i
  // |x| clears the sign bit only: -0 becomes +0, a NaN keeps its payload.
  const V4 a = vabs(v);
  EXPECT_EQ(bits(a[0]), 0u);
  EXPECT_EQ(bits(a[1]), bits(kNaN) & 0x7fffffffffffffffULL);
}

}  // namespace
}  // namespace pound::simd

#include "motion/response_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/simd.hpp"

namespace pound {
namespace {
constexpr std::size_t kLanes = 8;  // the oscillators are padded to a multiple of this
}  // namespace

// Derivation (equivalent to Nigam & Jennings 1969): over one step the forcing is
// f(tau) = f0 + (f1 - f0) tau / h with f = -a_g. A particular solution is
//   xp(tau) = f(tau) / w^2 - 2 zeta (f1 - f0) / (w^3 h),   xp' = (f1 - f0) / (w^2 h),
// and the homogeneous propagator over h (E = exp(-zeta w h), wd = w sqrt(1 - zeta^2),
// s = sin(wd h), c = cos(wd h), r = zeta / sqrt(1 - zeta^2)) is
//   [x1; v1] = E [c + r s, s / wd; -w s / sqrt(1 - zeta^2), c - r s] [x0; v0].
// The full step is x1 = xp(h) + A ([x0; v0] - [xp(0); xp'(0)]), linear in f0 and f1.
SdofStep SdofStep::make(double period, double damping, double h) {
  const double w = 2.0 * M_PI / period;
  const double q = std::sqrt(1.0 - damping * damping);
  const double wd = w * q;
  const double E = std::exp(-damping * w * h);
  const double s = std::sin(wd * h), c = std::cos(wd * h);
  const double r = damping / q;
  SdofStep k{};
  k.a11 = E * (c + r * s);
  k.a12 = E * s / wd;
  k.a21 = -E * w * s / q;
  k.a22 = E * (c - r * s);
  // Partial derivatives of xp(0), xp'(0) (= xp'(h)) and xp(h) with respect to f0 and f1.
  const double w2 = w * w, g = 2.0 * damping / (w2 * w * h);
  const double p0_0 = 1.0 / w2 + g, p0_1 = -g;
  const double d_0 = -1.0 / (w2 * h), d_1 = 1.0 / (w2 * h);
  const double ph_0 = g, ph_1 = 1.0 / w2 - g;
  // Coefficients on f; the ground acceleration enters as f = -a_g.
  k.b11 = -(ph_0 - k.a11 * p0_0 - k.a12 * d_0);
  k.b12 = -(ph_1 - k.a11 * p0_1 - k.a12 * d_1);
  k.b21 = -(d_0 - k.a21 * p0_0 - k.a22 * d_0);
  k.b22 = -(d_1 - k.a21 * p0_1 - k.a22 * d_1);
  return k;
}

SdofHistory sdof_history(const GroundMotion& motion, double period, double damping) {
  const SdofStep k = SdofStep::make(period, damping, motion.dt);
  const auto& a = motion.accel;
  SdofHistory h;
  h.x.assign(a.size(), 0.0);
  h.v.assign(a.size(), 0.0);
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    h.x[i + 1] = k.a11 * h.x[i] + k.a12 * h.v[i] + k.b11 * a[i] + k.b12 * a[i + 1];
    h.v[i + 1] = k.a21 * h.x[i] + k.a22 * h.v[i] + k.b21 * a[i] + k.b22 * a[i + 1];
  }
  return h;
}

SpectrumCalculator::SpectrumCalculator(std::vector<double> periods, double damping, double dt,
                                       ResponseSpectrumOptions options)
    : periods_(std::move(periods)), damping_(damping), dt_(dt), path_(options.simd) {
  if (!(damping >= 0.0 && damping < 1.0))
    throw InputError("response spectrum: damping " + std::to_string(damping) +
                     "; valid: 0 <= damping < 1 (fraction of critical)");
  if (!(dt > 0.0)) throw InputError("response spectrum: dt must be > 0 s");
  if (!(options.max_step_fraction >= 0.0))
    throw InputError("response spectrum: max_step_fraction must be >= 0");
  std::vector<std::size_t> order;  // periods > 0
  for (std::size_t i = 0; i < periods_.size(); ++i) {
    const double T = periods_[i];
    if (!(T >= 0.0) || !std::isfinite(T))
      throw InputError("response spectrum: period " + std::to_string(T) +
                       " s; valid: finite periods >= 0 s");
    PerPeriod p;
    rigid_ = rigid_ || T == 0.0;
    if (T > 0.0) {
      p.omega = 2.0 * M_PI / T;
      if (options.max_step_fraction > 0.0)
        p.substeps = std::max(1, int(std::ceil(dt / (options.max_step_fraction * T) - 1e-9)));
      order.push_back(i);
    }
    per_.push_back(p);
  }
  // Lanes ordered by sub-step count, most first (stable), so that the blocks needing inner
  // points come first and hold similar counts; padded to a multiple of kLanes.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return per_[a].substeps > per_[b].substeps;
  });
  const std::size_t nl = (order.size() + kLanes - 1) / kLanes * kLanes;
  Lanes& l = lanes_;
  for (std::vector<double>* c :
       {&l.a11, &l.a12, &l.a21, &l.a22, &l.g1, &l.b12, &l.g2, &l.b22, &l.c, &l.w2})
    c->assign(nl, 0.0);
  lane_of_.assign(periods_.size(), 0);
  for (std::size_t p = 0; p < order.size(); ++p) {
    const std::size_t i = order[p];
    lane_of_[i] = p;
    const SdofStep k = SdofStep::make(periods_[i], damping, dt);
    const double w = per_[i].omega;
    l.a11[p] = k.a11;
    l.a12[p] = k.a12;
    l.a21[p] = k.a21;
    l.a22[p] = k.a22;
    // The recurrence is run on y = x - b12 a_i, u = v - b22 a_i (state x, v of the lanes
    // below): then
    //   y_{i+1} = a11 y_i + a12 u_i + g1 a_i,  u_{i+1} = a21 y_i + a22 u_i + g2 a_i,
    // g1 = a11 b12 + a12 b22 + b11, g2 = a21 b12 + a22 b22 + b21, and x_{i+1} = y_{i+1} +
    // b12 a_{i+1}: a product and a sum fewer per step than the recurrence on x, v.
    l.g1[p] = k.a11 * k.b12 + k.a12 * k.b22 + k.b11;
    l.b12[p] = k.b12;
    l.g2[p] = k.a21 * k.b12 + k.a22 * k.b22 + k.b21;
    l.b22[p] = k.b22;
    l.c[p] = 2.0 * damping * w;
    l.w2[p] = w * w;
  }
  // Inner points: at s = j / m of the step (j = 1 .. m - 1) the exact propagator over s dt
  // for the ground acceleration linear from a_i to a_i + s (a_{i+1} - a_i), i.e. SdofStep over
  // s dt with b on a0 and a1 = (1 - s) a_i + s a_{i+1}.
  Points& q = points_;
  const std::size_t nblocks = nl / kLanes;
  for (std::size_t b = 0; b < nblocks; ++b) {
    int count = 0;
    for (std::size_t p = b * kLanes; p < std::min(order.size(), (b + 1) * kLanes); ++p)
      count = std::max(count, per_[order[p]].substeps - 1);
    q.count.push_back(count);
    q.offset.push_back(q.xx.size() / kLanes);
    for (std::vector<double>* c : {&q.xx, &q.xv, &q.xa0, &q.xa1, &q.vx, &q.vv, &q.va0, &q.va1})
      c->resize(c->size() + static_cast<std::size_t>(count) * kLanes, 0.0);
    for (int j = 1; j <= count; ++j)
      for (std::size_t p = b * kLanes; p < std::min(order.size(), (b + 1) * kLanes); ++p) {
        const std::size_t i = order[p];
        const int m = per_[i].substeps;
        if (j >= m) continue;
        const double s = double(j) / double(m);
        const SdofStep k = SdofStep::make(periods_[i], damping, s * dt);
        const std::size_t at =
            (q.offset[b] + static_cast<std::size_t>(j - 1)) * kLanes + p % kLanes;
        // On the state y, u at t_i: x_i = y_i + b12 a_i, v_i = u_i + b22 a_i (above).
        const double b12 = l.b12[p], b22 = l.b22[p];
        q.xx[at] = k.a11;
        q.xv[at] = k.a12;
        q.xa0[at] = k.a11 * b12 + k.a12 * b22 + (k.b11 + k.b12 * (1.0 - s));
        q.xa1[at] = k.b12 * s;
        q.vx[at] = k.a21;
        q.vv[at] = k.a22;
        q.va0[at] = k.a21 * b12 + k.a22 * b22 + (k.b21 + k.b22 * (1.0 - s));
        q.va1[at] = k.b22 * s;
      }
  }
}

namespace {

// Blocks of eight oscillators (core/simd.hpp): one V8 on AVX-512, two V4 on AVX2, four V2 on
// the SSE2 baseline.
using simd::V2;
using simd::V4;
using simd::V8;
using simd::vfabs;
using simd::vfma;
using simd::vfmax;
using simd::vload;
using simd::vsplat;
using simd::vstore;
static_assert(kLanes == 8, "the kernel works on blocks of eight oscillators");

struct KernelArrays {
  std::size_t blocks;
  const double *a11, *a12, *a21, *a22, *g1, *b12, *g2, *b22, *c, *w2;
  const int* count;
  const std::size_t* offset;
  const double *xx, *xv, *xa0, *xa1, *vx, *vv, *va0, *va1;
  double *xmax, *amax;  // amax: only with kAbsolute
};

// Peaks of the oscillators of U vectors of lanes (the chunk starting at lane p0) over the
// record a[0..n): per sample, the inner points from the state at t_i, then the exact step to
// t_{i+1} (SdofStep::make for dt), for the ground acceleration linear between samples; with
// kAbsolute also the peak of x'' + a_g = -(c v + w^2 x). The state stays in registers through
// the record, and the U recurrences are independent, so their steps overlap in the processor
// (one recurrence alone would wait on its own latency at every sample).
template <class V, bool kAbsolute, int U>
__attribute__((always_inline)) inline void peak_chunk(const KernelArrays& k, std::size_t p0,
                                                      const double* a, std::size_t n) {
  constexpr std::size_t W = simd::kWidth<V>;
  V sx[U], sv[U], xm[U], am[U];  // state y, u (constructor), peaks
  std::size_t p[U], q0[U];
  int count[U];
#pragma GCC unroll 8
  for (int u = 0; u < U; ++u) {
    p[u] = p0 + static_cast<std::size_t>(u) * W;
    const std::size_t b = p[u] / kLanes;
    count[u] = k.count[b];
    q0[u] = k.offset[b] * kLanes + p[u] % kLanes;
    // At rest: x_0 = v_0 = 0.
    sx[u] = -(vload<V>(k.b12 + p[u]) * vsplat<V>(n ? a[0] : 0.0));
    sv[u] = -(vload<V>(k.b22 + p[u]) * vsplat<V>(n ? a[0] : 0.0));
    xm[u] = am[u] = V{};
  }
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const V A0 = vsplat<V>(a[i]), A1 = vsplat<V>(a[i + 1]);
#pragma GCC unroll 8
    for (int u = 0; u < U; ++u) {
      for (int j = 0; j < count[u]; ++j) {
        const std::size_t q = q0[u] + static_cast<std::size_t>(j) * kLanes;
        const V xj = vfma(vload<V>(k.xx + q), sx[u],
                          vfma(vload<V>(k.xv + q), sv[u],
                               vfma(vload<V>(k.xa0 + q), A0, vload<V>(k.xa1 + q) * A1)));
        xm[u] = vfmax(xm[u], vfabs(xj));
        if (kAbsolute) {
          const V vj = vfma(vload<V>(k.vx + q), sx[u],
                            vfma(vload<V>(k.vv + q), sv[u],
                                 vfma(vload<V>(k.va0 + q), A0, vload<V>(k.va1 + q) * A1)));
          am[u] = vfmax(am[u], vfabs(vfma(vload<V>(k.c + p[u]), vj, vload<V>(k.w2 + p[u]) * xj)));
        }
      }
      const V yn = vfma(vload<V>(k.a11 + p[u]), sx[u],
                        vfma(vload<V>(k.a12 + p[u]), sv[u], vload<V>(k.g1 + p[u]) * A0));
      const V un = vfma(vload<V>(k.a21 + p[u]), sx[u],
                        vfma(vload<V>(k.a22 + p[u]), sv[u], vload<V>(k.g2 + p[u]) * A0));
      sx[u] = yn;
      sv[u] = un;
      const V xn = vfma(vload<V>(k.b12 + p[u]), A1, yn);
      xm[u] = vfmax(xm[u], vfabs(xn));
      if (kAbsolute) {
        const V vn = vfma(vload<V>(k.b22 + p[u]), A1, un);
        am[u] = vfmax(am[u], vfabs(vfma(vload<V>(k.c + p[u]), vn, vload<V>(k.w2 + p[u]) * xn)));
      }
    }
  }
#pragma GCC unroll 8
  for (int u = 0; u < U; ++u) {
    vstore(k.xmax + p[u], xm[u]);
    if (kAbsolute) vstore(k.amax + p[u], am[u]);
  }
}

// Every lane: chunks of four vectors, then the rest.
template <class V, bool kAbsolute>
__attribute__((always_inline)) inline void peak_body(const KernelArrays& k, const double* a,
                                                     std::size_t n) {
  constexpr std::size_t W = simd::kWidth<V>, kChunk = 4;
  const std::size_t lanes = k.blocks * kLanes;
  std::size_t p = 0;
  for (; p + kChunk * W <= lanes; p += kChunk * W) peak_chunk<V, kAbsolute, kChunk>(k, p, a, n);
  // The rest in one chunk (one vector alone would wait on its own latency at every sample).
  switch ((lanes - p) / W) {
    case 3:
      peak_chunk<V, kAbsolute, 3>(k, p, a, n);
      break;
    case 2:
      peak_chunk<V, kAbsolute, 2>(k, p, a, n);
      break;
    case 1:
      peak_chunk<V, kAbsolute, 1>(k, p, a, n);
      break;
    default:
      break;
  }
}

// One function per instruction set; every lane does the same operations in the same order,
// products and sums rounded separately except the explicit fused multiply-adds (simd::vfma,
// one rounding on every path), so all give the same bits (core/simd.hpp). The baseline's
// std::fma is slow without the instruction; only CPUs without AVX2 and FMA take it.
POUND_NO_CONTRACT __attribute__((target("avx512f"))) void peak_avx512(const KernelArrays& k,
                                                                      const double* a,
                                                                      std::size_t n, bool sa) {
  if (sa)
    peak_body<V8, true>(k, a, n);
  else
    peak_body<V8, false>(k, a, n);
}
POUND_NO_CONTRACT __attribute__((target("avx2,fma"))) void peak_avx2(const KernelArrays& k,
                                                                     const double* a, std::size_t n,
                                                                     bool sa) {
  if (sa)
    peak_body<V4, true>(k, a, n);
  else
    peak_body<V4, false>(k, a, n);
}
POUND_NO_CONTRACT void peak_baseline(const KernelArrays& k, const double* a, std::size_t n,
                                     bool sa) {
  if (sa)
    peak_body<V2, true>(k, a, n);
  else
    peak_body<V2, false>(k, a, n);
}

using PeakKernel = void (*)(const KernelArrays&, const double*, std::size_t, bool);

PeakKernel peak_kernel(SimdPath path) {
  static const bool avx512 = __builtin_cpu_supports("avx512f");
  static const bool avx2 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  switch (path) {
    case SimdPath::automatic:
      return avx512 ? peak_avx512 : avx2 ? peak_avx2 : peak_baseline;
    case SimdPath::avx512:
      if (!avx512) throw InputError("response spectrum: this CPU has no AVX-512");
      return peak_avx512;
    case SimdPath::avx2:
      if (!avx2) throw InputError("response spectrum: this CPU has no AVX2 and FMA");
      return peak_avx2;
    case SimdPath::baseline:
      return peak_baseline;
  }
  return peak_baseline;
}

}  // namespace

bool simd_path_available(SimdPath path) {
  switch (path) {
    case SimdPath::avx512:
      return __builtin_cpu_supports("avx512f");
    case SimdPath::avx2:
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    default:
      return true;
  }
}

void SpectrumCalculator::peaks(const std::vector<double>& a, std::vector<double>& sd,
                               std::vector<double>* sa) const {
  const std::size_t np = periods_.size();
  sd.assign(np, 0.0);
  if (sa) sa->assign(np, 0.0);
  if (sa && rigid_) {  // T = 0: a rigid oscillator moves with the ground
    double pga = 0.0;  // (a serial chain over the record: only where a period needs it)
    for (double x : a) pga = std::max(pga, std::fabs(x));
    for (std::size_t i = 0; i < np; ++i)
      if (per_[i].omega == 0.0) (*sa)[i] = pga;
  }
  const std::size_t nl = lanes_.a11.size();
  // The peaks (no allocation per spectrum for the usual sizes).
  constexpr std::size_t kStackLanes = 256;
  double stack[2 * kStackLanes];
  std::vector<double> heap;
  double* peak = stack;
  if (nl > kStackLanes) {
    heap.resize(2 * nl);
    peak = heap.data();
  }
  const Lanes& l = lanes_;
  const Points& q = points_;
  const KernelArrays k{nl / kLanes,  l.a11.data(),   l.a12.data(),    l.a21.data(), l.a22.data(),
                       l.g1.data(),  l.b12.data(),   l.g2.data(),     l.b22.data(), l.c.data(),
                       l.w2.data(),  q.count.data(), q.offset.data(), q.xx.data(),  q.xv.data(),
                       q.xa0.data(), q.xa1.data(),   q.vx.data(),     q.vv.data(),  q.va0.data(),
                       q.va1.data(), peak,           peak + nl};
  peak_kernel(path_)(k, a.data(), a.size(), sa != nullptr);
  for (std::size_t i = 0; i < np; ++i) {
    if (per_[i].omega == 0.0) continue;
    sd[i] = k.xmax[lane_of_[i]];
    if (sa) (*sa)[i] = k.amax[lane_of_[i]];
  }
}

ResponseSpectrum SpectrumCalculator::compute(const std::vector<double>& accel) const {
  ResponseSpectrum r;
  r.damping = damping_;
  r.period = periods_;
  peaks(accel, r.sd, &r.sa_abs);
  const std::size_t n = periods_.size();
  r.psv.resize(n);
  r.psa.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double w = per_[i].omega;
    r.psv[i] = w * r.sd[i];
    r.psa[i] = w == 0.0 ? r.sa_abs[i] : w * w * r.sd[i];
  }
  return r;
}

void SpectrumCalculator::compute_psa(const std::vector<double>& accel,
                                     std::vector<double>& psa) const {
  std::vector<double> sd;
  peaks(accel, sd, nullptr);
  psa.resize(periods_.size());
  double pga = 0.0;  // only with a period 0 (the generator's periods have none)
  if (rigid_)
    for (double x : accel) pga = std::max(pga, std::fabs(x));
  for (std::size_t i = 0; i < periods_.size(); ++i) {
    const double w = per_[i].omega;
    psa[i] = w == 0.0 ? pga : w * w * sd[i];
  }
}

ResponseSpectrum response_spectrum(const GroundMotion& motion, const std::vector<double>& periods,
                                   double damping, ResponseSpectrumOptions options) {
  return SpectrumCalculator(periods, damping, motion.dt, options).compute(motion.accel);
}

std::vector<double> log_spaced_periods(double t_min, double t_max, int n) {
  if (!(t_min > 0.0 && t_max > t_min && n >= 2))
    throw InputError("periods: need 0 < t_min < t_max and at least 2 periods");
  std::vector<double> t(static_cast<std::size_t>(n));
  const double l0 = std::log(t_min), l1 = std::log(t_max);
  for (int i = 0; i < n; ++i) t[std::size_t(i)] = std::exp(l0 + (l1 - l0) * i / (n - 1));
  t.front() = t_min;
  t.back() = t_max;
  return t;
}

ResponseSpectrum design_response_spectrum(const DesignSpectrum& target,
                                          const std::vector<double>& periods) {
  ResponseSpectrum r;
  r.damping = target.damping();
  r.period = periods;
  // A design spectrum gives the pseudo-acceleration; SD = Sa / w^2, PSV = Sa / w, and the
  // absolute acceleration is taken equal to the pseudo-acceleration.
  for (double T : r.period) {
    const double sa = target.sa(T), w = T > 0.0 ? 2.0 * M_PI / T : 0.0;
    r.psa.push_back(sa);
    r.sa_abs.push_back(sa);
    r.sd.push_back(w > 0.0 ? sa / (w * w) : 0.0);
    r.psv.push_back(w > 0.0 ? sa / w : 0.0);
  }
  return r;
}

}  // namespace pound

#include "motion/response_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/vec4.hpp"

namespace pound {
namespace {
constexpr std::size_t kLanes = 4;  // oscillator groups are padded to a multiple of this
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
    : periods_(std::move(periods)), damping_(damping), dt_(dt) {
  if (!(damping >= 0.0 && damping < 1.0))
    throw InputError("response spectrum: damping " + std::to_string(damping) +
                     "; valid: 0 <= damping < 1 (fraction of critical)");
  if (!(dt > 0.0)) throw InputError("response spectrum: dt must be > 0 s");
  if (!(options.max_step_fraction >= 0.0))
    throw InputError("response spectrum: max_step_fraction must be >= 0");
  for (double T : periods_) {
    if (!(T >= 0.0) || !std::isfinite(T))
      throw InputError("response spectrum: period " + std::to_string(T) +
                       " s; valid: finite periods >= 0 s");
    PerPeriod p;
    if (T > 0.0) {
      p.omega = 2.0 * M_PI / T;
      if (options.max_step_fraction > 0.0)
        p.substeps = std::max(1, int(std::ceil(dt / (options.max_step_fraction * T) - 1e-9)));
      p.step = SdofStep::make(T, damping, dt / p.substeps);
    }
    per_.push_back(p);
  }
  // Group the periods by sub-step count (in order of first appearance) and lay the groups
  // out one after another in the flat lane arrays, each padded with inert oscillators (all
  // coefficients 0) to a multiple of kLanes.
  for (std::size_t i = 0; i < per_.size(); ++i) {
    if (per_[i].omega == 0.0) continue;
    auto g = std::find_if(groups_.begin(), groups_.end(),
                          [&](const Group& x) { return x.substeps == per_[i].substeps; });
    if (g == groups_.end()) {
      groups_.emplace_back();
      g = groups_.end() - 1;
      g->substeps = per_[i].substeps;
    }
    g->index.push_back(i);
  }
  Lanes& l = lanes_;
  for (Group& g : groups_) {
    g.begin = l.a11.size();
    for (std::size_t i : g.index) {
      const SdofStep& k = per_[i].step;
      const double w = per_[i].omega;
      l.a11.push_back(k.a11);
      l.a12.push_back(k.a12);
      l.a21.push_back(k.a21);
      l.a22.push_back(k.a22);
      l.b11.push_back(k.b11);
      l.b12.push_back(k.b12);
      l.b21.push_back(k.b21);
      l.b22.push_back(k.b22);
      l.c.push_back(2.0 * damping * w);
      l.w2.push_back(w * w);
    }
    g.end = (l.a11.size() + kLanes - 1) / kLanes * kLanes;
    for (std::vector<double>* c :
         {&l.a11, &l.a12, &l.a21, &l.a22, &l.b11, &l.b12, &l.b21, &l.b22, &l.c, &l.w2})
      c->resize(g.end, 0.0);
  }
}

namespace {

// Four oscillators side by side as one simd::V4 (core/vec4.hpp).
using simd::load;
using simd::store;
using simd::V4;
using simd::vabs;
using simd::vmax;
static_assert(kLanes == 4, "the kernel works on blocks of four oscillators");

// The oscillators of one sub-step group: lanes [begin, end) of the flat arrays.
struct KernelGroup {
  std::size_t begin, end;
  int substeps;
};
struct KernelArrays {
  const double *a11, *a12, *a21, *a22, *b11, *b12, *b21, *b22, *c, *w2;
  double *x, *v, *xmax, *amax;  // amax null: no absolute acceleration
};

// Peaks of every oscillator over the record a[0..n): the exact step of SdofStep::make for
// the ground acceleration linear between samples, sub-step j of m using the values
// a_i + j (a_{i+1} - a_i) / m, every group in one pass over the samples (the groups'
// recurrences are independent, so their steps overlap in the processor). Each lane does the
// operations of the scalar recurrence in the same order and no FMA is enabled, so the AVX2
// clone and the default (SSE2) clone give the same bits on any x86-64 machine.
__attribute__((target_clones("avx2", "default"))) void peak_kernel(const KernelArrays& k,
                                                                   const KernelGroup* groups,
                                                                   std::size_t ngroups,
                                                                   const double* a, std::size_t n) {
  // Local restrict copies: the stores (memcpy) could otherwise alias the structure.
  const double* __restrict a11 = k.a11;
  const double* __restrict a12 = k.a12;
  const double* __restrict a21 = k.a21;
  const double* __restrict a22 = k.a22;
  const double* __restrict b11 = k.b11;
  const double* __restrict b12 = k.b12;
  const double* __restrict b21 = k.b21;
  const double* __restrict b22 = k.b22;
  const double* __restrict c = k.c;
  const double* __restrict w2 = k.w2;
  double* __restrict x = k.x;
  double* __restrict v = k.v;
  double* __restrict xmax = k.xmax;
  double* __restrict amax = k.amax;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    for (std::size_t gi = 0; gi < ngroups; ++gi) {
      const std::size_t begin = groups[gi].begin, end = groups[gi].end;
      const int m = groups[gi].substeps;
      const double da = (a[i + 1] - a[i]) * (1.0 / m);
      for (int j = 0; j < m; ++j) {
        const double a0 = a[i] + j * da;
        const double a1 = j + 1 == m ? a[i + 1] : a[i] + (j + 1) * da;
        const V4 A0 = {a0, a0, a0, a0}, A1 = {a1, a1, a1, a1};
        for (std::size_t p = begin; p < end; p += kLanes) {
          const V4 xp = load(x + p), vp = load(v + p);
          const V4 xn =
              load(a11 + p) * xp + load(a12 + p) * vp + load(b11 + p) * A0 + load(b12 + p) * A1;
          const V4 vn =
              load(a21 + p) * xp + load(a22 + p) * vp + load(b21 + p) * A0 + load(b22 + p) * A1;
          store(x + p, xn);
          store(v + p, vn);
          store(xmax + p, vmax(load(xmax + p), vabs(xn)));
          if (amax)  // x'' + a_g = -(c v + w^2 x)
            store(amax + p, vmax(load(amax + p), vabs(load(c + p) * vn + load(w2 + p) * xn)));
        }
      }
    }
  }
}

}  // namespace

void SpectrumCalculator::peaks(const std::vector<double>& a, std::vector<double>& sd,
                               std::vector<double>* sa) const {
  const std::size_t np = periods_.size();
  sd.assign(np, 0.0);
  if (sa) sa->assign(np, 0.0);
  double pga = 0.0;
  for (double x : a) pga = std::max(pga, std::fabs(x));
  for (std::size_t i = 0; i < np; ++i)  // T = 0: a rigid oscillator moves with the ground
    if (per_[i].omega == 0.0 && sa) (*sa)[i] = pga;
  const std::size_t nl = lanes_.a11.size();
  std::vector<double> x(nl, 0.0), v(nl, 0.0), xmax(nl, 0.0), amax(sa ? nl : 0, 0.0);
  std::vector<KernelGroup> kg;
  for (const Group& g : groups_) kg.push_back({g.begin, g.end, g.substeps});
  const Lanes& l = lanes_;
  const KernelArrays k{l.a11.data(), l.a12.data(),
                       l.a21.data(), l.a22.data(),
                       l.b11.data(), l.b12.data(),
                       l.b21.data(), l.b22.data(),
                       l.c.data(),   l.w2.data(),
                       x.data(),     v.data(),
                       xmax.data(),  sa ? amax.data() : nullptr};
  peak_kernel(k, kg.data(), kg.size(), a.data(), a.size());
  for (const Group& g : groups_)
    for (std::size_t p = 0; p < g.index.size(); ++p) {
      sd[g.index[p]] = xmax[g.begin + p];
      if (sa) (*sa)[g.index[p]] = amax[g.begin + p];
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
  double pga = 0.0;
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

}  // namespace pound

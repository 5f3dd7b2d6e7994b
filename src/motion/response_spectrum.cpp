#include "motion/response_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

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
    if (T == 0.0) continue;
    auto g = std::find_if(groups_.begin(), groups_.end(),
                          [&](const Group& x) { return x.substeps == p.substeps; });
    if (g == groups_.end()) {
      groups_.emplace_back();
      g = groups_.end() - 1;
      g->substeps = p.substeps;
    }
    g->index.push_back(per_.size() - 1);
    const SdofStep& k = p.step;
    g->a11.push_back(k.a11);
    g->a12.push_back(k.a12);
    g->a21.push_back(k.a21);
    g->a22.push_back(k.a22);
    g->b11.push_back(k.b11);
    g->b12.push_back(k.b12);
    g->b21.push_back(k.b21);
    g->b22.push_back(k.b22);
    g->c.push_back(2.0 * damping * p.omega);
    g->w2.push_back(p.omega * p.omega);
  }
  // Pad every group with inert oscillators (all coefficients 0) to a multiple of kLanes.
  for (Group& g : groups_)
    for (std::vector<double>* c :
         {&g.a11, &g.a12, &g.a21, &g.a22, &g.b11, &g.b12, &g.b21, &g.b22, &g.c, &g.w2})
      c->resize((c->size() + kLanes - 1) / kLanes * kLanes, 0.0);
}

namespace {

// One step of n independent oscillators (restrict pointers so the loop vectorises).
template <class G>
void advance(const G& g, double a0, double a1, std::size_t n, double* __restrict x,
             double* __restrict v, double* __restrict xmax) {
  const double* __restrict a11 = g.a11.data();
  const double* __restrict a12 = g.a12.data();
  const double* __restrict a21 = g.a21.data();
  const double* __restrict a22 = g.a22.data();
  const double* __restrict b11 = g.b11.data();
  const double* __restrict b12 = g.b12.data();
  const double* __restrict b21 = g.b21.data();
  const double* __restrict b22 = g.b22.data();
  for (std::size_t b = 0; b < n; b += kLanes) {  // n is a multiple of kLanes
    for (std::size_t p = b; p < b + kLanes; ++p) {
      const double xn = a11[p] * x[p] + a12[p] * v[p] + b11[p] * a0 + b12[p] * a1;
      const double vn = a21[p] * x[p] + a22[p] * v[p] + b21[p] * a0 + b22[p] * a1;
      x[p] = xn;
      v[p] = vn;
      xmax[p] = std::max(xmax[p], std::fabs(xn));
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
  std::vector<double> x, v, xmax, amax;
  for (const Group& g : groups_) {
    const std::size_t n = g.a11.size();  // padded
    x.assign(n, 0.0);
    v.assign(n, 0.0);
    xmax.assign(n, 0.0);
    amax.assign(n, 0.0);
    double* xp = x.data();
    double* vp = v.data();
    double* xmaxp = xmax.data();
    double* amaxp = amax.data();
    const int m = g.substeps;
    const double inv = 1.0 / m;
    for (std::size_t i = 0; i + 1 < a.size(); ++i) {
      const double da = (a[i + 1] - a[i]) * inv;
      for (int j = 0; j < m; ++j) {
        const double a0 = a[i] + j * da;
        const double a1 = j + 1 == m ? a[i + 1] : a[i] + (j + 1) * da;
        advance(g, a0, a1, n, xp, vp, xmaxp);
        if (sa)
          for (std::size_t p = 0; p < n; ++p)  // x'' + a_g = -(c v + w^2 x)
            amaxp[p] = std::max(amaxp[p], std::fabs(g.c[p] * vp[p] + g.w2[p] * xp[p]));
      }
    }
    for (std::size_t p = 0; p < g.index.size(); ++p) {
      sd[g.index[p]] = xmax[p];
      if (sa) (*sa)[g.index[p]] = amax[p];
    }
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

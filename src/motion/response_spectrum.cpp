#include "motion/response_spectrum.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace pound {

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
}

void SpectrumCalculator::peaks(const PerPeriod& p, const std::vector<double>& a, double& sd,
                               double& sa) const {
  sd = 0.0;
  sa = 0.0;
  if (p.omega == 0.0) {  // T = 0: a rigid oscillator moves with the ground
    for (double x : a) sa = std::max(sa, std::fabs(x));
    return;
  }
  const SdofStep& k = p.step;
  const double c = 2.0 * damping_ * p.omega, w2 = p.omega * p.omega;
  double x = 0.0, v = 0.0, xmax = 0.0, amax = 0.0;
  const int m = p.substeps;
  const double inv = 1.0 / m;
  for (std::size_t i = 0; i + 1 < a.size(); ++i) {
    const double da = (a[i + 1] - a[i]) * inv;
    double a0 = a[i];
    for (int j = 0; j < m; ++j) {
      const double a1 = j + 1 == m ? a[i + 1] : a0 + da;
      const double xn = k.a11 * x + k.a12 * v + k.b11 * a0 + k.b12 * a1;
      v = k.a21 * x + k.a22 * v + k.b21 * a0 + k.b22 * a1;
      x = xn;
      a0 = a1;
      xmax = std::max(xmax, std::fabs(x));
      amax = std::max(amax, std::fabs(c * v + w2 * x));  // x'' + a_g = -(c v + w^2 x)
    }
  }
  sd = xmax;
  sa = amax;
}

ResponseSpectrum SpectrumCalculator::compute(const std::vector<double>& accel) const {
  ResponseSpectrum r;
  r.damping = damping_;
  r.period = periods_;
  const std::size_t n = periods_.size();
  r.sd.resize(n);
  r.psv.resize(n);
  r.psa.resize(n);
  r.sa_abs.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    peaks(per_[i], accel, r.sd[i], r.sa_abs[i]);
    const double w = per_[i].omega;
    r.psv[i] = w * r.sd[i];
    r.psa[i] = w == 0.0 ? r.sa_abs[i] : w * w * r.sd[i];
  }
  return r;
}

void SpectrumCalculator::compute_psa(const std::vector<double>& accel,
                                     std::vector<double>& psa) const {
  psa.resize(periods_.size());
  double sd = 0.0, sa = 0.0;
  for (std::size_t i = 0; i < periods_.size(); ++i) {
    peaks(per_[i], accel, sd, sa);
    const double w = per_[i].omega;
    psa[i] = w == 0.0 ? sa : w * w * sd;
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

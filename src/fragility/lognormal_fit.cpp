#include "fragility/lognormal_fit.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "sampling/normal.hpp"

namespace pound {
namespace {

constexpr double kLn2Pi = 1.8378770664093453;  // ln(2 pi)
constexpr double kTail = -30.0;                // below: asymptotic series for Phi

// Phi(x) = phi(x) / (-x) * S(x) for x -> -inf, S = 1 - 1/x^2 + 3/x^4 - 15/x^6 + 105/x^8
// (Abramowitz & Stegun 26.2.12); the truncation error at x = -30 is below 1e-13.
double tail_series(double x) {
  const double r = 1.0 / (x * x);
  return 1.0 - r * (1.0 - r * (3.0 - r * (15.0 - 105.0 * r)));
}

// The log-likelihood, its gradient and the negative Hessian in centred probit parameters
// eta = a + b (t - tbar), t = ln x.
struct Terms {
  double l = 0.0, ga = 0.0, gb = 0.0, haa = 0.0, hab = 0.0, hbb = 0.0;
};

Terms evaluate(const std::vector<Observation>& obs, const std::vector<double>& t, double a,
               double b, bool derivatives) {
  Terms s;
  for (std::size_t j = 0; j < obs.size(); ++j) {
    const double eta = a + b * t[j];
    const double z = double(obs[j].z), m = double(obs[j].n - obs[j].z);
    if (z > 0) s.l += z * log_normal_cdf(eta);
    if (m > 0) s.l += m * log_normal_cdf(-eta);
    if (!derivatives) continue;
    const double lp = normal_mills(eta), lm = normal_mills(-eta);
    const double g = z * lp - m * lm;                            // dl/deta
    const double w = z * lp * (eta + lp) + m * lm * (lm - eta);  // -d2l/deta2 >= 0
    s.ga += g;
    s.gb += g * t[j];
    s.haa += w;
    s.hab += w * t[j];
    s.hbb += w * t[j] * t[j];
  }
  return s;
}

}  // namespace

const char* to_string(FitStatus s) {
  switch (s) {
    case FitStatus::ok:
      return "ok";
    case FitStatus::no_data:
      return "no_data";
    case FitStatus::none_exceed:
      return "none_exceed";
    case FitStatus::all_exceed:
      return "all_exceed";
    case FitStatus::separated:
      return "separated";
    case FitStatus::single_intensity:
      return "single_intensity";
    case FitStatus::not_increasing:
      return "not_increasing";
    case FitStatus::no_convergence:
      return "no_convergence";
  }
  return "unknown";
}

double log_normal_cdf(double x) {
  if (x < kTail) return -0.5 * x * x - 0.5 * kLn2Pi - std::log(-x) + std::log(tail_series(x));
  if (x > 0) return std::log1p(-0.5 * std::erfc(x / std::sqrt(2.0)));
  return std::log(0.5 * std::erfc(-x / std::sqrt(2.0)));
}

double normal_mills(double x) {
  if (x < kTail) return -x / tail_series(x);
  const double phi = std::exp(-0.5 * x * x - 0.5 * kLn2Pi);
  return phi / (0.5 * std::erfc(-x / std::sqrt(2.0)));
}

double LognormalFit::probability(double im) const {
  if (!finite() || !(im > 0)) return std::numeric_limits<double>::quiet_NaN();
  return normal_cdf(std::log(im / theta) / beta);
}

LognormalFit fit_lognormal(const std::vector<Observation>& all) {
  LognormalFit fit;
  std::vector<Observation> obs;
  long n = 0, z = 0;
  for (const auto& o : all)
    if (o.n > 0 && o.im > 0) {
      obs.push_back(o);
      n += o.n;
      z += o.z;
    }
  if (n == 0) return fit;
  // The empirical bracket reported without a finite estimate.
  fit.theta_lo = 0.0, fit.theta_hi = INFINITY;
  for (const auto& o : obs) {
    if (o.z == 0) fit.theta_lo = std::max(fit.theta_lo, o.im);
    if (o.z == o.n) fit.theta_hi = std::min(fit.theta_hi, o.im);
  }
  if (z == 0) return fit.status = FitStatus::none_exceed, fit;
  if (z == n) return fit.status = FitStatus::all_exceed, fit;

  // Existence of a finite maximum (Albert & Anderson 1984): the outcomes must overlap in t.
  std::set<double> distinct;
  double non_lo = INFINITY, non_hi = -INFINITY, exc_lo = INFINITY, exc_hi = -INFINITY;
  std::vector<double> t(obs.size());
  double tbar = 0.0;
  for (std::size_t j = 0; j < obs.size(); ++j) {
    t[j] = std::log(obs[j].im);
    distinct.insert(t[j]);
    tbar += double(obs[j].n) * t[j];
    if (obs[j].z > 0) exc_lo = std::min(exc_lo, t[j]), exc_hi = std::max(exc_hi, t[j]);
    if (obs[j].z < obs[j].n) non_lo = std::min(non_lo, t[j]), non_hi = std::max(non_hi, t[j]);
  }
  if (distinct.size() < 2) return fit.status = FitStatus::single_intensity, fit;
  if (non_hi <= exc_lo) return fit.status = FitStatus::separated, fit;
  if (exc_hi <= non_lo) return fit.status = FitStatus::not_increasing, fit;
  tbar /= double(n);
  double sxx = 0.0;
  for (std::size_t j = 0; j < obs.size(); ++j) {
    t[j] -= tbar;
    sxx += double(obs[j].n) * t[j] * t[j];
  }

  // Start: weighted least squares on the empirical probits (Baker 2015, "probit regression").
  double a = 0.0, b = 1.0;
  {
    double sy = 0.0, sty = 0.0;
    for (std::size_t j = 0; j < obs.size(); ++j) {
      const double y = normal_quantile((obs[j].z + 0.5) / (obs[j].n + 1.0));
      sy += double(obs[j].n) * y;
      sty += double(obs[j].n) * t[j] * y;
    }
    a = sy / double(n);
    b = sxx > 0 ? sty / sxx : 1.0;
    if (!(b > 0)) b = 1.0 / std::sqrt(sxx / double(n) + 1e-12);
  }

  // Newton with backtracking on the concave log-likelihood.
  Terms s = evaluate(obs, t, a, b, true);
  bool converged = false;
  for (int it = 1; it <= 200 && !converged; ++it) {
    fit.iterations = it;
    const double det = s.haa * s.hbb - s.hab * s.hab;
    double da, db;
    if (det > 1e-300 * (s.haa * s.hbb + 1.0)) {
      da = (s.hbb * s.ga - s.hab * s.gb) / det;
      db = (s.haa * s.gb - s.hab * s.ga) / det;
    } else {  // flat direction: gradient step
      da = s.ga / (s.haa + 1.0);
      db = s.gb / (s.hbb + 1.0);
    }
    const double slope = s.ga * da + s.gb * db;  // > 0 for an ascent direction
    double step = 1.0;
    Terms next;
    for (int k = 0; k < 60; ++k, step *= 0.5) {
      next = evaluate(obs, t, a + step * da, b + step * db, false);
      if (next.l >= s.l + 1e-4 * step * slope) break;
    }
    a += step * da;
    b += step * db;
    const double change = std::abs(step * da) + std::abs(step * db);
    s = evaluate(obs, t, a, b, true);
    converged =
        change < 1e-11 * (1.0 + std::abs(a) + std::abs(b)) ||
        std::abs(s.ga) + std::abs(s.gb * std::sqrt(double(n) / (sxx + 1e-300))) < 1e-10 * double(n);
  }
  fit.loglik = s.l;
  if (!converged || !std::isfinite(a) || !std::isfinite(b))
    return fit.status = FitStatus::no_convergence, fit;
  if (!(b > 0)) return fit.status = FitStatus::not_increasing, fit;

  fit.status = FitStatus::ok;
  fit.theta = std::exp(tbar - a / b);
  fit.beta = 1.0 / b;
  // Inverse observed information in (a, b), then the delta method with
  // J = d(ln theta, beta)/d(a, b) = [[-1/b, a/b^2], [0, -1/b^2]].
  const double det = s.haa * s.hbb - s.hab * s.hab;
  if (det > 0) {
    const double caa = s.hbb / det, cab = -s.hab / det, cbb = s.haa / det;
    const double j11 = -1.0 / b, j12 = a / (b * b), j22 = -1.0 / (b * b);
    fit.var_ln_theta = j11 * j11 * caa + 2 * j11 * j12 * cab + j12 * j12 * cbb;
    fit.cov_ln_theta_beta = j11 * j22 * cab + j12 * j22 * cbb;
    fit.var_beta = j22 * j22 * cbb;
  } else {
    fit.var_ln_theta = fit.var_beta = INFINITY;
  }
  return fit;
}

}  // namespace pound

#include "motion/motion_processing.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/error.hpp"

namespace pound {
namespace {

// Exact integration of a piecewise-linear acceleration from rest (see the header). The
// increments, which do not depend on each other, are formed first (a loop the compiler
// vectorises), then summed: the same operations in the same order as the single loop
//   v[i+1] = v[i] + 0.5 dt (a[i] + a[i+1]),  d[i+1] = d[i] + dt v[i] + dt^2 (2 a[i] + a[i+1]) / 6,
// so the same bits, without the divisions in the serial chain.
void integrate_samples(const std::vector<double>& a, double dt, std::vector<double>& v,
                       std::vector<double>& d) {
  const std::size_t n = a.size();
  v.resize(n);
  d.resize(n);
  if (n == 0) return;
  double* __restrict pv = v.data();
  double* __restrict pd = d.data();
  const double* __restrict pa = a.data();
  const double h = 0.5 * dt, q = dt * dt;  // as the expressions above group them
  for (std::size_t i = 0; i + 1 < n; ++i) {
    pv[i + 1] = h * (pa[i] + pa[i + 1]);
    pd[i + 1] = q * (2.0 * pa[i] + pa[i + 1]) / 6.0;
  }
  double vi = 0.0, di = 0.0;  // the running sums in registers
  pv[0] = pd[0] = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    const double dn = di + dt * vi + pd[i + 1];
    vi = vi + pv[i + 1];
    di = dn;
    pv[i + 1] = vi;
    pd[i + 1] = di;
  }
}

}  // namespace

GroundKinematics integrate(const GroundMotion& motion) {
  GroundKinematics k;
  integrate_samples(motion.accel, motion.dt, k.velocity, k.displacement);
  return k;
}

// The correction a_c = (1 - s) (c0 s + c1 s^2 + c2 s^3 + c3 s^4), s = t / T (see the header).
struct BaselineCorrector::Impl {
  static constexpr int kTerms = 4;
  std::size_t n = 0;
  double dt = 0.0, T = 0.0;
  Eigen::MatrixXd basis_d;  // displacement of each basis acceleration at the samples
  Eigen::FullPivLU<Eigen::Matrix<double, kTerms + 2, kTerms + 2>> kkt;
  std::vector<double> s, w;  // s_i = t_i / T and (1 - s_i) s_i
  std::vector<double> v, d;  // scratch: the record's velocity and displacement
};

BaselineCorrector::BaselineCorrector(std::size_t n, double dt) : impl_(std::make_unique<Impl>()) {
  constexpr int kTerms = Impl::kTerms;
  Impl& d = *impl_;
  d.n = n;
  d.dt = dt;
  d.T = dt * double(n - 1);
  // Displacement of each basis acceleration, by the same integrator as the record's.
  d.basis_d.resize(Eigen::Index(n), kTerms);
  Eigen::Matrix<double, 2, kTerms> ends;
  std::vector<double> phi(n), pv, pd;
  for (int k = 0; k < kTerms; ++k) {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = double(i) * dt / d.T;
      double p = 1.0 - x;
      for (int j = 0; j <= k; ++j) p *= x;
      phi[i] = p;
    }
    integrate_samples(phi, dt, pv, pd);
    for (std::size_t i = 0; i < n; ++i) d.basis_d(Eigen::Index(i), k) = pd[i];
    ends(0, k) = pv.back();
    ends(1, k) = pd.back();
  }
  // KKT system of min |D c - d|^2 subject to E c = [v_end, d_end].
  Eigen::Matrix<double, kTerms + 2, kTerms + 2> kkt = Eigen::Matrix<double, 6, 6>::Zero();
  kkt.topLeftCorner<kTerms, kTerms>() = d.basis_d.transpose() * d.basis_d;
  kkt.topRightCorner<kTerms, 2>() = ends.transpose();
  kkt.bottomLeftCorner<2, kTerms>() = ends;
  d.kkt.compute(kkt);
  d.s.resize(n);
  d.w.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    d.s[i] = double(i) * dt / d.T;
    d.w[i] = (1.0 - d.s[i]) * d.s[i];
  }
}

BaselineCorrector::~BaselineCorrector() = default;

void BaselineCorrector::apply(std::vector<double>& accel) {
  constexpr int kTerms = Impl::kTerms;
  Impl& d = *impl_;
  if (accel.size() != d.n)
    throw std::logic_error("baseline correction: " + std::to_string(accel.size()) +
                           " samples for a corrector of " + std::to_string(d.n));
  std::vector<double>& v = d.v;
  std::vector<double>& disp_v = d.d;
  integrate_samples(accel, d.dt, v, disp_v);
  const Eigen::Map<const Eigen::VectorXd> disp(disp_v.data(), Eigen::Index(d.n));
  Eigen::Matrix<double, kTerms + 2, 1> rhs;
  rhs.head<kTerms>() = d.basis_d.transpose() * disp;
  rhs(kTerms) = v.back();
  rhs(kTerms + 1) = disp_v.back();
  const Eigen::Matrix<double, kTerms + 2, 1> sol = d.kkt.solve(rhs);
  const double c0 = sol(0), c1 = sol(1), c2 = sol(2), c3 = sol(3);
  const double* __restrict s = d.s.data();
  const double* __restrict w = d.w.data();
  double* __restrict a = accel.data();
  for (std::size_t i = 0; i < d.n; ++i) a[i] -= w[i] * (c0 + s[i] * (c1 + s[i] * (c2 + s[i] * c3)));
}

GroundMotion baseline_correct(const GroundMotion& motion) {
  if (motion.accel.size() < 8) return motion;
  GroundMotion out = motion;
  BaselineCorrector(motion.accel.size(), motion.dt).apply(out.accel);
  return out;
}

GroundMotion truncate(const GroundMotion& motion, double seconds) {
  if (!(seconds > 0.0))
    throw InputError(motion.name + ": truncation length " + std::to_string(seconds) +
                     " s; valid: a duration > 0 s");
  GroundMotion out = motion;
  const double last = seconds / motion.dt + 1e-9;
  const std::size_t keep = static_cast<std::size_t>(std::floor(last)) + 1;
  if (keep < out.accel.size()) out.accel.resize(keep);
  return out;
}

GroundMotion scale(const GroundMotion& motion, double factor) {
  GroundMotion out = motion;
  for (double& a : out.accel) a *= factor;
  return out;
}

}  // namespace pound

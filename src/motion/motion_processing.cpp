#include "motion/motion_processing.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace pound {
namespace {

// Exact integration of a piecewise-linear acceleration from rest (see the header).
void integrate_samples(const std::vector<double>& a, double dt, std::vector<double>& v,
                       std::vector<double>& d) {
  const std::size_t n = a.size();
  v.assign(n, 0.0);
  d.assign(n, 0.0);
  for (std::size_t i = 0; i + 1 < n; ++i) {
    v[i + 1] = v[i] + 0.5 * dt * (a[i] + a[i + 1]);
    d[i + 1] = d[i] + dt * v[i] + dt * dt * (2.0 * a[i] + a[i + 1]) / 6.0;
  }
}

}  // namespace

GroundKinematics integrate(const GroundMotion& motion) {
  GroundKinematics k;
  integrate_samples(motion.accel, motion.dt, k.velocity, k.displacement);
  return k;
}

GroundMotion baseline_correct(const GroundMotion& motion) {
  constexpr int kTerms = 4;  // a_c = (1 - s) (c0 s + c1 s^2 + c2 s^3 + c3 s^4), s = t / T
  const std::size_t n = motion.accel.size();
  if (n < 8) return motion;
  const double T = motion.duration();

  // Displacement of the record and of each basis acceleration, by the same integrator.
  std::vector<double> v, d;
  integrate_samples(motion.accel, motion.dt, v, d);
  Eigen::MatrixXd basis_d(n, kTerms);
  Eigen::Vector2d rhs_end(v.back(), d.back());
  Eigen::Matrix<double, 2, kTerms> ends;
  std::vector<double> phi(n), pv, pd;
  for (int k = 0; k < kTerms; ++k) {
    for (std::size_t i = 0; i < n; ++i) {
      const double x = double(i) * motion.dt / T;
      double p = 1.0 - x;
      for (int j = 0; j <= k; ++j) p *= x;
      phi[i] = p;
    }
    integrate_samples(phi, motion.dt, pv, pd);
    for (std::size_t i = 0; i < n; ++i) basis_d(Eigen::Index(i), k) = pd[i];
    ends(0, k) = pv.back();
    ends(1, k) = pd.back();
  }
  const Eigen::Map<const Eigen::VectorXd> disp(d.data(), Eigen::Index(n));

  // KKT system of min |D c - d|^2 subject to E c = [v_end, d_end].
  Eigen::Matrix<double, kTerms + 2, kTerms + 2> kkt = Eigen::Matrix<double, 6, 6>::Zero();
  kkt.topLeftCorner<kTerms, kTerms>() = basis_d.transpose() * basis_d;
  kkt.topRightCorner<kTerms, 2>() = ends.transpose();
  kkt.bottomLeftCorner<2, kTerms>() = ends;
  Eigen::Matrix<double, kTerms + 2, 1> rhs;
  rhs.head<kTerms>() = basis_d.transpose() * disp;
  rhs.tail<2>() = rhs_end;
  const Eigen::Matrix<double, kTerms + 2, 1> sol = kkt.fullPivLu().solve(rhs);

  GroundMotion out = motion;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = double(i) * motion.dt / T;
    out.accel[i] -= (1.0 - s) * s * (sol(0) + s * (sol(1) + s * (sol(2) + s * sol(3))));
  }
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

#include "solver/run_recorder.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace pound {
// QuinticHermite::absmax_bound() of every floor's displacement (out[i]) and of every storey's
// drift (out[n + i]; below[i] = 1 where the storey joins floor i - 1, 0 where it stands on the
// ground, so that the drift of a first storey is its floor's displacement) over a step of
// length h from the values u, velocities v and accelerations a at both ends. One pass over the
// floors, compiled for AVX2 and the baseline (no fused multiply-add, so the same bits), instead
// of a bound and a branch per quintic (peaks_over_step refines only where a bound could raise a
// peak).
__attribute__((target_clones("avx2", "default"))) void RunRecorder::peak_bounds(
    int n, const double* __restrict u0, const double* __restrict u1, const double* __restrict v0,
    const double* __restrict v1, const double* __restrict a0, const double* __restrict a1,
    const double* __restrict below, double h, double h2, double* __restrict out) {
  const auto bound = [](double g0, double g1, double m0, double m1, double c0, double c1) {
    return QuinticHermite::absmax_bound(g0, g1, m0, m1, c0, c1);
  };
  for (int i = 0; i < n; ++i)
    out[i] = bound(u0[i], u1[i], h * v0[i], h * v1[i], h2 * a0[i], h2 * a1[i]);
  if (n > 0) out[n] = out[0];  // floor 0 stands on the ground
  for (int i = 1; i < n; ++i) {
    const double w = below[i];
    out[n + i] = bound(u0[i] - w * u0[i - 1], u1[i] - w * u1[i - 1],
                       h * v0[i] - w * (h * v0[i - 1]), h * v1[i] - w * (h * v1[i - 1]),
                       h2 * a0[i] - w * (h2 * a0[i - 1]), h2 * a1[i] - w * (h2 * a1[i - 1]));
  }
}

RunRecorder::RunRecorder(const AssembledRow& row, const std::vector<RowStorey>& storeys,
                         bool contacts, bool history)
    : n_(row.dofs()),
      ns_(static_cast<int>(row.sites.size())),
      contacts_(contacts),
      history_(history) {
  below_.assign(n_, -1);
  weight_.assign(n_, 0.0);
  for (int i = 0; i < n_; ++i) {  // a row's floors stand on the floor before them or the ground
    const int b = storeys[i].below;
    if (b != -1 && b != i - 1)
      throw std::logic_error("storey below floor DOF " + std::to_string(i));
    below_[i] = b;
    weight_[i] = b < 0 ? 0.0 : 1.0;
  }
  bounds_.assign(2 * n_, 0.0);
  for (const auto& s : row.sites) site_dofs_.emplace_back(s.dof_left, s.dof_right);
}

void RunRecorder::start(const Eigen::VectorXd& u0) {
  r_.peak_disp.setZero(n_);
  r_.peak_drift.setZero(n_);
  r_.peak_abs_accel.setZero(n_);
  r_.sites.assign(ns_, SiteResult{});
  for (int s = 0; s < ns_ && !contacts_; ++s)
    r_.sites[s].peak_approach = u0(site_dofs_[s].first) - u0(site_dofs_[s].second);
}

void RunRecorder::history(double t, const Eigen::VectorXd& u, const Eigen::VectorXd& a_rel,
                          double ag, const Eigen::VectorXd& force, const Eigen::VectorXd& shear) {
  r_.history.t.push_back(t);
  r_.history.u.push_back(u);
  r_.history.a_abs.push_back(a_rel.array() + ag);
  r_.history.force.push_back(force);
  r_.history.shear.push_back(shear);
}

void RunRecorder::finish(double t, const Eigen::VectorXd& u, const Eigen::VectorXd& v) {
  r_.u_end = u;
  r_.v_end = v;
  r_.t_end = t;
}

void RunRecorder::throw_non_finite(double t, const char* what) {
  throw NumericalError(std::string(what) + ": non-finite state at t = " + std::to_string(t) +
                       " s (the response diverged; check stiffness, masses and step)");
}

}  // namespace pound

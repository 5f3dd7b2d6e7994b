#include "solver/run_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/error.hpp"

namespace pound {
// QuinticHermite::absmax_bound() of every floor's displacement (out[i]) and of every storey's
// drift (out[n + i]; below[i] = 1 where the storey joins floor i - 1, 0 where it stands on the
// ground, so that the drift of a first storey is its floor's displacement) over a step of
// length h from the values u, velocities v and accelerations a at both ends. One pass over the
// floors, compiled for AVX2 and the baseline (no fused multiply-add, so the same bits), instead
// of a bound and a branch per quintic (peaks_over_step refines only where a bound could raise a
// peak).
// A file-local function: clang refuses target_clones on a member whose declaration the header
// has already used (peaks_over_step), so RunRecorder::peak_bounds forwards to it.
namespace {
__attribute__((target_clones("avx2", "default"))) void peak_bounds_kernel(
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

// The same for a row with flexible foundations (issue 29): the drift of DOF i is
// u_i + wb_i u_bi + wr_i u_ri (wb_i = -1 on the DOF bi below, wr_i = -h_i on the base rotation
// ri; weight 0 and the DOF itself where there is none), each coefficient formed in the order of
// peaks_over_step's scalar quintics, so that every bound has their bits. The DOFs from nf on
// (the bases' sway and rotation, after every floor: AssembledRow) are foundation springs, whose
// drift is their displacement: their bound is the displacement's, not formed twice.
__attribute__((target_clones("avx2", "default"))) void peak_bounds_general_kernel(
    int n, int nf, const double* __restrict u0, const double* __restrict u1,
    const double* __restrict v0, const double* __restrict v1, const double* __restrict a0,
    const double* __restrict a1, const int* __restrict bi, const double* __restrict wb,
    const int* __restrict ri, const double* __restrict wr, double h, double h2,
    double* __restrict out) {
  const auto bound = [](double g0, double g1, double m0, double m1, double c0, double c1) {
    return QuinticHermite::absmax_bound(g0, g1, m0, m1, c0, c1);
  };
  for (int i = 0; i < n; ++i)
    out[i] = bound(u0[i], u1[i], h * v0[i], h * v1[i], h2 * a0[i], h2 * a1[i]);
  for (int i = nf; i < n; ++i) out[n + i] = out[i];
  for (int i = 0; i < nf; ++i) {
    const int b = bi[i], r = ri[i];
    const double kb = wb[i], kr = wr[i], kbh = kb * h, kbh2 = kb * h2, krh = kr * h, krh2 = kr * h2;
    out[n + i] =
        bound(u0[i] + kb * u0[b] + kr * u0[r], u1[i] + kb * u1[b] + kr * u1[r],
              h * v0[i] + kbh * v0[b] + krh * v0[r], h * v1[i] + kbh * v1[b] + krh * v1[r],
              h2 * a0[i] + kbh2 * a0[b] + krh2 * a0[r], h2 * a1[i] + kbh2 * a1[b] + krh2 * a1[r]);
  }
}
}  // namespace

void RunRecorder::peak_bounds(int n, const double* u0, const double* u1, const double* v0,
                              const double* v1, const double* a0, const double* a1,
                              const double* below, double h, double h2, double* out) {
  peak_bounds_kernel(n, u0, u1, v0, v1, a0, a1, below, h, h2, out);
}

RunRecorder::RunRecorder(const AssembledRow& row, const std::vector<RowStorey>& storeys,
                         bool contacts, bool history)
    : n_(row.dofs()),
      ns_(static_cast<int>(row.sites.size())),
      nf_(row.floors),
      contacts_(contacts),
      history_(history) {
  below_.assign(n_, -1);
  weight_.assign(n_, 0.0);
  rot_.assign(n_, -1);
  rot_h_.assign(n_, 0.0);
  for (int i = 0; i < n_; ++i) {  // a row's floors stand on the floor before them or the ground
    const int b = storeys[i].below;
    // ... or on a flexible foundation (issue 29): the drifts of peaks_over_step's general path.
    if ((b != -1 && b != i - 1) || storeys[i].rot >= 0) general_ = true;
    below_[i] = b;
    weight_[i] = b < 0 ? 0.0 : 1.0;
    rot_[i] = storeys[i].rot;
    rot_h_[i] = storeys[i].rot >= 0 ? storeys[i].p.h : 0.0;
  }
  bounds_.assign(2 * n_, 0.0);
  // The general path's drift coefficients (peak_bounds_general_kernel).
  g_below_.assign(n_, 0), g_rot_.assign(n_, 0);
  g_wb_.assign(n_, 0.0), g_wr_.assign(n_, 0.0);
  for (int i = 0; i < n_; ++i) {
    g_below_[i] = below_[i] >= 0 ? below_[i] : i;
    g_wb_[i] = below_[i] >= 0 ? -1.0 : 0.0;
    g_rot_[i] = rot_[i] >= 0 ? rot_[i] : i;
    g_wr_[i] = rot_[i] >= 0 ? -rot_h_[i] : 0.0;
  }
  for (const auto& s : row.sites) site_points_.emplace_back(s.left, s.right);
}

void RunRecorder::set_collapse(const std::vector<RowStorey>& storeys, double ratio) {
  check_collapse_ = std::isfinite(ratio);
  if (!check_collapse_) return;
  collapse_drift_.assign(n_, 0.0);
  last_drift_.assign(n_, 0.0);
  building_.assign(n_, 0);
  storey_no_.assign(n_, 1);
  nb_ = 0;
  for (int i = 0; i < n_; ++i) {
    building_[i] = storeys[i].building;
    nb_ = std::max(nb_, building_[i] + 1);
    if (storeys[i].foundation) {  // a foundation spring: no storey, no collapse drift
      collapse_drift_[i] = std::numeric_limits<double>::infinity();
      storey_no_[i] = 0;
      continue;
    }
    collapse_drift_[i] = ratio * storeys[i].p.h;
    const int b = below_[i];
    storey_no_[i] = b >= 0 && !storeys[b].foundation ? storey_no_[b] + 1 : 1;
  }
}

void RunRecorder::start(const Eigen::VectorXd& u0) {
  r_.collapse.assign(check_collapse_ ? nb_ : 0, BuildingCollapse{});
  r_.stopped = false;
  new_collapses_ = 0;
  held_.assign(n_, 0);
  any_held_ = false;
  energy_held_ = false;
  for (int k = 0; k < n_ && check_collapse_; ++k) last_drift_[k] = drift(u0.data(), k);
  r_.peak_disp.setZero(n_);
  r_.peak_drift.setZero(n_);
  r_.peak_abs_accel.setZero(n_);
  r_.sites.assign(ns_, SiteResult{});
  for (int s = 0; s < ns_ && !contacts_; ++s)
    r_.sites[s].peak_approach =
        site_points_[s].first.of(u0.data()) - site_points_[s].second.of(u0.data());
}

void RunRecorder::merge_from(const RunRecorder& other, const std::vector<int>& dof_map) {
  const RowResult& o = other.r_;
  for (int k = 0; k < other.n_; ++k) {
    const int d = dof_map[static_cast<std::size_t>(k)];
    r_.peak_disp(d) = std::max(r_.peak_disp(d), o.peak_disp(k));
    r_.peak_drift(d) = std::max(r_.peak_drift(d), o.peak_drift(k));
    r_.peak_abs_accel(d) = std::max(r_.peak_abs_accel(d), o.peak_abs_accel(k));
  }
  r_.steps += o.steps;
  r_.rejected += o.rejected;
  r_.events += o.events;
  r_.exact_steps += o.exact_steps;
  r_.steps_from_free = r_.steps;
}

void RunRecorder::collapse(int b, int storey, double t, CollapseCause cause) {
  if (r_.collapse.empty() || r_.collapse[b].collapsed) return;
  r_.collapse[b] = {true, t, storey, cause};
  ++new_collapses_;
}

std::vector<int> RunRecorder::hold_collapsed(bool& all) {
  std::vector<int> now;
  all = true;
  for (int b = 0; b < nb_; ++b) all = all && collapsed(b);
  for (int k = 0; k < n_; ++k)
    if (!held_[k] && collapsed(building_[k])) {
      held_[k] = 1;
      now.push_back(k);
    }
  any_held_ = any_held_ || !now.empty();
  return now;
}

void RunRecorder::peaks_over_step_general(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                                          const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1,
                                          double t0, double h) {
  const int n = n_;
  const double h2 = h * h;
  const double *u0 = y0.data(), *u1 = y1.data(), *v0 = u0 + n, *v1 = u1 + n;
  const double *a0 = dy0.data() + n, *a1 = dy1.data() + n;
  double* bound = bounds_.data();
  peak_bounds_general_kernel(n, nf_, u0, u1, v0, v1, a0, a1, g_below_.data(), g_wb_.data(),
                             g_rot_.data(), g_wr_.data(), h, h2, bound);
  for (int i = 0; i < n; ++i) {
    if (any_held_ && held_[i]) continue;
    // The quintic of the displacement, then of the drift q = u_i - u_below - h_i u_rot (each
    // coefficient from the values, rates and accelerations at both ends), refined only where its
    // bound could raise the peak (QuinticHermite::raise_peak).
    const bool disp = !(bound[i] <= r_.peak_disp(i)), drift = !(bound[n + i] <= r_.peak_drift(i));
    if (!disp && !drift) continue;
    const QuinticHermite c{u0[i], u1[i], h * v0[i], h * v1[i], h2 * a0[i], h2 * a1[i]};
    if (disp) r_.peak_disp(i) = c.refine_peak(r_.peak_disp(i));
    const int b = below_[i], r = rot_[i];
    if (b < 0 && r < 0) {  // a storey on the ground or a foundation spring: its drift is u_i
      r_.peak_drift(i) = r_.peak_disp(i);
      if (check_collapse_ && r_.peak_drift(i) > collapse_drift_[i]) step_collapse(i, c, t0, h);
      continue;
    }
    if (!drift) continue;
    QuinticHermite d = c;
    if (b >= 0) {
      d.g0 += -1.0 * u0[b];
      d.g1 += -1.0 * u1[b];
      d.m0 += -1.0 * h * v0[b];
      d.m1 += -1.0 * h * v1[b];
      d.c0 += -1.0 * h2 * a0[b];
      d.c1 += -1.0 * h2 * a1[b];
    }
    if (r >= 0) {
      const double w = -rot_h_[i];
      d.g0 += w * u0[r];
      d.g1 += w * u1[r];
      d.m0 += w * h * v0[r];
      d.m1 += w * h * v1[r];
      d.c0 += w * h2 * a0[r];
      d.c1 += w * h2 * a1[r];
    }
    r_.peak_drift(i) = d.refine_peak(r_.peak_drift(i));
    if (check_collapse_ && r_.peak_drift(i) > collapse_drift_[i]) step_collapse(i, d, t0, h);
  }
}

void RunRecorder::sampled_collapse(int k, double d, double t, double h) {
  const int b = building_[k];
  if (collapsed(b)) return;
  // |drift| passes the limit between the last sample d0 and d, linear between them.
  const double d0 = last_drift_[k], lim = d > 0.0 ? collapse_drift_[k] : -collapse_drift_[k];
  double th = 1.0;
  if ((d - lim) * (d0 - lim) < 0.0) th = (lim - d0) / (d - d0);
  collapse(b, storey_no_[k], t - h + th * h, CollapseCause::drift);
}

void RunRecorder::step_collapse(int k, const QuinticHermite& d, double t0, double h) {
  const int b = building_[k];
  if (collapsed(b)) return;
  // The first theta in (0, 1] where |d(theta)| passes the limit (|d(0)| is below it: the peak
  // was): a scan, then bisection.
  const double lim = collapse_drift_[k];
  auto over = [&](double th) { return std::fabs(d.at(th)) > lim; };
  double lo = 0.0, hi = 1.0;
  constexpr int kScan = 64;
  for (int i = 1; i <= kScan; ++i) {
    if (over(double(i) / kScan)) {
      hi = double(i) / kScan;
      break;
    }
    lo = double(i) / kScan;
  }
  for (int it = 0; it < 50; ++it) {
    const double mid = 0.5 * (lo + hi);
    (over(mid) ? hi : lo) = mid;
  }
  collapse(b, storey_no_[k], t0 + hi * h, CollapseCause::drift);
}

void RunRecorder::history(double t, const Eigen::VectorXd& u, const Eigen::VectorXd& a_rel,
                          const double* ag, const Eigen::VectorXd& force,
                          const Eigen::VectorXd& shear) {
  r_.history.t.push_back(t);
  r_.history.u.push_back(u);
  r_.history.a_abs.push_back(a_rel + Eigen::Map<const Eigen::VectorXd>(ag, a_rel.size()));
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

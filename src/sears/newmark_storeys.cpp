#include "sears/newmark_storeys.hpp"

#include <algorithm>
#include <cmath>

namespace pound::sears {

NewmarkStoreys::NewmarkStoreys(const AssembledRow& a, const Eigen::VectorXd& u0)
    : storeys_(a.storeys.size() == static_cast<std::size_t>(a.dofs()) ? a.storeys
                                                                      : elastic_storeys(a)),
      linear_(a.linear) {
  const int n = a.dofs();
  committed_.assign(n, StoreyState{});
  r_.setZero(n);
  building_linear_.assign(a.offset.size(), 1);
  strain_.assign(a.offset.size(), -1.0);
  for (int i = 0; i < n; ++i) {
    const RowStorey& s = storeys_[i];
    if (!s.law->linear()) building_linear_[s.building] = 0;
    // Monotone loading from rest to the initial drift.
    const double d = drift(u0, i);
    r_(i) = s.p.k0 * d - s.law->advance(s.p, StoreyState{}, 0.0, d, committed_[i]);
  }
  trial_ = committed_;
  r_trial_ = r_;
  rd_.setZero(n);
  rd_trial_ = rd_;
  rd_prev_ = rd_;
  for (const auto& st : storeys_) tangent_damping_ = tangent_damping_ || st.damping_a1 > 0.0;
  can_fail_.assign(n, 0);
  failed_in_step_.assign(n, 0);
  for (int i = 0; i < n; ++i) can_fail_[i] = storeys_[i].law->can_fail();
}

Eigen::MatrixXd NewmarkStoreys::influence(const Eigen::LLT<Eigen::MatrixXd>& mt) const {
  const int n = static_cast<int>(storeys_.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    B(j, j) = 1.0;
    if (storeys_[j].below >= 0) B(storeys_[j].below, j) = -1.0;
    if (storeys_[j].rot >= 0) B(storeys_[j].rot, j) = -storeys_[j].p.h;
  }
  return mt.solve(B);
}

Eigen::VectorXd NewmarkStoreys::forces(const Eigen::VectorXd& r) const {
  Eigen::VectorXd Br = r;
  for (int j = 0, n = static_cast<int>(storeys_.size()); j < n; ++j) {
    if (storeys_[j].below >= 0) Br(storeys_[j].below) -= r(j);
    if (storeys_[j].rot >= 0) Br(storeys_[j].rot) -= storeys_[j].p.h * r(j);
  }
  return Br;
}

bool NewmarkStoreys::trial(const Eigen::VectorXd& u, const Eigen::VectorXd& u_end,
                           const Eigen::VectorXd& v_end, Eigen::VectorXd& guess) {
  bool converged = true;
  for (int i = 0, n = static_cast<int>(storeys_.size()); i < n; ++i) {
    const RowStorey& s = storeys_[i];
    const double d1 = drift(u_end, i);
    double V;
    if (can_fail_[i] && failed_in_step_[i]) {
      V = s.law->shear(s.p, trial_[i], d1, trial_[i].x);  // failed: no shear
    } else {
      V = s.law->advance(s.p, committed_[i], drift(u, i), d1, trial_[i]);
      if (can_fail_[i] && s.law->failed(s.p, trial_[i])) failed_in_step_[i] = 1;
    }
    double r = s.p.k0 * d1 - V, fd = 0.0;
    if (s.damping_a1 > 0.0) {  // tangent damping of the step's start (newmark_storeys.hpp)
      double slope = s.p.k0, offset = 0.0;
      s.law->branch_line(s.p, committed_[i], slope, offset);
      fd = s.damping_a1 * (std::max(slope, 0.0) - s.p.k0) * drift(v_end, i);
      r -= fd;
      rd_trial_(i) = fd;
    }
    if (std::fabs(r - guess(i)) > 1e-12 * (std::fabs(V) + std::fabs(s.p.k0 * d1) + std::fabs(fd)))
      converged = false;
    guess(i) = r;
  }
  r_trial_ = guess;
  return converged;
}

void NewmarkStoreys::commit() {
  std::fill(failed_in_step_.begin(), failed_in_step_.end(), 0);
  committed_.swap(trial_);
  trial_ = committed_;
  r_ = r_trial_;
  if (tangent_damping_) {
    rd_prev_ = rd_;
    rd_ = rd_trial_;
  }
}

void NewmarkStoreys::set_state(const std::vector<StoreyState>& states, const Eigen::VectorXd& u,
                               const Eigen::VectorXd& v) {
  committed_ = states;
  trial_ = committed_;
  std::fill(failed_in_step_.begin(), failed_in_step_.end(), 0);
  for (int i = 0, n = static_cast<int>(storeys_.size()); i < n; ++i) {
    const RowStorey& s = storeys_[i];
    const double d = drift(u, i);
    r_(i) = s.p.k0 * d - s.law->shear(s.p, committed_[i], d, committed_[i].x);
    rd_(i) = 0.0;
    if (s.damping_a1 > 0.0) {  // the tangent damper at the drift rate (trial())
      double slope = s.p.k0, offset = 0.0;
      s.law->branch_line(s.p, committed_[i], slope, offset);
      rd_(i) = s.damping_a1 * (std::max(slope, 0.0) - s.p.k0) * drift(v, i);
      r_(i) -= rd_(i);
    }
  }
  r_trial_ = r_;
  rd_trial_ = rd_;
  rd_prev_ = rd_;
}

double NewmarkStoreys::damper_work(const Eigen::VectorXd& u_prev, const Eigen::VectorXd& u) const {
  if (!tangent_damping_) return 0.0;
  double w = 0.0;
  for (int i = 0, n = static_cast<int>(storeys_.size()); i < n; ++i)
    w += 0.5 * (rd_prev_(i) + rd_(i)) * (drift(u, i) - drift(u_prev, i));
  return w;
}

const std::vector<double>& NewmarkStoreys::strain_by_building(const Eigen::VectorXd& u) {
  std::fill(strain_.begin(), strain_.end(), -1.0);
  for (std::size_t i = 0; i < storeys_.size(); ++i) {
    const RowStorey& s = storeys_[i];
    if (building_linear_[s.building]) continue;
    double& e = strain_[s.building];
    e = std::max(e, 0.0) + s.law->stored(s.p, committed_[i], drift(u, int(i)), committed_[i].x);
  }
  return strain_;
}

double NewmarkStoreys::shear(const Eigen::VectorXd& u, int i) const {
  return storeys_[i].p.k0 * drift(u, i) - r_(i) - rd_(i);
}

double NewmarkStoreys::dissipated(const Eigen::VectorXd& u, int i) const {
  const RowStorey& s = storeys_[i];
  return s.law->dissipated(s.p, committed_[i], drift(u, i), committed_[i].x);
}

double NewmarkStoreys::stored(const Eigen::VectorXd& u) const {
  double e = 0.0;
  for (std::size_t i = 0; i < storeys_.size(); ++i) {
    const RowStorey& s = storeys_[i];
    const double d = drift(u, int(i));
    e += s.law->stored(s.p, committed_[i], d, committed_[i].x);
    // P-Delta on the chord (the drift on a fixed base).
    const double c = s.rot >= 0 ? storey_chord(s, int(i), u.data()) : d;
    if (s.kg != 0.0) e -= 0.5 * s.kg * c * c;
  }
  return e;
}

}  // namespace pound::sears

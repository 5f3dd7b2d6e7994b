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
}

Eigen::MatrixXd NewmarkStoreys::influence(const Eigen::LLT<Eigen::MatrixXd>& mt) const {
  const int n = static_cast<int>(storeys_.size());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n; ++j) {
    B(j, j) = 1.0;
    if (storeys_[j].below >= 0) B(storeys_[j].below, j) = -1.0;
  }
  return mt.solve(B);
}

bool NewmarkStoreys::trial(const Eigen::VectorXd& u, const Eigen::VectorXd& u_end,
                           Eigen::VectorXd& guess) {
  bool converged = true;
  for (int i = 0, n = static_cast<int>(storeys_.size()); i < n; ++i) {
    const RowStorey& s = storeys_[i];
    const double d1 = drift(u_end, i);
    const double V = s.law->advance(s.p, committed_[i], drift(u, i), d1, trial_[i]);
    const double r = s.p.k0 * d1 - V;
    if (std::fabs(r - guess(i)) > 1e-12 * (std::fabs(V) + std::fabs(s.p.k0 * d1)))
      converged = false;
    guess(i) = r;
  }
  r_trial_ = guess;
  return converged;
}

void NewmarkStoreys::commit() {
  committed_.swap(trial_);
  trial_ = committed_;
  r_ = r_trial_;
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
  return storeys_[i].p.k0 * drift(u, i) - r_(i);
}

double NewmarkStoreys::dissipated(const Eigen::VectorXd& u, int i) const {
  const RowStorey& s = storeys_[i];
  return s.law->dissipated(s.p, committed_[i], drift(u, i), committed_[i].x);
}

double NewmarkStoreys::stored(const Eigen::VectorXd& u) const {
  double e = 0.0;
  for (std::size_t i = 0; i < storeys_.size(); ++i) {
    const RowStorey& s = storeys_[i];
    e += s.law->stored(s.p, committed_[i], drift(u, int(i)), committed_[i].x);
  }
  return e;
}

}  // namespace pound::sears

#include "solver/exact_steps.hpp"

#include <cmath>
#include <cstring>

namespace pound {

ExactSteps::ExactSteps(const ExactSteps& o)
    : enabled_(o.enabled_),
      h_(o.h_),
      point_(o.point_),
      declined_(o.declined_),
      own_cache_(o.own_cache_),
      cache_(o.cache_ == &o.own_cache_ ? &own_cache_ : o.cache_),
      config_(o.config_),
      offsets_ready_(o.offsets_ready_),
      offsets_response_(o.offsets_response_),
      k_scratch_(o.k_scratch_),
      c_scratch_(o.c_scratch_),
      visits_(o.visits_),
      declined_before_iteration_(o.declined_before_iteration_),
      visited_(o.visited_) {}

void ExactSteps::enable(const AssembledRow& row, double h_max, double rec_dt,
                        ExactStepCache* shared) {
  enabled_ = true;
  h_ = h_max;
  if (rec_dt > 0) h_ = rec_dt / std::ceil(rec_dt / h_max * (1 - 1e-12));
  point_ = 0;
  if (shared) cache_ = shared;
  if (cache_->row != &row || cache_->h != h_) {
    cache_->entries.clear();
    cache_->by_key.clear();
    cache_->row = &row;
    cache_->h = h_;
  }
  invalidate();
}

namespace {

// FNV-1a over the bits of the matrix' entries (-0 as +0: equal matrices hash alike).
std::uint64_t bits_hash(const Eigen::MatrixXd& k) {
  std::uint64_t h = 1469598103934665603ull;
  for (Eigen::Index i = 0; i < k.size(); ++i) {
    const double x = k.data()[i] + 0.0;
    std::uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    h = (h ^ b) * 1099511628211ull;
  }
  return h;
}

}  // namespace

// Massless base DOFs b (issue 29; RowDynamics::project): v_b = -S (K_b u + C_ba v_a + off_b),
// S = C_bb^-1, replaces their velocity entries in u' = v and in the damping of the others,
//   v_a' = -M_a^-1 [(K_a - C_ab S K_b) u + (C_aa - C_ab S C_ba) v_a + off_a - C_ab S off_b] - ag,
// and their velocity entries stay put (v_b' = 0; the caller projects them after the step).
void ExactSteps::eliminate_massless(const RowDynamics& dyn, const Eigen::MatrixXd& K,
                                    const Eigen::MatrixXd& C, Eigen::MatrixXd& A,
                                    Eigen::MatrixXd& B) {
  const int n = static_cast<int>(K.rows());
  const std::vector<int>& bs = dyn.massless();
  const int nb = static_cast<int>(bs.size());
  const Eigen::MatrixXd& S = dyn.massless_inverse();
  Eigen::MatrixXd Kb(nb, n), Cb(nb, n), Cxb(n, nb);
  std::vector<char> is_b(n, 0);
  for (int k = 0; k < nb; ++k) is_b[bs[k]] = 1;
  for (int k = 0; k < nb; ++k) {
    Kb.row(k) = K.row(bs[k]);
    Cb.row(k) = C.row(bs[k]);
    Cxb.col(k) = C.col(bs[k]);
  }
  for (int k = 0; k < nb; ++k) Cb(k, bs[k]) = 0.0;  // (their own velocities are not states)
  for (int k = 0; k < nb; ++k)
    for (int j = 0; j < nb; ++j) Cb(k, bs[j]) = 0.0;
  const Eigen::MatrixXd SK = S * Kb, SC = S * Cb;  // v_b = -SK u - SC v - S off_b
  const Eigen::VectorXd& im = dyn_inv_mass(dyn);
  for (int i = 0; i < n; ++i) {
    if (is_b[i]) continue;
    const Eigen::RowVectorXd cib = Cxb.row(i);
    A.block(n + i, 0, 1, n) = -im(i) * (K.row(i) - cib * SK);
    Eigen::RowVectorXd ci = C.row(i) - cib * SC;
    for (int j : bs) ci(j) = 0.0;
    A.block(n + i, n, 1, n) = -im(i) * ci;
    for (int k = 0; k < nb; ++k) B(n + i, bs[k]) += im(i) * (cib * S.col(k))(0);
  }
  for (int k = 0; k < nb; ++k) {
    const int b = bs[k];
    A.row(b).setZero();
    A.block(b, 0, 1, n) = -SK.row(k);
    A.block(b, n, 1, n) = -SC.row(k);
    A.row(n + b).setZero();
    B.row(n + b).setZero();
    for (int j = 0; j < nb; ++j) B(b, bs[j]) = -S(k, j);
  }
}

void ExactSteps::undo_iteration() {
  if (visited_ >= 0) --visits_[visited_];
  declined_ = declined_before_iteration_;
}

const LinearStep* ExactSteps::propagator(const RowDynamics& dyn, const AssembledRow& row) {
  auto& entries = cache_->entries;
  if (config_ < 0) {
    dyn.stiffness(k_scratch_);
    const std::uint64_t key = bits_hash(k_scratch_);
    const auto [first, last] = cache_->by_key.equal_range(key);
    for (auto it = first; it != last && config_ < 0; ++it)
      if (entries[it->second].K == k_scratch_) config_ = it->second;
    if (config_ < 0) {
      entries.push_back({k_scratch_, key, false, {}});
      config_ = static_cast<int>(entries.size()) - 1;
      cache_->by_key.emplace(key, config_);
    }
    if (visits_.size() < entries.size()) visits_.resize(entries.size(), 0);
  }
  if (visits_[config_] < ExactStepCache::kExactWarmup) {
    visited_ = config_;
    if (++visits_[config_] < ExactStepCache::kExactWarmup) return nullptr;
  }
  ExactStepCache::Entry& e = entries[config_];
  const int n = row.dofs();
  if (!e.ready) {
    // z = [u; v], z' = A z + B w, w = [off; ag_0 .. ag_m-1]: u' = v,
    // v' = -M^-1 (K u + C v + off) - ag (physics.md section 1, without contact forces;
    // docs/hysteresis.md for K_t and off), ag_c the acceleration of ground channel c under the
    // floors on it (one column for a row without ground, its floors on no channel).
    const Eigen::VectorXd& im = row.inv_mass;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = -(im.asDiagonal() * e.K);
    dyn.damping_matrix(c_scratch_);  // the tangent stiffness' damping, or the initial C
    A.bottomRightCorner(n, n) = -(im.asDiagonal() * c_scratch_);
    const int m = ground_inputs(dyn);
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(2 * n, n + m);
    B.block(n, 0, n, n) = -Eigen::MatrixXd(im.asDiagonal());
    for (int i = 0; i < n; ++i)
      if (dyn.channel(i) < m && im(i) != 0.0) B(n + i, n + dyn.channel(i)) = -1.0;
    if (!dyn.massless().empty()) eliminate_massless(dyn, e.K, c_scratch_, A, B);
    // Balance displacements against velocities by the row's largest frequency scale.
    const double w = std::sqrt(A.bottomLeftCorner(n, n).cwiseAbs().rowwise().sum().maxCoeff());
    Eigen::VectorXd scale = Eigen::VectorXd::Ones(2 * n);
    if (w > 0.0 && std::isfinite(w)) scale.head(n).setConstant(1.0 / w);
    e.step = linear_step(A, B, h_, scale);
    e.ready = true;
  }
  if (!offsets_ready_) {
    const std::vector<double>& off = dyn.offsets();
    offsets_response_.setZero(2 * n);
    if (dyn.affine())
      for (int j = 0; j < n; ++j)
        if (off[j] != 0.0) offsets_response_ += e.step.p1.col(j) * off[j];
    offsets_ready_ = true;
  }
  return &e.step;
}

}  // namespace pound

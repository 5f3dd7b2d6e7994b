#include "solver/exact_steps.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "solver/small_dense.hpp"

namespace pound {

ExactSteps::ExactSteps(const ExactSteps& o)
    : enabled_(o.enabled_),
      h_(o.h_),
      point_(o.point_),
      declined_(o.declined_),
      own_cache_(o.own_cache_),
      cache_(o.cache_ == &o.own_cache_ ? &own_cache_ : o.cache_),
      blocks_(o.blocks_),
      whole_(o.whole_),
      rates_(o.rates_),
      gate_(o.gate_),
      k_scratch_(o.k_scratch_),
      kb_scratch_(o.kb_scratch_),
      c_scratch_(o.c_scratch_),
      z1_(o.z1_),
      a1_(o.a1_),
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
  // The blocks: the whole row, or each building with its base on a row with a flexible
  // foundation.
  const int n = row.dofs(), nb = static_cast<int>(row.offset.size());
  whole_ = std::none_of(row.rot.begin(), row.rot.end(), [](int r) { return r >= 0; });
  blocks_.assign(whole_ ? 1 : nb, Block{});
  int largest = 0;
  rates_ = !whole_ && (row.inv_mass.array() != 0.0).all();
  for (int b = 0; b < static_cast<int>(blocks_.size()); ++b) {
    std::vector<int> dofs;
    if (whole_) {
      for (int i = 0; i < n; ++i) dofs.push_back(i);
    } else {
      const int end = b + 1 < nb ? row.offset[b + 1] : row.floors;
      for (int i = row.offset[b]; i < end; ++i) dofs.push_back(i);
      if (row.sway[b] >= 0) dofs.push_back(row.sway[b]);
      if (row.rot[b] >= 0) dofs.push_back(row.rot[b]);
    }
    std::vector<int>& st = blocks_[b].state;
    for (int i : dofs) st.push_back(i);
    for (int i : dofs) st.push_back(n + i);
    largest = std::max(largest, static_cast<int>(st.size()));
  }
  z1_.setZero(largest + 4);  // (padded rows)
  a1_.setZero(largest + 4);
  invalidate();
}

namespace {

// A block's step in place (ExactSteps::step on flexible foundations): z1 = Phi z0 + c + P1 a0 +
// P2 (a1 - a0) as linear_step_apply's kernels, the same operations in the same order (the same
// bits: element by element, no fused multiply-add), with z0 read from the row's state y0 at the
// block's entries idx and the rows padded to ld, a multiple of 4 (zero rows), so that the
// columns go by whole vectors of four (GCC's vector extension: AVX2 or two SSE2 halves).
using dense::add_columns_any;
using dense::V4;

__attribute__((target_clones("avx2", "default"))) void block_apply_kernel(
    int ns, int ld, const double* __restrict phi, const double* __restrict c,
    const double* __restrict q1, const double* __restrict q2, double a0, double da,
    const double* __restrict y0, const int* __restrict idx, double* __restrict z1) {
  const int nv = ld / 4;
  V4* z = reinterpret_cast<V4*>(z1);
  const V4 *cv = reinterpret_cast<const V4*>(c), *p1 = reinterpret_cast<const V4*>(q1),
           *p2 = reinterpret_cast<const V4*>(q2);
  for (int i = 0; i < nv; ++i) z[i] = cv[i] + p1[i] * a0 + p2[i] * da;
  add_columns_any(ns, ld, phi, y0, idx, z);  // Phi is column-major: add its columns
}

// A further ramped input (linear_step_apply's add_input) on ld rows.
__attribute__((target_clones("avx2", "default"))) void block_add_input(int ld,
                                                                       const double* __restrict q1,
                                                                       const double* __restrict q2,
                                                                       double a0, double da,
                                                                       double* __restrict z1) {
  V4* z = reinterpret_cast<V4*>(z1);
  const V4 *p1 = reinterpret_cast<const V4*>(q1), *p2 = reinterpret_cast<const V4*>(q2);
  for (int i = 0; i < ld / 4; ++i) z[i] += p1[i] * a0 + p2[i] * da;
}

// out = A_v z on lda rows (a multiple of 4), z read from y at idx (ExactSteps::rates).
__attribute__((target_clones("avx2", "default"))) void block_rates_kernel(
    int ns, int lda, const double* __restrict acc, const double* __restrict y,
    const int* __restrict idx, double* __restrict out) {
  V4* o = reinterpret_cast<V4*>(out);
  for (int i = 0; i < lda / 4; ++i) o[i] = V4{0.0, 0.0, 0.0, 0.0};
  add_columns_any(ns, lda, acc, y, idx, o);
}

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
  for (int e : visited_) --visits_[e];
  visited_.clear();
  declined_ = declined_before_iteration_;
}

// The entry of block `block` at stiffness K, added when new.
int ExactSteps::find_entry(int block, const Eigen::MatrixXd& K) {
  auto& entries = cache_->entries;
  const std::uint64_t key = bits_hash(K) + static_cast<std::uint64_t>(block);
  const auto [first, last] = cache_->by_key.equal_range(key);
  for (auto it = first; it != last; ++it)
    if (entries[it->second].block == block && entries[it->second].K == K) return it->second;
  entries.push_back(ExactStepCache::Entry{});
  entries.back().block = block;
  entries.back().K = K;
  entries.back().key = key;
  const int e = static_cast<int>(entries.size()) - 1;
  cache_->by_key.emplace(key, e);
  return e;
}

void ExactSteps::row_system(const RowDynamics& dyn, const AssembledRow& row,
                            const Eigen::MatrixXd& K, Eigen::MatrixXd& A, Eigen::MatrixXd& B) {
  // z = [u; v], z' = A z + B w, w = [off; ag_0 .. ag_m-1]: u' = v,
  // v' = -M^-1 (K u + C v + off) - ag (physics.md section 1, without contact forces;
  // docs/hysteresis.md for K_t and off), ag_c the acceleration of ground channel c under the
  // floors on it (one column for a row without ground, its floors on no channel).
  const int n = row.dofs();
  const Eigen::VectorXd& im = row.inv_mass;
  A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  A.topRightCorner(n, n).setIdentity();
  A.bottomLeftCorner(n, n) = -(im.asDiagonal() * K);
  dyn.damping_matrix(c_scratch_);  // the tangent stiffness' damping, or the initial C
  A.bottomRightCorner(n, n) = -(im.asDiagonal() * c_scratch_);
  const int m = ground_inputs(dyn);
  B = Eigen::MatrixXd::Zero(2 * n, n + m);
  B.block(n, 0, n, n) = -Eigen::MatrixXd(im.asDiagonal());
  for (int i = 0; i < n; ++i)
    if (dyn.channel(i) < m && im(i) != 0.0) B(n + i, n + dyn.channel(i)) = -1.0;
  if (!dyn.massless().empty()) eliminate_massless(dyn, K, c_scratch_, A, B);
}

LinearStep ExactSteps::block_step(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double h) {
  // Balance displacements against velocities by the block's largest frequency scale.
  const Eigen::Index n = A.rows() / 2;
  const double w = std::sqrt(A.bottomLeftCorner(n, n).cwiseAbs().rowwise().sum().maxCoeff());
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(2 * n);
  if (w > 0.0 && std::isfinite(w)) scale.head(n).setConstant(1.0 / w);
  return linear_step(A, B, h, scale);
}

bool ExactSteps::ready(const RowDynamics& dyn, const AssembledRow& row) {
  auto& entries = cache_->entries;
  const int nblocks = static_cast<int>(blocks_.size());
  if (gate_ < 0) {
    // The row's stiffness (its entry counts the warm-up), and each block's part of it.
    dyn.stiffness(k_scratch_);
    gate_ = find_entry(whole_ ? 0 : nblocks, k_scratch_);
    for (int bi = 0; bi < nblocks && !whole_; ++bi) {
      Block& b = blocks_[bi];
      const int nd = static_cast<int>(b.state.size()) / 2;
      kb_scratch_.resize(nd, nd);
      for (int i = 0; i < nd; ++i)
        for (int j = 0; j < nd; ++j) kb_scratch_(i, j) = k_scratch_(b.state[i], b.state[j]);
      b.config = find_entry(bi, kb_scratch_);
    }
    if (whole_) blocks_[0].config = gate_;
    if (visits_.size() < entries.size()) visits_.resize(entries.size(), 0);
  }
  // The warm-up counts the grid points met with the row's stiffness, whether its blocks'
  // propagators are at hand or not: the same steps as one propagator for the row.
  bool ready = true;
  if (visits_[gate_] < ExactStepCache::kExactWarmup) {
    visited_.push_back(gate_);
    if (++visits_[gate_] < ExactStepCache::kExactWarmup) ready = false;
  }
  if (!ready) return false;
  const int n = row.dofs(), m = ground_inputs(dyn);
  Eigen::MatrixXd A, B;  // the row's system, formed once when a block needs it
  for (Block& b : blocks_) {
    ExactStepCache::Entry& e = entries[b.config];
    if (!e.ready) {
      if (whole_) {
        row_system(dyn, row, e.K, A, B);
      } else if (A.size() == 0) {
        dyn.stiffness(k_scratch_);
        row_system(dyn, row, k_scratch_, A, B);
      }
      if (whole_) {
        e.step = block_step(A, B, h_);
      } else {
        // The block's rows and columns (A is block diagonal over the buildings), and of B its
        // offsets' columns and the ground channels'.
        const int ns = static_cast<int>(b.state.size()), nd = ns / 2;
        Eigen::MatrixXd Ab(ns, ns), Bb(ns, nd + m);
        for (int i = 0; i < ns; ++i) {
          for (int j = 0; j < ns; ++j) Ab(i, j) = A(b.state[i], b.state[j]);
          for (int j = 0; j < nd; ++j) Bb(i, j) = B(b.state[i], b.state[j]);
          for (int c = 0; c < m; ++c) Bb(i, nd + c) = B(b.state[i], n + c);
        }
        e.step = block_step(Ab, Bb, h_);
        pad_block(Ab, m, e);
      }
      e.ready = true;
    }
    if (!b.offsets_ready) {
      const std::vector<double>& off = dyn.offsets();
      const int nd = static_cast<int>(b.state.size()) / 2;
      b.offsets_response.setZero(whole_ ? 2 * nd : e.ld);
      b.offsets_acc.setZero(nd);
      if (dyn.affine())
        for (int j = 0; j < nd; ++j)
          if (off[b.state[j]] != 0.0) {
            b.offsets_response.head(2 * nd) += e.step.p1.col(j) * off[b.state[j]];
            b.offsets_acc(j) = -row.inv_mass(b.state[j]) * off[b.state[j]];
          }
      b.offsets_ready = true;
    }
  }
  return true;
}

// The padded copies of a block's step (its ground inputs: the last m columns of P1 and P2)
// and the accelerations' rows of its A (Entry).
void ExactSteps::pad_block(const Eigen::MatrixXd& Ab, int m, ExactStepCache::Entry& e) {
  const int ns = static_cast<int>(Ab.rows()), nd = ns / 2;
  const int ld = (ns + 3) / 4 * 4, lda = (nd + 3) / 4 * 4;
  const LinearStep& L = e.step;
  const int first = static_cast<int>(L.p1.cols()) - m;
  e.ld = ld;
  e.lda = lda;
  e.phi.assign(static_cast<std::size_t>(ld) * ns, 0.0);
  e.p1.assign(static_cast<std::size_t>(ld) * m, 0.0);
  e.p2.assign(static_cast<std::size_t>(ld) * m, 0.0);
  e.acc.assign(static_cast<std::size_t>(lda) * ns, 0.0);
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < ns; ++i) e.phi[j * ld + i] = L.phi(i, j);
  for (int c = 0; c < m; ++c)
    for (int i = 0; i < ns; ++i) {
      e.p1[c * ld + i] = L.p1(i, first + c);
      e.p2[c * ld + i] = L.p2(i, first + c);
    }
  for (int j = 0; j < ns; ++j)
    for (int i = 0; i < nd; ++i) e.acc[j * lda + i] = Ab(nd + i, j);
}

void ExactSteps::step(int r, const double* a0, const double* a1, const Eigen::VectorXd& y0,
                      Eigen::VectorXd& y1) {
  const auto& entries = cache_->entries;
  if (whole_) {
    const Block& b = blocks_[0];
    linear_step_apply(entries[b.config].step, r, a0, a1, b.offsets_response.data(), y0.data(),
                      y1.data());
    return;
  }
  // Each building's block in place: its entries of y0 read where they are, its rows written
  // back into y1 (the bits of linear_step_apply on the gathered block).
  double* z1 = z1_.data();
  for (const Block& b : blocks_) {
    const ExactStepCache::Entry& e = entries[b.config];
    const int ns = static_cast<int>(b.state.size()), ld = e.ld;
    const int m = static_cast<int>(e.p1.size()) / ld, first = m - r;
    block_apply_kernel(ns, ld, e.phi.data(), b.offsets_response.data(), e.p1.data() + first * ld,
                       e.p2.data() + first * ld, a0[0], a1[0] - a0[0], y0.data(), b.state.data(),
                       z1);
    for (int k = 1; k < r; ++k)
      block_add_input(ld, e.p1.data() + (first + k) * ld, e.p2.data() + (first + k) * ld, a0[k],
                      a1[k] - a0[k], z1);
    for (int k = 0; k < ns; ++k) y1(b.state[k]) = z1[k];
  }
}

void ExactSteps::rates(const RowDynamics& dyn, const double* agc, const Eigen::VectorXd& y,
                       Eigen::VectorXd& dy) {
  const auto& entries = cache_->entries;
  const int n = dyn.layout().dofs;
  double* a = a1_.data();
  for (const Block& b : blocks_) {
    const ExactStepCache::Entry& e = entries[b.config];
    const int ns = static_cast<int>(b.state.size()), nd = ns / 2;
    block_rates_kernel(ns, e.lda, e.acc.data(), y.data(), b.state.data(), a);
    for (int k = 0; k < nd; ++k) {
      const int i = b.state[k];
      dy(i) = y(n + i);  // u' = v
      dy(n + i) = a[k] + b.offsets_acc(k) - agc[dyn.channel(i)];
    }
  }
}

}  // namespace pound

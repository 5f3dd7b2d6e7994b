#include "solver/row_forces.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "solver/small_dense.hpp"

namespace pound {

// Storage of K and C. A shear building's K is tridiagonal (Th. 3.6) and so is its Rayleigh
// damping C = a0 M + a1 K (Chopra 11.4.1); buildings do not couple (block diagonal: the entries
// between one building's top floor and the next one's first floor are zero). Then the three
// bands are kept (kl_(i) = K(i, i-1), kd_(i) = K(i, i), ku_(i) = K(i, i+1), the same for C;
// zero outside the matrix). Otherwise (modal damping gives a full C per building) compressed
// rows over the union of the nonzero patterns. Either costs O(nonzeros) instead of O(n^2) and
// gives the dense products up to round-off.
RowForces::RowForces(const AssembledRow& row, const std::vector<RowStorey>& storeys)
    : row_(row), storeys_(storeys), n_(row.dofs()), cv_(Eigen::VectorXd::Zero(row.dofs())) {
  tridiagonal_ = true;
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j)
      if (std::abs(i - j) > 1 && (row_.K(i, j) != 0.0 || row_.C(i, j) != 0.0)) tridiagonal_ = false;
  auto band = [&](const Eigen::MatrixXd& A, int offset) {
    std::vector<double> b(n_, 0.0);
    for (int i = 0; i < n_; ++i)
      if (i + offset >= 0 && i + offset < n_) b[i] = A(i, i + offset);
    return b;
  };
  kl_ = band(row_.K, -1), kd_ = band(row_.K, 0), ku_ = band(row_.K, 1);
  cl_ = band(row_.C, -1), cd_ = band(row_.C, 0), cu_ = band(row_.C, 1);
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    topology_ = topology_ || st.rot >= 0 || (st.below >= 0 && st.below != i - 1);
  }
  // The compressed rows: the nonzeros of K and C, and with a flexible foundation every pair of
  // a storey's DOFs (its line and tangent damper change there).
  std::vector<std::vector<char>> used(n_, std::vector<char>(n_, 0));
  for (int i = 0; i < n_; ++i)
    for (int j = 0; j < n_; ++j) used[i][j] = row_.K(i, j) != 0.0 || row_.C(i, j) != 0.0;
  for (int i = 0; i < n_ && topology_; ++i) {
    const RowStorey& st = storeys_[i];
    for (int a : {i, st.below, st.rot})
      for (int b : {i, st.below, st.rot})
        if (a >= 0 && b >= 0) used[a][b] = 1;
  }
  row_start_.assign(1, 0);
  for (int i = 0; i < n_; ++i) {
    for (int j = 0; j < n_; ++j) {
      if (!used[i][j]) continue;
      col_.push_back(j);
      k_val_.push_back(row_.K(i, j));
      c_val_.push_back(row_.C(i, j));
    }
    row_start_.push_back(static_cast<int>(col_.size()));
  }
  tl_.assign(n_, 0.0), td_.assign(n_, 0.0), tu_.assign(n_, 0.0), off_.assign(n_, 0.0);
  if (topology_) set_topology();
  // Tangent-stiffness damping: the initial damping and, per such storey, where its entries
  // (i, i), (b, b), (i, b), (b, i) stand in the compressed rows (b the floor below, -1: none).
  for (int i = 0; i < n_; ++i) tangent_damping_ = tangent_damping_ || storeys_[i].damping_a1 > 0.0;
  if (tangent_damping_) {
    cl0_ = cl_, cd0_ = cd_, cu0_ = cu_, c_val0_ = c_val_;
    auto at = [&](int i, int j) {
      for (int e = row_start_[i]; e < row_start_[i + 1]; ++e)
        if (col_[e] == j) return e;
      return -1;
    };
    damping_entry_.assign(n_, {-1, -1, -1, -1});
    for (int i = 0; i < n_; ++i) {
      const int b = storeys_[i].below;
      damping_entry_[i] = {at(i, i), b >= 0 ? at(b, b) : -1, b >= 0 ? at(i, b) : -1,
                           b >= 0 ? at(b, i) : -1};
    }
  }
  if (topology_) set_base_path();
}

// The O(n) path of a row with flexible foundations (issue 29; row_forces.hpp). With the
// floors' displacements relative to the base x_j = U_j - u0 - H_j theta (x = T U,
// structure/building_on_base.hpp), storey j's deformation is x_j - x_j-1 (x_0 = 0), so the
// fixed-base damping C_fixed acts on x' as on a fixed base: tridiagonal for Rayleigh damping
// of a shear building (Chopra 11.4.1), its tangent-stiffness part per storey along x_j - x_j-1;
// T^T returns its forces f_x: f_x on the floors, -sum f_x on the sway, -sum H_j f_x on the
// rotation. Taken when every floor's storey stands on the floor below in its building or on its
// base's sway (with its base's rotation), every base DOF holds only its foundation spring, and
// the row knows its dashpots (AssembledRow::base_damping); otherwise the compressed rows serve.
void RowForces::set_base_path() {
  const int nf = row_.floors;
  if (static_cast<int>(row_.base_damping.size()) != n_ || nf <= 0 || nf > n_) return;
  f_height_.assign(nf, 0.0);
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    if (i >= nf) {  // a base DOF: its foundation spring
      if (!st.foundation || st.below >= 0 || st.rot >= 0) return;
      continue;
    }
    const int b = st.building, sway = row_.sway[b];
    const bool first = i == row_.offset[b];
    if (st.foundation || st.rot != row_.rot[b] || st.below != (first ? sway : i - 1)) return;
    f_height_[i] = (first ? 0.0 : f_height_[i - 1]) + st.p.h;  // H_j, as assemble_on_base
  }
  x_tridiagonal_ = true;
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < nf; ++j)
      if (std::abs(i - j) > 1 && row_.C(i, j) != 0.0) x_tridiagonal_ = false;
  if (!x_tridiagonal_ && tangent_damping_) return;  // (tangent damping needs Rayleigh's bands)
  // The floors' block of C is C_fixed (T's floor columns are the identity).
  if (x_tridiagonal_) {
    xl_.assign(nf, 0.0), xd_.assign(nf, 0.0), xu_.assign(nf, 0.0);
    for (int i = 0; i < nf; ++i) {
      xd_[i] = row_.C(i, i);
      if (i > 0) xl_[i] = row_.C(i, i - 1);
      if (i + 1 < nf) xu_[i] = row_.C(i, i + 1);
    }
    xl0_ = xl_, xd0_ = xd_, xu0_ = xu_;
  } else {
    xrow_.assign(1, 0);
    for (int i = 0; i < nf; ++i) {
      for (int j = 0; j < nf; ++j)
        if (row_.C(i, j) != 0.0) xcol_.push_back(j), xval_.push_back(row_.C(i, j));
      xrow_.push_back(static_cast<int>(xcol_.size()));
    }
  }
  s_h_.resize(n_), s_kg_.resize(n_), s_slope_.resize(n_), s_off_.assign(n_, 0.0);
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    s_h_[i] = st.p.h, s_kg_[i] = st.kg;
    s_slope_[i] = st.p.k0;  // linear storeys (K u); set_lines() replaces it by the branch's
  }
  segments_.clear();
  for (std::size_t b = 0; b < row_.offset.size(); ++b) {
    const int first = row_.offset[b];
    const int last = b + 1 < row_.offset.size() ? row_.offset[b + 1] : nf;
    segments_.push_back({first, last - first, row_.sway[b], row_.rot[b]});
  }
  dashpot_ = row_.base_damping;
  xv_.assign(nf, 0.0);
  floors_ = nf;
  base_path_ = true;
  set_dense();
}

namespace {
// out = A_v [u; v] of one building (RowForces::DenseBlock), its entries of u and v at idx.
__attribute__((target_clones("avx2", "default"))) void dense_block_kernel(
    int nd, int lda, const double* __restrict a, const double* __restrict u,
    const double* __restrict v, const int* __restrict idx, double* __restrict out) {
  dense::V4* o = reinterpret_cast<dense::V4*>(out);
  for (int i = 0; i < lda / 4; ++i) o[i] = dense::V4{0.0, 0.0, 0.0, 0.0};
  dense::add_columns_any(nd, lda, a, u, idx, o);
  dense::add_columns_any(nd, lda, a + static_cast<std::ptrdiff_t>(nd) * lda, v, idx, o);
}
}  // namespace

// The dense blocks of linear(): each building's DOFs with mass, K and C block diagonal over
// them, none more than kDenseDofs (otherwise base_forces serves).
void RowForces::set_dense() {
  dense_.clear();
  const int nf = row_.floors, nb = static_cast<int>(row_.offset.size());
  std::vector<int> block(n_, -1);
  std::vector<DenseBlock> blocks(nb);
  for (int b = 0; b < nb; ++b) {
    const int end = b + 1 < nb ? row_.offset[b + 1] : nf;
    for (int i = row_.offset[b]; i < end; ++i) blocks[b].dofs.push_back(i);
    if (row_.sway[b] >= 0) blocks[b].dofs.push_back(row_.sway[b]);
    if (row_.rot[b] >= 0) blocks[b].dofs.push_back(row_.rot[b]);
    for (int i : blocks[b].dofs) block[i] = b;
    if (static_cast<int>(blocks[b].dofs.size()) > kDenseDofs) return;
  }
  for (int i = 0; i < n_; ++i) {
    if (block[i] < 0 || !(row_.inv_mass(i) != 0.0)) return;
    for (int j = 0; j < n_; ++j)
      if (block[j] != block[i] && (row_.K(i, j) != 0.0 || row_.C(i, j) != 0.0)) return;
  }
  std::size_t largest = 0;
  for (DenseBlock& g : blocks) {
    const int nd = static_cast<int>(g.dofs.size());
    g.lda = (nd + 3) / 4 * 4;
    g.a.assign(static_cast<std::size_t>(g.lda) * 2 * nd, 0.0);
    for (int j = 0; j < nd; ++j)
      for (int i = 0; i < nd; ++i) {
        const double im = row_.inv_mass(g.dofs[i]);
        g.a[j * g.lda + i] = -im * row_.K(g.dofs[i], g.dofs[j]);
        g.a[(nd + j) * g.lda + i] = -im * row_.C(g.dofs[i], g.dofs[j]);
      }
    largest = std::max(largest, static_cast<std::size_t>(g.lda));
  }
  dense_ = std::move(blocks);
  dense_out_.assign(largest, 0.0);
}

void RowForces::dense_accelerations(const double* __restrict u, const double* __restrict v,
                                    const double* __restrict ag, double* __restrict dv) const {
  double* out = dense_out_.data();
  for (const DenseBlock& g : dense_) {
    const int nd = static_cast<int>(g.dofs.size());
    dense_block_kernel(nd, g.lda, g.a.data(), u, v, g.dofs.data(), out);
    for (int k = 0; k < nd; ++k) dv[g.dofs[k]] = out[k] - ag[g.dofs[k]];
  }
}

void RowForces::set_base_tangent_damping(int i, double dc) {
  // Between x_i and the floor below's x (none on the base: x_0 = 0).
  const int b = storeys_[i].below;
  xd_[i] += dc;
  if (b < 0 || b >= floors_) return;
  xd_[b] += dc;
  xu_[b] -= dc;
  xl_[i] -= dc;
}

// Building g's part of C v: C_fixed x' on its floors into f (x'_j = v_j - v0 - H_j w), and
// returns sum_j (C_fixed x')_j and sum_j H_j (C_fixed x')_j for its base.
void RowForces::segment_damping(const BaseSegment& g, const double* __restrict v,
                                double* __restrict f, double& sum, double& moment) const {
  const int o = g.first, m = g.floors;
  const double v0 = g.sway >= 0 ? v[g.sway] : 0.0, w = g.sway >= 0 ? v[g.rot] : 0.0;
  const double* __restrict H = f_height_.data() + o;
  double* __restrict xv = xv_.data();
  for (int j = 0; j < m; ++j) xv[o + j] = v[o + j] - v0 - H[j] * w;
  double cs = 0.0, chs = 0.0;
  if (x_tridiagonal_) {
    const double *l = xl_.data() + o, *d = xd_.data() + o, *up = xu_.data() + o;
    const double* x = xv + o;
    for (int j = 0; j < m; ++j) {
      double cx = d[j] * x[j];
      if (j > 0) cx += l[j] * x[j - 1];
      if (j + 1 < m) cx += up[j] * x[j + 1];
      f[o + j] = cx;
      cs += cx;
      chs += H[j] * cx;
    }
  } else {
    for (int j = 0; j < m; ++j) {
      double cx = 0.0;
      for (int e = xrow_[o + j]; e < xrow_[o + j + 1]; ++e) cx += xval_[e] * xv[xcol_[e]];
      f[o + j] = cx;
      cs += cx;
      chs += H[j] * cx;
    }
  }
  sum = cs;
  moment = chs;
}

void RowForces::base_damping(const double* __restrict v, double* __restrict cv) const {
  for (const BaseSegment& g : segments_) {
    double cs, chs;
    segment_damping(g, v, cv, cs, chs);
    if (g.sway < 0) continue;
    cv[g.sway] = dashpot_[g.sway] * v[g.sway] - cs;
    cv[g.rot] = dashpot_[g.rot] * v[g.rot] - chs;
  }
}

void RowForces::base_forces(const double* __restrict u, const double* __restrict v,
                            double* __restrict f) const {
  for (const BaseSegment& g : segments_) {
    // Storey j: V = slope d + offset on its deformation d = c - h theta, c = U_j - U_j-1 its
    // chord (U_0 = u0), P-Delta -kg c (physics.md section 5a): F = V - kg c on floor j, -F on
    // the floor below (on the sway for the first storey), -h V on the rotation. With Rayleigh
    // damping in one pass with the bands of C_fixed on x' (segment_damping otherwise).
    const int o = g.first, m = g.floors;
    const bool flexible = g.sway >= 0;
    const double u0 = flexible ? u[g.sway] : 0.0, th = flexible ? u[g.rot] : 0.0;
    const double v0 = flexible ? v[g.sway] : 0.0, w = flexible ? v[g.rot] : 0.0;
    const double *h = s_h_.data() + o, *kg = s_kg_.data() + o;
    const double *k = s_slope_.data() + o, *off = s_off_.data() + o;
    const double *uo = u + o, *vo = v + o, *H = f_height_.data() + o;
    double* fo = f + o;
    double cs = 0.0, chs = 0.0, below = u0, first = 0.0, moment = 0.0;
    if (x_tridiagonal_) {
      const double *l = xl_.data() + o, *dg = xd_.data() + o, *up = xu_.data() + o;
      double x_prev = 0.0, x = vo[0] - v0 - H[0] * w;
      for (int j = 0; j < m; ++j) {
        const double x_next = j + 1 < m ? vo[j + 1] - v0 - H[j + 1] * w : 0.0;
        const double cx = l[j] * x_prev + dg[j] * x + up[j] * x_next;  // (C_fixed x')_j
        cs += cx;
        chs += H[j] * cx;
        const double c = uo[j] - below, d = c - h[j] * th;
        const double V = k[j] * d + off[j], F = V - kg[j] * c;
        fo[j] = cx + F;
        if (j > 0)
          fo[j - 1] -= F;
        else
          first = F;
        moment += h[j] * V;
        below = uo[j];
        x_prev = x;
        x = x_next;
      }
    } else {
      segment_damping(g, v, f, cs, chs);
      for (int j = 0; j < m; ++j) {
        const double c = uo[j] - below, d = c - h[j] * th;
        const double V = k[j] * d + off[j], F = V - kg[j] * c;
        fo[j] += F;
        if (j > 0)
          fo[j - 1] -= F;
        else
          first = F;
        moment += h[j] * V;
        below = uo[j];
      }
    }
    if (!flexible) continue;
    // The base: its dashpots, springs (K u + offset: the foundation "storeys"), and the
    // floors' damping forces and storeys' reactions through T^T.
    const int s = g.sway, r = g.rot;
    f[s] = dashpot_[s] * v[s] - cs + (s_slope_[s] * u0 + s_off_[s]) - first;
    f[r] = dashpot_[r] * v[r] - chs + (s_slope_[r] * th + s_off_[r]) - moment;
  }
}

void RowForces::base_accelerations(const double* __restrict u, const double* __restrict v,
                                   const double* __restrict ag, double* __restrict dv) const {
  double* f = cv_.data();
  base_forces(u, v, f);
  const double* im = row_.inv_mass.data();
  for (int i = 0; i < n_; ++i) dv[i] = -im[i] * f[i] - ag[i];
}

void RowForces::set_topology() {
  auto at = [&](int i, int j) {
    for (int e = row_start_[i]; e < row_start_[i + 1]; ++e)
      if (col_[e] == j) return e;
    return -1;
  };
  entries_.assign(n_, {});
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    const int dof[3] = {i, st.below, st.rot};
    const double g[3] = {1.0, -1.0, -st.p.h}, c[3] = {1.0, -1.0, 0.0};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (dof[a] >= 0 && dof[b] >= 0)
          entries_[i].push_back({at(dof[a], dof[b]), g[a] * g[b], c[a] * c[b]});
  }
  kt_val_.assign(col_.size(), 0.0);
  touching_.assign(n_, {});
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    touching_[i].push_back({i, 1.0, 1.0});
    if (st.below >= 0) touching_[st.below].push_back({i, -1.0, -1.0});
    if (st.rot >= 0) touching_[st.rot].push_back({i, -st.p.h, 0.0});
  }
}

double RowForces::raw_force(int i, const double* u, const double* v, int kind,
                            const std::vector<StoreyState>& states, const double* y,
                            const std::vector<int>& xoff) const {
  double f = 0.0;
  for (int e = row_start_[i]; e < row_start_[i + 1]; ++e) {
    f += c_val_[e] * v[col_[e]];
    if (kind == 0) f += k_val_[e] * u[col_[e]];
    if (kind == 1) f += kt_val_[e] * u[col_[e]];
  }
  if (kind == 1) f += off_[i];
  if (kind != 2) return f;
  for (const Touch& t : touching_[i]) {
    const RowStorey& st = storeys_[t.storey];
    const double* x = xoff[t.storey] >= 0 ? y + xoff[t.storey] : nullptr;
    const double V = st.law->shear(st.p, states[t.storey], storey_drift(st, t.storey, u), x);
    f += t.g * V - t.c * st.kg * storey_chord(st, t.storey, u);
  }
  return f;
}

// The storeys' lines along their deformations and P-Delta along their chords (row_forces.hpp).
void RowForces::set_lines_general(const std::vector<StoreyState>& states) {
  std::fill(kt_val_.begin(), kt_val_.end(), 0.0);
  std::fill(off_.begin(), off_.end(), 0.0);
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    double slope = 0.0, offset = 0.0;
    st.law->branch_line(st.p, states[i], slope, offset);
    for (const StoreyEntry& e : entries_[i]) kt_val_[e.entry] += slope * e.g - st.kg * e.c;
    if (base_path_) s_slope_[i] = slope, s_off_[i] = offset;
    off_[i] += offset;
    if (st.below >= 0) off_[st.below] -= offset;
    if (st.rot >= 0) off_[st.rot] -= st.p.h * offset;
  }
}

void RowForces::set_lines(const std::vector<StoreyState>& states) {
  if (topology_) {
    set_lines_general(states);
    return;
  }
  std::fill(tl_.begin(), tl_.end(), 0.0);
  std::fill(td_.begin(), td_.end(), 0.0);
  std::fill(tu_.begin(), tu_.end(), 0.0);
  std::fill(off_.begin(), off_.end(), 0.0);
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    double slope = 0.0, offset = 0.0;
    st.law->branch_line(st.p, states[i], slope, offset);
    // P-Delta: the storey's shear gains -kg d (row_forces.hpp).
    slope -= st.kg;
    // V = slope (u_i - u_b) + offset acts as +V on floor i and -V on the floor below b.
    td_[i] += slope;
    off_[i] += offset;
    if (st.below >= 0) {
      td_[st.below] += slope;
      tu_[st.below] -= slope;
      tl_[i] -= slope;
      off_[st.below] -= offset;
    }
  }
}

void RowForces::set_tangent_damping(const std::vector<StoreyState>& states) {
  cl_ = cl0_, cd_ = cd0_, cu_ = cu0_, c_val_ = c_val0_;
  if (base_path_) xl_ = xl0_, xd_ = xd0_, xu_ = xu0_;
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    if (!(st.damping_a1 > 0.0)) continue;
    double slope = 0.0, offset = 0.0;
    st.law->branch_line(st.p, states[i], slope, offset);
    // a1 (max(k_t, 0) - k0) between floor i and the floor below (Charney 2008): a damper of
    // that coefficient in parallel with the initial stiffness' one.
    const double dc = st.damping_a1 * (std::max(slope, 0.0) - st.p.k0);
    if (topology_) {  // along the storey's deformation
      for (const StoreyEntry& e : entries_[i]) c_val_[e.entry] += dc * e.g;
      if (base_path_) set_base_tangent_damping(i, dc);
      continue;
    }
    const int b = st.below;
    const auto& e = damping_entry_[i];
    auto add = [&](int entry, double x) {
      if (entry >= 0) c_val_[entry] += x;
    };
    cd_[i] += dc;
    add(e[0], dc);
    if (b < 0) continue;
    cd_[b] += dc;
    cu_[b] -= dc;
    cl_[i] -= dc;
    add(e[1], dc);
    add(e[2], -dc);
    add(e[3], -dc);
  }
}

void RowForces::damping_matrix(Eigen::MatrixXd& C) const {
  C.setZero(n_, n_);
  for (int i = 0; i < n_; ++i)
    for (int e = row_start_[i]; e < row_start_[i + 1]; ++e) C(i, col_[e]) = c_val_[e];
}

void RowForces::stiffness(bool affine, Eigen::MatrixXd& K) const {
  if (!affine) {
    K = row_.K;
    return;
  }
  K.setZero(n_, n_);  // allocates only the first time
  if (topology_) {
    for (int i = 0; i < n_; ++i)
      for (int e = row_start_[i]; e < row_start_[i + 1]; ++e) K(i, col_[e]) = kt_val_[e];
    return;
  }
  for (int i = 0; i < n_; ++i) {
    K(i, i) = td_[i];
    if (i > 0) K(i, i - 1) = tl_[i];
    if (i + 1 < n_) K(i, i + 1) = tu_[i];
  }
}

void RowForces::general(const Eigen::VectorXd& y, const std::vector<StoreyState>& states,
                        const std::vector<int>& xoff, const double* ag, double* dy,
                        const double* vel) const {
  const double* u = y.data();
  const double* v = vel ? vel : u + n_;
  double* dv = dy + n_;
  damping(v, dv);
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    const double* x = xoff[i] >= 0 ? u + xoff[i] : nullptr;
    if (st.rot >= 0) {  // on a flexible foundation: the law along d, P-Delta along the chord
      const double d = storey_drift(st, i, u), c = storey_chord(st, i, u);
      const double V = st.law->shear(st.p, states[i], d, x), P = -st.kg * c;
      dv[i] += V + P;
      if (st.below >= 0) dv[st.below] -= V + P;
      dv[st.rot] -= st.p.h * V;
      if (x) st.law->rates(st.p, states[i], d, storey_drift(st, i, v), x, dy + xoff[i]);
      continue;
    }
    const double d = u[i] - (st.below >= 0 ? u[st.below] : 0.0);
    double V = st.law->shear(st.p, states[i], d, x);
    if (st.kg != 0.0) V -= st.kg * d;  // P-Delta
    dv[i] += V;
    if (st.below >= 0) dv[st.below] -= V;
    if (x) {
      const double dd = v[i] - (st.below >= 0 ? v[st.below] : 0.0);
      st.law->rates(st.p, states[i], d, dd, x, dy + xoff[i]);
    }
  }
  const double* im = row_.inv_mass.data();
  for (int i = 0; i < n_; ++i) dv[i] = -im[i] * dv[i] - ag[i];
}

void RowForces::damping(const double* v, double* cv) const {
  if (base_path_) {
    base_damping(v, cv);
    return;
  }
  if (tridiagonal_ && n_ > 1) {
    for (int i = 0; i < n_; ++i)
      cv[i] = cd_[i] * v[i] + (i > 0 ? cl_[i] * v[i - 1] : 0.0) +
              (i + 1 < n_ ? cu_[i] * v[i + 1] : 0.0);
    return;
  }
  for (int i = 0; i < n_; ++i) {
    double f = 0.0;
    for (int e = row_start_[i]; e < row_start_[i + 1]; ++e) f += c_val_[e] * v[col_[e]];
    cv[i] = f;
  }
}

}  // namespace pound

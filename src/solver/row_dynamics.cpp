#include "solver/row_dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "structure/building_on_base.hpp"

namespace pound {

RowDynamics::RowDynamics(const AssembledRow& row, const std::vector<RowStorey>& storeys,
                         bool track_energy, const RowGround* ground)
    : row_(row),
      storeys_(storeys),
      n_(row.dofs()),
      ns_(static_cast<int>(row.sites.size())),
      linear_(row.linear),
      track_(track_energy),
      ground_(row, ground),
      forces_(row, storeys) {
  active.assign(ns_, false);
  v0.assign(ns_, 0.0);
  crush.assign(ns_, 0.0);
  crushing.assign(ns_, 0);
  crush_law_penetration.assign(ns_, 0.0);
  storey.assign(n_, StoreyState{});
  layout_.dofs = n_;
  layout_.storey_offset.assign(n_, -1);
  for (int i = 0; i < n_; ++i) {
    const StoreyLaw& law = *storeys_[i].law;
    if (law.continuous_states() > 0) {
      layout_.storey_offset[i] = 2 * n_ + layout_.storey_states;
      layout_.storey_states += law.continuous_states();
    }
  }
  affine_ = !linear_;
  for (int i = 0; i < n_; ++i) {
    double slope, offset;
    affine_ = affine_ && storeys_[i].law->branch_line(storeys_[i].p, storey[i], slope, offset);
  }
  layout_.impulses = 2 * n_ + layout_.storey_states;
  layout_.energies = layout_.impulses + ns_;
  layout_.ground = layout_.energies + (track_ ? 3 : 0);
  set_ground_layout();
  slab_sites_ = std::all_of(row_.sites.begin(), row_.sites.end(), slab_site);
  plain_ = slab_sites_;
  force_.setZero(ns_);
  scratch_.setZero(n_);
  held_.assign(n_, 0);
  for (int i = 0; i < n_; ++i)
    if (row_.inv_mass(i) == 0.0) massless_.push_back(i);
  if (!massless_.empty()) {
    veff_.setZero(n_);
    rb_.setZero(static_cast<int>(massless_.size()));
    vb_ = rb_;
    factor_massless();
  }
}

// The floors' ground channels, and the ground states of the channels that a contact site meets
// from a building on another channel (the only ones whose displacement enters a penetration).
void RowDynamics::set_ground_layout() {
  const int channels = ground_.channels();
  mv_.assign(channels + 1, 0.0);
  layout_.ground_offset.assign(channels, -1);
  site_ground_.assign(ns_, {-1, -1});
  int next = layout_.ground;
  auto state_of = [&](int c) {
    if (layout_.ground_offset[c] < 0) {
      layout_.ground_offset[c] = next;
      next += 2;
    }
    return layout_.ground_offset[c];
  };
  for (int i = 0; i < ns_; ++i)
    if (ground_.differs(i))
      site_ground_[i] = {state_of(ground_.site_channels(i).first),
                         state_of(ground_.site_channels(i).second)};
  layout_.size = next;
}

// The impulses' rates and the contact forces of contact_force() on the sites' floors, every site
// a slab site (slab_sites(): w F is F for w = 1).
__attribute__((always_inline)) inline void RowDynamics::add_slab_forces(double* du,
                                                                        double* dv) const {
  const double* im = row_.inv_mass.data();
  for (int i = 0; i < ns_; ++i) {
    const double f = force_(i);
    du[layout_.impulses + i] = f;
    if (f == 0.0) continue;
    const auto& site = row_.sites[i];
    dv[site.dof_left] -= im[site.dof_left] * f;
    dv[site.dof_right] += im[site.dof_right] * f;
  }
}

// The right-hand side; Plain: plain() and no condensed base DOFs, a row of before issues 36
// and 38 (their column sites, force caps and quasi-static bases), whose tests it leaves out (the
// same operations on the same numbers otherwise: the same bits).
template <bool Plain>
__attribute__((always_inline)) inline void RowDynamics::rhs_of(double t,
                                                               const Eigen::VectorXd& y_in,
                                                               Eigen::VectorXd& dy) {
  if (Plain) {
    for (int i = 0; i < ns_; ++i) {
      double f = 0.0;
      if (active[i])
        f = (*laws_)[i]->force(slab_penetration(y_in, i), penetration_rate(y_in, i), v0[i]);
      force_(i) = f;
    }
  } else {
    contact_forces(y_in);
  }
  const double* a_g = ground_acc(t);
  dy.resize(layout_.size);
  // Condensed base DOFs: their u_b solved, v_b = 0 until quasi_static_rates() (issue 38).
  const Eigen::VectorXd& y = Plain || qs_.empty() ? y_in : quasi_static_state(y_in, a_g);
  const double* u = y.data();
  const double* v = u + n_;
  double* du = dy.data();
  double* dv = du + n_;
  if (!massless_.empty()) v = massless_velocities(y);  // y's are stale there: see project()
  std::copy(v, v + n_, du);
  if (linear_)
    forces_.linear(u, v, a_g, dv);
  else if (affine_)
    forces_.affine(u, v, a_g, dv);
  else
    forces_.general(y, storey, layout_.storey_offset, a_g, dy.data(), v);
  if (!massless_.empty()) massless_rates(dv);
  if (Plain)
    add_slab_forces(du, dv);
  else
    add_contact_forces(du, dv);
  if (!Plain && !qs_.empty()) {
    double* vw = (v == veff_.data()) ? veff_.data() : yq_.data() + n_;
    quasi_static_rates(a_g, vw, dy);
    v = vw;
  }
  if (any_held_)
    for (int i = 0; i < n_; ++i)
      if (held_[i]) du[i] = dv[i] = 0.0;
  if (track_) energy_rates(y, v, du + layout_.energies);
  if (layout_.size == layout_.ground) return;
  // The channels' accelerations at t, evaluated by ground_acc(t) above.
  const double* agc = ground_.last_channel_acc();
  for (int c = 0; c < ground_.channels(); ++c) {  // ug' = vg, vg' = ag
    const int g = layout_.ground_offset[c];
    if (g < 0) continue;
    du[g] = y(g + 1);
    du[g + 1] = agc[c];
  }
}

void RowDynamics::rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
  if (plain_ && qs_.empty())
    rhs_of<true>(t, y, dy);
  else
    rhs_of<false>(t, y, dy);
}

// The contact forces with crushing faces (docs/contact-models.md, "Crushing faces"): the cap
// during a crushing phase; otherwise the law on the penetration less the indentation, never
// above the cap (the phase starts where it reaches it: a switch of row_switches.hpp; the min
// only guards a crossing that rises and falls back inside one step).
void RowDynamics::capped_contact_forces(const Eigen::VectorXd& y) {
  for (int i = 0; i < ns_; ++i) {
    double f = 0.0;
    if (active[i]) f = crushing[i] ? force_cap_ : std::min(law_force(y, i), force_cap_);
    force_(i) = f;
  }
}

// The impulses' rates and the contact forces of contact_force() on the sites' DOFs.
void RowDynamics::add_contact_forces(double* du, double* dv) const {
  if (slab_sites_)
    add_slab_forces(du, dv);
  else
    add_point_forces(du, dv);
}

void RowDynamics::add_point_forces(double* du, double* dv) const {
  const double* im = row_.inv_mass.data();
  for (int i = 0; i < ns_; ++i) {
    const double f = force_(i);
    du[layout_.impulses + i] = f;
    if (f == 0.0) continue;
    const auto& site = row_.sites[i];  // w_k F on each DOF of a side (SitePoint)
    for (int k = 0; k < site.left.count; ++k) {
      const int d = site.left.dof[k];
      dv[d] -= im[d] * (site.left.weight[k] * f);
    }
    for (int k = 0; k < site.right.count; ++k) {
      const int d = site.right.dof[k];
      dv[d] += im[d] * (site.right.weight[k] * f);
    }
  }
}

void RowDynamics::storey_changed(int) {
  if (affine_) forces_.set_lines(storey);
  if (forces_.tangent_damping()) forces_.set_tangent_damping(storey);
  if (!massless_.empty()) factor_massless();
  if (!qs_.empty()) factor_quasi_static();
}

// Massless base DOFs (a flexible foundation without mass or rotary inertia; issue 29): their
// rows of M u'' + C u' + f = 0 have no inertia, so that C_bb v_b = -(C_ba v_a + f_b(u)) gives
// their velocities from the state (b massless, a the others). S = C_bb^-1 is formed here.
void RowDynamics::factor_massless() {
  const int m = static_cast<int>(massless_.size());
  Eigen::MatrixXd Cbb = Eigen::MatrixXd::Zero(m, m);
  std::vector<int> slot(n_, -1);
  for (int k = 0; k < m; ++k) slot[massless_[k]] = k;
  for (int k = 0; k < m; ++k)
    forces_.row_entries(massless_[k], 0, [&](int j, double c, double) {
      if (slot[j] >= 0) Cbb(k, slot[j]) = c;
    });
  massless_S_ = Cbb.inverse();
}

const double* RowDynamics::massless_velocities(const Eigen::VectorXd& y) {
  const double* u = y.data();
  double* v = veff_.data();
  std::copy(u + n_, u + 2 * n_, v);
  for (int b : massless_) v[b] = 0.0;
  const int kind = linear_ ? 0 : (affine_ ? 1 : 2);
  const int m = static_cast<int>(massless_.size());
  for (int k = 0; k < m; ++k)
    rb_(k) = -forces_.raw_force(massless_[k], u, v, kind, storey, u, layout_.storey_offset);
  vb_.noalias() = massless_S_ * rb_;
  for (int k = 0; k < m; ++k) v[massless_[k]] = vb_(k);
  return v;
}

// After the massive DOFs' accelerations dv: the massless ones' velocity rates, from the
// derivative of C_bb v_b = -(C_ba v_a + K_b u): v_b' = -S (K_b u' + C_ba v_a') (linear and
// piecewise-linear storeys; 0 for other laws, whose v_b the projection keeps on the constraint).
void RowDynamics::massless_rates(double* dv) {
  const int m = static_cast<int>(massless_.size());
  const double* v = veff_.data();
  for (int k = 0; k < m; ++k) {
    double r = 0.0;
    if (linear_ || affine_)
      forces_.row_entries(massless_[k], linear_ ? 0 : 1, [&](int j, double c, double kk) {
        r += kk * v[j];
        if (row_.inv_mass(j) != 0.0) r += c * dv[j];
      });
    rb_(k) = -r;
  }
  vb_.noalias() = massless_S_ * rb_;
  for (int k = 0; k < m; ++k) dv[massless_[k]] = vb_(k);
}

namespace {

// Whether the slowest root of m x'' + c x' + k x = 0 is stiff against a period T [s]: its
// condensation's relative error, 2 pi / (root T) for a real root (k / c without mass, the slow
// root 2 k / (c + sqrt(c^2 - 4 m k)) when overdamped) and (2 pi / (root T))^2 for an oscillating
// one (root sqrt(k / m), whose inertia the condensation leaves out), at most 2 pi / threshold.
bool stiff_root(double m, double c, double k, double T, double threshold) {
  const BaseRoots r = base_roots(m, c, k);  // structure/building_on_base.hpp
  if (r.real) return r.slow * T >= threshold;
  const double x = r.slow * T;
  return x * x / (2.0 * M_PI) >= threshold;
}

}  // namespace

// The shortest period of an oscillating mode (damping ratio below 1; step_period) of the row
// with the DOFs marked in `drop` massless [s].
double RowDynamics::period_without(const std::vector<char>& drop) const {
  Eigen::MatrixXd M = row_.M;
  for (int i = 0; i < n_; ++i)
    if (drop[i]) M(i, i) = 0.0;
  const ModalProperties m = modal_properties(M, row_.K, row_.C);
  double t = std::numeric_limits<double>::infinity();
  for (int i = 0; i < m.periods.size(); ++i)
    if (m.periods(i) > 0.0 && std::isfinite(m.periods(i)) && !(m.damping_ratios(i) >= 1.0))
      t = std::min(t, m.periods(i));
  return t;
}

double RowDynamics::condense_stiff_roots(double rate_times_period, double t_min) {
  if (!qs_.empty() || !std::isfinite(rate_times_period)) return t_min;
  const int nb = static_cast<int>(row_.sway.size());
  std::vector<double> mass(n_, 0.0), damping(n_, 0.0), spring(n_, 0.0);  // per base DOF, SI
  std::vector<char> base(n_, 0), candidate(nb, 0), loaded(n_, 0);
  // A base that a contact site loads (a slab striking a first storey's columns: the base takes
  // (1 - s) F) stays integrated: its quasi-static limit would need the contact force inside
  // the constraint K_b u_b + ... = P_b(u_b), which the condensation does not solve.
  for (const ContactSite& site : row_.sites)
    for (const SitePoint* pt : {&site.left, &site.right})
      for (int k = 0; k < pt->count; ++k)
        if (pt->weight[k] != 0.0) loaded[pt->dof[k]] = 1;
  bool massive = false;
  for (int bi = 0; bi < nb; ++bi) {
    bool all = true, any = false;
    const double t1 = bi < static_cast<int>(row_.periods.size()) && row_.periods[bi].size() > 0
                          ? row_.periods[bi](0)
                          : t_min;
    for (int d : {row_.sway[bi], row_.rot[bi]}) {
      if (d < 0) continue;
      double c = 0.0, k = 0.0;
      forces_.row_entries(d, 0, [&](int j, double cj, double kj) {
        if (j == d) c = cj, k = kj;
      });
      mass[d] = row_.inv_mass(d) == 0.0 ? 0.0 : 1.0 / row_.inv_mass(d);
      damping[d] = c, spring[d] = k;
      // (the condensed row's shortest period lies below the longest, t1: a cheap first test)
      any = true;
      all = all && stiff_root(mass[d], c, k, std::max(t1, t_min), rate_times_period);
    }
    for (int d : {row_.sway[bi], row_.rot[bi]})
      if (d >= 0 && loaded[d]) all = false;
    candidate[bi] = any && all;
    for (int d : {row_.sway[bi], row_.rot[bi]})
      if (d >= 0 && candidate[bi]) base[d] = 1, massive = massive || row_.inv_mass(d) != 0.0;
  }
  if (std::none_of(candidate.begin(), candidate.end(), [](char c) { return c != 0; })) return t_min;
  // The periods the condensed row steps at: those of the row with its candidate bases massless.
  const double t_cond = massive ? period_without(base) : t_min;
  if (!(t_cond > 0.0) || !std::isfinite(t_cond)) return t_min;
  std::vector<char> condensed(n_, 0);
  bool any_mass = false;
  for (int bi = 0; bi < nb; ++bi) {
    bool all = candidate[bi] != 0;
    for (int d : {row_.sway[bi], row_.rot[bi]})
      if (d >= 0)
        all = all && stiff_root(mass[d], damping[d], spring[d], t_cond, rate_times_period);
    for (int d : {row_.sway[bi], row_.rot[bi]})
      if (d >= 0 && all) condensed[d] = 1, any_mass = any_mass || row_.inv_mass(d) != 0.0;
  }
  for (int d = 0; d < n_; ++d)
    if (condensed[d]) qs_.push_back(d);
  if (qs_.empty()) return t_min;
  std::vector<int> first_order;
  for (int b : massless_)
    if (!condensed[b]) first_order.push_back(b);
  massless_ = first_order;
  if (!massless_.empty()) {
    rb_.setZero(static_cast<int>(massless_.size()));
    vb_ = rb_;
    factor_massless();
  }
  qs_mark_ = condensed;
  yq_.setZero(layout_.size);
  rq_.setZero(static_cast<int>(qs_.size()));
  vq_ = rq_;
  factor_quasi_static();
  return any_mass ? period_without(condensed) : t_min;
}

// K_bb over the condensed DOFs (the tangent lines' for piecewise-linear storeys, the initial
// stiffness otherwise), and Q = K_bb - C_ba M_a^-1 C_ab (C symmetric), for v_b.
void RowDynamics::factor_quasi_static() {
  const int m = static_cast<int>(qs_.size());
  const int kind = affine_ ? 1 : 0;
  std::vector<int> slot(n_, -1);
  for (int k = 0; k < m; ++k) slot[qs_[k]] = k;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(m, m), Ca = Eigen::MatrixXd::Zero(m, n_);
  for (int k = 0; k < m; ++k)
    forces_.row_entries(qs_[k], kind, [&](int j, double c, double kj) {
      if (slot[j] >= 0)
        K(k, slot[j]) = kj;
      else if (row_.inv_mass(j) != 0.0)
        Ca(k, j) = c;
    });
  qs_kinv_ = K.inverse();
  qs_ground_.resize(m);  // m_b times the earthquake's influence on b [kg]
  for (int k = 0; k < m; ++k) {
    const int b = qs_[k];
    qs_ground_(k) = row_.inv_mass(b) == 0.0 ? 0.0 : row_.influence(b) / row_.inv_mass(b);
  }
  qs_qinv_ = (K - Ca * row_.inv_mass.asDiagonal() * Ca.transpose()).inverse();
}

// y with the condensed DOFs' displacements solving K_b u + C_ba v_a + off_b = 0 (the base rows
// without C_bb v_b): one Newton step from y's (exact for linear and piecewise-linear storeys),
// chord iterations on K_bb for other laws; their velocities 0 (set by quasi_static_rates).
const Eigen::VectorXd& RowDynamics::quasi_static_state(const Eigen::VectorXd& y,
                                                       const double* a_g) {
  yq_ = y;
  double* u = yq_.data();
  double* v = u + n_;
  for (int b : qs_) v[b] = 0.0;
  const int kind = linear_ ? 0 : (affine_ ? 1 : 2);
  const int m = static_cast<int>(qs_.size());
  for (int it = 0; it < (kind == 2 ? 50 : 1); ++it) {
    for (int k = 0; k < m; ++k)
      rq_(k) = forces_.raw_force(qs_[k], u, v, kind, storey, u, layout_.storey_offset) +
               qs_ground_(k) * a_g[qs_[k]];
    vq_.noalias() = qs_kinv_ * rq_;
    double change = 0.0, size = 0.0;
    for (int k = 0; k < m; ++k) {
      u[qs_[k]] -= vq_(k);
      change = std::max(change, std::fabs(vq_(k)));
      size = std::max(size, std::fabs(u[qs_[k]]));
    }
    if (change <= 1e-14 * size) break;
  }
  return yq_;
}

// After the other DOFs' accelerations dv (with v_b = 0): v_b from the constraint's derivative,
// (K_bb - C_ba M_a^-1 C_ab) v_b = -(K_ba v_a + C_ba dv_a), into v and y's copy, and dv_a
// corrected by -M_a^-1 C_ab v_b (linear and piecewise-linear storeys: exact; other laws: their
// forces evaluated again with v_b). The condensed DOFs' rates: du_b = v_b, dv_b = 0.
void RowDynamics::quasi_static_rates(const double* a_g, double* v, Eigen::VectorXd& dy) {
  double* du = dy.data();
  double* dv = du + n_;
  const int m = static_cast<int>(qs_.size());
  const int kind = affine_ ? 1 : 0;
  const std::vector<char>& is_qs = qs_mark_;
  for (int k = 0; k < m; ++k) {
    double r = 0.0;
    forces_.row_entries(qs_[k], kind, [&](int j, double c, double kj) {
      if (is_qs[j]) return;
      r += kj * v[j];
      if (row_.inv_mass(j) != 0.0) r += c * dv[j];
    });
    rq_(k) = -r;
  }
  vq_.noalias() = qs_qinv_ * rq_;
  for (int k = 0; k < m; ++k) v[qs_[k]] = yq_(n_ + qs_[k]) = vq_(k);
  if (linear_ || affine_) {
    for (int k = 0; k < m; ++k)
      forces_.row_entries(qs_[k], kind, [&](int j, double c, double) {
        if (row_.inv_mass(j) != 0.0) dv[j] -= row_.inv_mass(j) * c * vq_(k);
      });
  } else {
    forces_.general(yq_, storey, layout_.storey_offset, a_g, du, v);
    if (!massless_.empty()) massless_rates(dv);
    add_contact_forces(du, dv);
  }
  for (int k = 0; k < m; ++k) du[qs_[k]] = vq_(k), dv[qs_[k]] = 0.0;
}

void RowDynamics::damping_matrix(Eigen::MatrixXd& C) const {
  if (forces_.tangent_damping())
    forces_.damping_matrix(C);
  else
    C = row_.C;
}

void RowDynamics::energy_rates(const Eigen::VectorXd& y, const double* v, double* dE) {
  double* cv = scratch_.data();
  forces_.damping(v, cv);
  std::fill(mv_.begin(), mv_.end(), 0.0);
  double vcv = 0.0, contact = 0.0, ground_work = 0.0;
  for (int i = 0; i < n_; ++i) {
    if (row_.inv_mass(i) != 0.0) mv_[ground_.channel(i)] += v[i] / row_.inv_mass(i);
    vcv += v[i] * cv[i];
  }
  for (int i = 0; i < ns_; ++i) {
    contact += force_(i) * penetration_rate(y, i);
    const auto& g = site_ground_[i];
    if (g.first >= 0) ground_work += force_(i) * (y(g.first + 1) - y(g.second + 1));
  }
  const double* agc = ground_.last_channel_acc();
  double input = -agc[0] * mv_[0];
  for (int c = 1; c <= ground_.channels(); ++c) input -= agc[c] * mv_[c];
  dE[0] = input + ground_work;
  dE[1] = vcv;
  dE[2] = contact;
}

double RowDynamics::storey_energies(const Eigen::VectorXd& y, Eigen::VectorXd& hysteretic) const {
  hysteretic.setZero(n_);
  double strain = 0.0;
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    const double d = drift(y, 0, i);
    hysteretic(i) = st.law->dissipated(st.p, storey[i], d, continuous_states(y, i));
    strain += st.law->stored(st.p, storey[i], d, continuous_states(y, i));
    // P-Delta: -P c^2 / (2 h), c the storey's chord (its drift on a fixed base).
    const double c = st.rot >= 0 ? storey_chord(st, i, y.data()) : d;
    if (st.kg != 0.0) strain -= 0.5 * st.kg * c * c;
  }
  return strain;
}

}  // namespace pound

#include "solver/row_dynamics.hpp"

#include <algorithm>
#include <cmath>

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

void RowDynamics::rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
  contact_forces(y);
  const double* a_g = ground_acc(t);
  dy.resize(layout_.size);
  const double* u = y.data();
  const double* v = u + n_;
  const double* im = row_.inv_mass.data();
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
  if (any_held_)
    for (int i = 0; i < n_; ++i)
      if (held_[i]) du[i] = dv[i] = 0.0;
  if (track_) energy_rates(y, v, t, du + layout_.energies);
  if (layout_.size == layout_.ground) return;
  const double* agc = ground_.channel_acc(t);
  for (int c = 0; c < ground_.channels(); ++c) {  // ug' = vg, vg' = ag
    const int g = layout_.ground_offset[c];
    if (g < 0) continue;
    du[g] = y(g + 1);
    du[g + 1] = agc[c];
  }
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

void RowDynamics::storey_changed(int) {
  if (affine_) forces_.set_lines(storey);
  if (forces_.tangent_damping()) forces_.set_tangent_damping(storey);
  if (!massless_.empty()) factor_massless();
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

void RowDynamics::damping_matrix(Eigen::MatrixXd& C) const {
  if (forces_.tangent_damping())
    forces_.damping_matrix(C);
  else
    C = row_.C;
}

void RowDynamics::energy_rates(const Eigen::VectorXd& y, const double* v, double t, double* dE) {
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
  const double* agc = ground_.channel_acc(t);
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

#pragma once
// The equations of motion of a row of buildings between switching events (physics.md sections
// 1-2 and 5a; docs/integration.md):
//   u' = v,  v' = -M^-1 (C v + f(u, x)) - ag + M^-1 P(u, v, ug, vg),  x' (storey laws),
//   J' = contact force per site,  E' (energy rates),  ug' = vg, vg' = ag (ground, per channel),
// with u relative to each building's own ground, ag the ground acceleration under each floor
// (its building's: ground/row_ground.hpp), f = K u for linear storeys and f_j = V_j - V_{j+1}
// from the storey laws' shears V otherwise (solver/row_forces.hpp), and P the contact forces of
// the active contacts, which act on absolute displacements: delta = (u_L + ug_L) - (u_R + ug_R)
// - gap. The ground displacement and velocity of a channel are states of y where a contact
// site joins buildings on different channels (they are the exact integrals of a piecewise-linear
// ag, which every step integrates exactly: steps end on the record's samples). It holds the
// discrete states the right-hand side depends on: which contacts are active (with their
// approach velocity) and each storey law's branch; solver/row_switches.hpp changes them at
// switching events. Kernel only: no files, no printing.
#include <Eigen/Dense>
#include <limits>
#include <vector>

#include "contact/contact_law.hpp"
#include "ground/floor_ground.hpp"
#include "solver/row_forces.hpp"
#include "structure/building_row.hpp"

namespace pound {

/// The state vector y = [u (n); v (n); x (storey continuous states); J (impulse per site);
/// E (energy balance: input, damping, contact, when tracked); G (ug, vg of each ground channel
/// that a contact site meets from a building on another channel)]. The error test covers u, v,
/// x.
struct StateLayout {
  int dofs = 0;           ///< floor DOFs n
  int storey_states = 0;  ///< continuous states of the storey laws
  int impulses = 0;       ///< offset of the impulses J in y
  int energies = 0;       ///< offset of the energies E in y
  int ground = 0;         ///< offset of the ground states G in y
  int size = 0;           ///< entries of y
  /// Per ground channel: the offset of its ug in y (vg follows), -1 when not a state.
  std::vector<int> ground_offset;
  std::vector<int> storey_offset;  ///< per DOF: offset of its storey's states in y, -1: none
  /// Entries under the local error test: u, v, x.
  int tested() const { return 2 * dofs + storey_states; }
};

class RowDynamics {
 public:
  /// `storeys` one per floor DOF of `row`; energies in the state when `track_energy`; `ground`
  /// under the row's buildings (null: none; kept by the caller).
  RowDynamics(const AssembledRow& row, const std::vector<RowStorey>& storeys, bool track_energy,
              const RowGround* ground);

  /// The contact laws, one per site (pounding), or none (the buildings vibrate independently).
  void set_contacts(const std::vector<const ContactLaw*>* laws) { laws_ = laws; }
  bool pounding() const { return laws_ != nullptr && !laws_->empty(); }
  /// The crushing faces' cap on every site's contact force [N] (docs/contact-models.md,
  /// "Crushing faces"); infinite: none (then nothing below about crushing ever acts).
  void set_force_cap(double cap) {
    force_cap_ = cap;
    plain_ = slab_sites_ && !(cap < kNoCap);
  }
  double force_cap() const { return force_cap_; }
  bool capped() const { return pounding() && force_cap_ < kNoCap; }
  /// Every site a slab site (SitePoint: one DOF of weight 1 each side; issue 36's column sites
  /// absent), and with plain() no force cap either: the fast paths of the rows of before issue 36
  /// (the same operations on the same numbers, so the same bits).
  bool slab_sites() const { return slab_sites_; }
  bool plain() const { return plain_; }
  /// Site i's contact law (pounding runs only).
  const ContactLaw& law(int i) const { return *(*laws_)[i]; }
  /// The law's own force at site i (before the cap) at y [N]: the law acting on the penetration
  /// less the permanent indentation (penetration() subtracts it).
  double law_force(const Eigen::VectorXd& y, int i) const {
    return (*laws_)[i]->force(penetration(y, i), penetration_rate(y, i), v0[i]);
  }
  /// The permanent indentation of site i's face at y [m]: the committed crush[i] plus, during a
  /// crushing phase, its growth since the phase began (c' = delta', so c - c_start = delta -
  /// delta_start: the law's own penetration stays crush_law_penetration[i]).
  double indentation(const Eigen::VectorXd& y, int i) const {
    return crushing[i] ? crush[i] + (penetration(y, i) - crush_law_penetration[i]) : crush[i];
  }

  const StateLayout& layout() const { return layout_; }
  bool linear() const { return linear_; }  ///< every storey linear elastic
  bool affine() const { return affine_; }  ///< every storey law piecewise linear
  const RowGround* ground() const { return ground_.ground(); }
  /// The ground acceleration under every floor DOF at t [m/s^2] (zeros without ground): the
  /// returned array holds n values until the next call.
  const double* ground_acc(double t) { return ground_.acc(t); }
  /// Each ground channel's acceleration at t [m/s^2], and 0 at index channels()
  /// (FloorGround::channel_acc; valid until the next call of it or ground_acc).
  const double* ground_channel_acc(double t) { return ground_.channel_acc(t); }
  /// The ground channel of floor DOF i (FloorGround::channel).
  int channel(int i) const { return ground_.channel(i); }
  /// The ground states of y at t [s] (exact: GroundTrace), after an exact step.
  void set_ground_states(double t, Eigen::VectorXd& y) const {
    for (int c = 0; c < ground_.channels(); ++c)
      if (layout_.ground_offset[c] >= 0)
        ground()->trace(c).kinematics(t, y(layout_.ground_offset[c] + 1),
                                      y(layout_.ground_offset[c]));
  }

  /// dy at (t, y) [SI per s]; the contact forces of y in contact_force().
  void rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy);
  /// The contact force per site at y [N] (zero where no contact is active).
  void contact_forces(const Eigen::VectorXd& y) {
    if (force_cap_ < kNoCap) return capped_contact_forces(y);
    for (int i = 0; i < ns_; ++i) {
      double f = 0.0;
      if (active[i]) f = (*laws_)[i]->force(penetration(y, i), penetration_rate(y, i), v0[i]);
      force_(i) = f;
    }
  }
  const Eigen::VectorXd& contact_force() const { return force_; }

  /// Penetration delta = (u_L + ug_L) - (u_R + ug_R) - gap at site i (physics.md sections 1,
  /// 5a and 5b) [m] and its rate, u_L and u_R the sides' points (SitePoint: a slab's floor, or
  /// the weighted floors of a struck column); the ground terms where the site's buildings stand
  /// on different channels.
  /// With a force cap, the face's permanent indentation crush[i] widens the gap (less its
  /// growth in a crushing phase: indentation()); without one crush[i] is 0 (x - 0 is x).
  /// plain(): the same values by the slabs' DOFs alone (1 x u is u, x - 0 is x).
  __attribute__((always_inline)) double penetration(const Eigen::VectorXd& y, int i) const {
    return plain_ ? slab_penetration(y, i) : point_penetration(y, i);
  }
  /// `slabs`: slab_sites(), or a constant where a loop was chosen once per run from it.
  double penetration_rate(const Eigen::VectorXd& y, int i) const {
    return penetration_rate(y, i, slab_sites_);
  }
  double penetration_rate(const Eigen::VectorXd& y, int i, bool slabs) const {
    const auto& s = row_.sites[i];
    const double* v = y.data() + n_;
    double r = slabs ? v[s.dof_left] - v[s.dof_right] : s.left.of(v) - s.right.of(v);
    const auto& g = site_ground_[i];
    if (g.first >= 0) r += y(g.first + 1) - y(g.second + 1);
    return r;
  }
  /// The approach (u_L + ug_L) - (u_R + ug_R) of site i's floors [m]: penetration + gap.
  double approach(const Eigen::VectorXd& y, int i) const { return approach(y, i, slab_sites_); }
  double approach(const Eigen::VectorXd& y, int i, bool slabs) const {
    const auto& s = row_.sites[i];
    double d = slabs ? y(s.dof_left) - y(s.dof_right) : s.left.of(y.data()) - s.right.of(y.data());
    const auto& g = site_ground_[i];
    if (g.first >= 0) d += y(g.first) - y(g.second);
    return d;
  }
  /// Drift of floor DOF `dof`'s storey in the block of y starting at `off` (0: displacements,
  /// n: velocities) [m], [m/s].
  double drift(const Eigen::VectorXd& y, int off, int dof) const {
    const RowStorey& st = storeys_[dof];
    const int b = st.below;
    const double d = y(off + dof) - (b >= 0 ? y(off + b) : 0.0);
    return st.rot >= 0 ? d - st.p.h * y(off + st.rot) : d;  // on a flexible foundation
  }
  /// The continuous states of floor DOF `dof`'s storey in y (null: none).
  const double* continuous_states(const Eigen::VectorXd& y, int dof) const {
    return layout_.storey_offset[dof] >= 0 ? y.data() + layout_.storey_offset[dof] : nullptr;
  }
  /// Shear of floor DOF `dof`'s storey at y [N].
  double storey_shear(const Eigen::VectorXd& y, int dof) const {
    const RowStorey& st = storeys_[dof];
    return st.law->shear(st.p, storey[dof], drift(y, 0, dof), continuous_states(y, dof));
  }
  /// Floor DOF i holds still from now on: no velocity or acceleration (a free run's collapsed
  /// building; its velocity must be set to zero by the caller).
  void hold(int i) {
    held_[i] = 1;
    any_held_ = true;
  }
  bool held(int i) const { return held_[i]; }
  /// After storey `dof` changed branch: the piecewise-linear forces' lines.
  void storey_changed(int dof);
  /// Massless base DOFs (issue 29) are first-order: their velocities follow from the state, and
  /// rhs() computes them (dy holds them as the displacements' rates) instead of reading y's
  /// velocity entries there. project() writes them into y (after each new state and its dy), so
  /// that drifts' rates, peaks and energies read the right ones. No-op without such DOFs.
  void project(Eigen::VectorXd& y, const Eigen::VectorXd& dy) const {
    for (int b : massless_) y(n_ + b) = dy(b);
    for (int b : qs_) y(b) = yq_(b), y(n_ + b) = yq_(n_ + b);  // rhs()'s last state, y's
  }
  const std::vector<int>& massless() const { return massless_; }
  /// A stiff root of a foundation (issue 38; docs/ssi.md, docs/integration.md): the base DOFs
  /// of each building whose slowest roots (alone on their spring, dashpot and mass: K_ii / C_ii
  /// without mass, sqrt(K_ii / M_ii) underdamped, the slow real root overdamped) [1/s] all reach
  /// `rate_times_period` / T (T [s] the shortest oscillating period of the row with those bases
  /// massless; t_min, the row's, when they are already) are condensed to their quasi-static
  /// limit: their own inertia and damping forces M_bb a_b + C_bb v_b are dropped from their rows,
  /// so that K_b u + C_ba v_a + off_b + M_bb ag_b = 0 gives u_b from the others (a singular
  /// perturbation, Kokotovic, Khalil & O'Reilly 1986, ch. 1; relative error O(omega / root),
  /// omega the row's frequencies), and its time derivative K_bb v_b + K_ba v_a + C_ba a_a = 0
  /// (the ground term's derivative left out) gives v_b. They leave massless(). rhs() then solves
  /// them at every state (y's entries there are only the starting guess; project() writes them
  /// back); their displacements' rates are v_b and their velocities' 0. Returns the shortest
  /// oscillating period of the row so condensed [s] (t_min unless a base with mass was).
  double condense_stiff_roots(double rate_times_period, double t_min);
  const std::vector<int>& quasi_static() const { return qs_; }
  const Eigen::VectorXd& inv_mass() const { return row_.inv_mass; }
  /// S = C_bb^-1 over the massless DOFs (their order in massless()) [m/(N s)].
  const Eigen::MatrixXd& massless_inverse() const { return massless_S_; }
  /// The stiffness of the linear or piecewise-linear right-hand side [N/m] and the offsets of
  /// the branches' lines [N] (solver/row_forces.hpp).
  void stiffness(Eigen::MatrixXd& K) const { forces_.stiffness(affine_, K); }
  const std::vector<double>& offsets() const { return forces_.offsets(); }
  /// The current damping matrix [N s/m] (the initial one unless tangent-stiffness damping).
  void damping_matrix(Eigen::MatrixXd& C) const;

  /// The storeys' strain energy (with P-Delta's -P d^2 / (2 h) per storey) and, per DOF, the
  /// hysteretic energy at y [J].
  double storey_energies(const Eigen::VectorXd& y, Eigen::VectorXd& hysteretic) const;

  // Discrete states (changed at switching events, solver/row_switches.hpp).
  std::vector<StoreyState> storey;  ///< per DOF: the discrete state of its storey law
  std::vector<char> active;         ///< per site: contact active
  std::vector<double> v0;           ///< per site: approach velocity at the contact's start [m/s]
  // Crushing faces (a force cap; solver/row_switches.hpp starts and ends the phases):
  std::vector<double> crush;   ///< per site: the committed permanent indentation c [m], >= 0
  std::vector<char> crushing;  ///< per site: in a crushing phase (F = cap, c' = delta')
  /// Per site: the law's own penetration delta - c held through the crushing phase [m] (the
  /// penetration where the law's force reached the cap).
  std::vector<double> crush_law_penetration;
  static constexpr double kNoCap = std::numeric_limits<double>::infinity();

 private:
  // E' = [input, damping v^T C v, contact sum_s F_s delta'_s] [W], the input being the work
  // of the effective earthquake forces -M ag on the floors, sum_i -ag_i m_i v_i, plus that of
  // the ground's relative motion on the contacts, sum_s F_s (vg_L - vg_R) (docs/ground.md).
  // At the t of the last ground_acc(t) (rhs_of's: the channels' accelerations are kept).
  void energy_rates(const Eigen::VectorXd& y, const double* v, double* dE);
  void factor_massless();
  const double* massless_velocities(const Eigen::VectorXd& y);
  void massless_rates(double* dv);
  void set_ground_layout();
  void capped_contact_forces(const Eigen::VectorXd& y);
  template <bool Plain>
  void rhs_of(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy);
  void add_contact_forces(double* du, double* dv) const;
  void add_slab_forces(double* du, double* dv) const;
  // penetration() with plain() and without.
  double slab_penetration(const Eigen::VectorXd& y, int i) const {
    const auto& s = row_.sites[i];
    double d = y(s.dof_left) - y(s.dof_right) - s.gap;
    const auto& g = site_ground_[i];
    if (g.first >= 0) d += y(g.first) - y(g.second);
    return d;
  }
  double point_penetration(const Eigen::VectorXd& y, int i) const {
    const auto& s = row_.sites[i];
    double d = s.left.of(y.data()) - s.right.of(y.data()) - s.gap - crush[i];
    const auto& g = site_ground_[i];
    if (g.first >= 0) d += y(g.first) - y(g.second);
    return d;
  }
  void add_point_forces(double* du, double* dv) const;
  void factor_quasi_static();
  const Eigen::VectorXd& quasi_static_state(const Eigen::VectorXd& y, const double* a_g);
  double period_without(const std::vector<char>& drop) const;
  void quasi_static_rates(const double* a_g, double* v, Eigen::VectorXd& dy);

  const AssembledRow& row_;
  const std::vector<RowStorey>& storeys_;
  const int n_, ns_;
  const bool linear_, track_;
  bool affine_ = false;
  StateLayout layout_;
  const std::vector<const ContactLaw*>* laws_ = nullptr;
  double force_cap_ = kNoCap;                     // [N]
  bool slab_sites_ = false, plain_ = false;       // slab_sites(), plain()
  FloorGround ground_;                            // the ground under floors and sites
  std::vector<std::pair<int, int>> site_ground_;  // per site: ug offsets of L and R, or -1
  mutable std::vector<double> mv_;                // per channel: sum m_i v_i (energy rates)
  std::vector<int> massless_;                     // DOFs without mass (a flexible foundation's)
  Eigen::MatrixXd massless_S_;                    // C_bb^-1 over them
  Eigen::VectorXd veff_, rb_, vb_;  // scratch: velocities with theirs, their forces, rates
  std::vector<int> qs_;             // massless DOFs condensed quasi-statically (issue 38)
  std::vector<char> qs_mark_;       // per DOF: one of them
  Eigen::MatrixXd qs_kinv_;         // K_bb^-1 over them [m/N]
  Eigen::MatrixXd qs_qinv_;         // (K_bb - C_ba M_a^-1 C_ab)^-1 over them [m/N]
  Eigen::VectorXd yq_, rq_, vq_;    // y with their u_b, v_b; their residual forces; rates
  Eigen::VectorXd qs_ground_;       // their masses times the earthquake's influence [kg]
  std::vector<char> held_;          // per DOF: held still (hold)
  bool any_held_ = false;
  Eigen::VectorXd force_;            // contact force per site [N]
  mutable Eigen::VectorXd scratch_;  // damping forces C v [N] (energy rates)
  RowForces forces_;                 // internal forces of the floors
};

}  // namespace pound

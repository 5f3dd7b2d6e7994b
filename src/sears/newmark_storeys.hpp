#pragma once
// Yielding storeys in the Newmark steps of the damped Sears row solver (issue 16;
// hysteresis/storey_law.hpp). The storey forces are written as
//     f(u) = K u - B r,    r_j = k0_j d_j - V_j,
// K the initial-stiffness matrix the Newmark operators were built with, V_j the shear of storey
// j's law and r_j the part of the linear spring's shear the law removes ((B r)_j = r_j - r_j+1).
// A step then solves Mt a_i+1 = p_i+1 - C (v + h/2 a) - K (u + h v + h^2/4 a) + B r_i+1 - D F,
// i.e. a_i+1 = a_hat + R r_i+1 - H F with R = Mt^-1 B, and r_i+1 follows from the return map of
// every storey at the end-of-step drifts. The fixed point is iterated with the constant Mt
// (modified Newton with the initial stiffness, Chopra, Dynamics of Structures, sec. 5.7;
// OpenSees' ModifiedNewton -initial): each pass contracts the error by about
// (1 - b) (w h)^2 / 4, so two or three passes suffice; a step in which no storey leaves its
// linear branch needs none. With P-Delta K already holds the geometric stiffness (K = K0 - Kg)
// and r stays the laws' part. With tangent-stiffness damping (RowStorey::damping_a1) r also
// takes the damper a1 (max(k_t, 0) - k0) of each such storey at the end-of-step drift rate:
// r_j = k0_j d_j - V_j - f_d,j, f_d,j = a1 (max(k_t,j, 0) - k0_j) dd_j (Charney 2008), k_t the
// tangent of the branch the step starts on (a coefficient of the trial's own branch has no
// fixed point when the branch changes in the step: the branch decides the damping that decides
// the branch; the lumped solver locates the switch instead).
// Kernel only: no files, no printing.
#include <Eigen/Dense>
#include <vector>

#include "structure/building_row.hpp"

namespace pound::sears {

class NewmarkStoreys {
 public:
  /// The storeys of `a`, loaded monotonically from rest to the initial displacements u0 [m].
  NewmarkStoreys(const AssembledRow& a, const Eigen::VectorXd& u0);

  /// True when every storey is linear (r stays 0 and nothing here is needed).
  bool linear() const { return linear_; }
  /// The committed correction r per floor DOF [N].
  const Eigen::VectorXd& correction() const { return r_; }
  /// B r: the correction's forces on the DOFs [N] (each storey's r along its deformation).
  Eigen::VectorXd forces(const Eigen::VectorXd& r) const;
  /// R = Mt^-1 B for a Newmark matrix Mt [1/kg].
  Eigen::MatrixXd influence(const Eigen::LLT<Eigen::MatrixXd>& mt) const;

  /// Whether a storey's damping follows its tangent stiffness (trial() needs the velocities).
  bool tangent_damping() const { return tangent_damping_; }
  /// Trial states for the step from the committed displacements u to u_end [m] (velocities
  /// v_end at its end [m/s]; read with tangent damping only). Writes their correction into
  /// `guess` and returns true when it differs from the guess given by no more than a relative
  /// 1e-12 (converged).
  bool trial(const Eigen::VectorXd& u, const Eigen::VectorXd& u_end, const Eigen::VectorXd& v_end,
             Eigen::VectorXd& guess);
  /// The work of the tangent damping's dampers over the step just committed, from the
  /// displacements u_prev to u (trapezoidal in the dampers' forces) [J]; 0 without.
  double damper_work(const Eigen::VectorXd& u_prev, const Eigen::VectorXd& u) const;
  /// Makes the last trial the committed state.
  void commit();
  /// Commits the given states (continuous states in StoreyState::x) at displacements u [m] and
  /// velocities v [m/s]: the state a stretch on the lumped solver's steps ended in (issue 30).
  void set_state(const std::vector<StoreyState>& states, const Eigen::VectorXd& u,
                 const Eigen::VectorXd& v);
  /// The committed states.
  const std::vector<StoreyState>& committed_states() const { return committed_; }

  /// Recoverable strain energy per building at the committed state and displacements u [J];
  /// -1 for a building whose storeys are all linear (TranslationBound then uses u^T K u / 2).
  const std::vector<double>& strain_by_building(const Eigen::VectorXd& u);
  /// Storey shear of floor DOF i's storey at the committed state and displacements u [N].
  double shear(const Eigen::VectorXd& u, int i) const;
  /// Hysteretic energy dissipated by floor DOF i's storey (committed) [J].
  double dissipated(const Eigen::VectorXd& u, int i) const;
  /// The committed discrete state of floor DOF i's storey.
  const StoreyState& committed(int i) const { return committed_[i]; }
  /// Recoverable strain energy of all storeys (committed), with P-Delta's -P d^2 / (2 h) [J].
  double stored(const Eigen::VectorXd& u) const;

 private:
  double drift(const Eigen::VectorXd& u, int i) const {
    const RowStorey& st = storeys_[i];
    const double d = u(i) - (st.below >= 0 ? u(st.below) : 0.0);
    return st.rot >= 0 ? d - st.p.h * u(st.rot) : d;  // on a flexible foundation (issue 29)
  }

  std::vector<RowStorey> storeys_;
  std::vector<StoreyState> committed_, trial_;
  std::vector<char> building_linear_;
  std::vector<double> strain_;
  Eigen::VectorXd r_, r_trial_;
  Eigen::VectorXd rd_, rd_trial_, rd_prev_;  // the damper forces f_d of tangent damping [N]
  // A storey whose trial failed within the step stays failed for the step's further passes: a
  // failure at an unloading has no fixed point otherwise (V for a trial drift past the failure,
  // 0 short of it).
  std::vector<char> can_fail_, failed_in_step_;
  bool linear_ = true;
  bool tangent_damping_ = false;
};

}  // namespace pound::sears

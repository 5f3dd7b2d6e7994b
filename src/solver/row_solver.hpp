#pragma once
// Time integration of buildings in a row with lumped-mass contacts (physics.md sections 1-2):
//   M u'' + C u' + K u = -M 1 ag(t) + P(u, u')
// by Dormand-Prince 5(4) with exact location of every contact event: the instants where a
// penetration delta crosses zero are found by Illinois iteration on re-taken Runge-Kutta steps,
// so no step straddles the start or end of a contact, where the force (and for the
// stereomechanical model the velocity) is discontinuous. Steps also end on every sample of the
// ground-motion record, where ag(t) has kinks. Kernel only: no files, no printing.
#include <Eigen/Dense>
#include <limits>
#include <vector>

#include "contact/contact_law.hpp"
#include "motion/ground_motion.hpp"
#include "solver/integrator_settings.hpp"
#include "solver/linear_step.hpp"
#include "structure/building_row.hpp"

namespace pound {

struct SiteResult {
  int impacts = 0;                ///< contact phases started
  double peak_force = 0.0;        ///< [N] (NaN for instantaneous impacts: no force history)
  double peak_penetration = 0.0;  ///< [m]
  double impulse = 0.0;           ///< total impulse transmitted [N s]
  double first_contact = -1.0;    ///< time of the first contact [s], -1 when none
  double last_separation = -1.0;  ///< time of the last separation [s], -1 when none
  /// Largest relative approach u_L - u_R of the site's floors over a run WITHOUT contact laws
  /// (the free run) [m]: the smallest at-rest gap that this motion would not close (its peak
  /// between steps from the cubic Hermite interpolant, as the contact events are located).
  /// NaN in a run with contacts.
  double peak_approach = std::numeric_limits<double>::quiet_NaN();
};

/// Time histories, one entry per accepted step and per event.
struct History {
  std::vector<double> t;               ///< [s]
  std::vector<Eigen::VectorXd> u;      ///< floor displacements relative to the ground [m]
  std::vector<Eigen::VectorXd> a_abs;  ///< absolute floor accelerations [m/s^2]
  std::vector<Eigen::VectorXd> force;  ///< contact force per site [N]
  std::vector<Eigen::VectorXd> shear;  ///< shear of the storey below each floor DOF [N]
};

/// Energy balance of a run, relative to the ground (Uang & Bertero 1990, "relative" energy
/// equation) [J]: input = kinetic + strain + damping + hysteretic + contact, where input is the
/// work of the effective earthquake forces -M 1 ag on the floors' motion, kinetic and strain
/// are the values at the end, and contact is the work the floors did on the contacts (what a
/// contact dissipated, plus what is still stored in a closed contact or, for the damped Sears
/// model, in the slabs' axial vibration at the end).
struct EnergyBalance {
  double input = 0.0, kinetic = 0.0, strain = 0.0, damping = 0.0, hysteretic = 0.0, contact = 0.0;
  /// input - (kinetic + strain + damping + hysteretic + contact): zero up to the integration
  /// error [J].
  double residual() const { return input - (kinetic + strain + damping + hysteretic + contact); }
};

struct RowResult {
  Eigen::VectorXd peak_disp;       ///< max |u| per floor DOF [m]
  Eigen::VectorXd peak_drift;      ///< max |u_j - u_{j-1}| per floor DOF (its storey) [m]
  Eigen::VectorXd peak_abs_accel;  ///< max |u'' + ag| per floor DOF [m/s^2]
  std::vector<SiteResult> sites;
  Eigen::VectorXd hysteretic_energy;  ///< per floor DOF: dissipated by its storey [J]
  EnergyBalance energy;               ///< when RowProblem::track_energy (else zeros)
  Eigen::VectorXd u_end, v_end;       ///< state at the end [m], [m/s]
  double t_end = 0.0;                 ///< time reached [s]
  long steps = 0, rejected = 0, events = 0;
  long exact_steps = 0;  ///< of `steps`, exact steps of the linear system (linear_step.hpp)
  /// Of `steps`, those the pounding run shares with the free run (solve_free_and_pounding:
  /// taken once, before the pounding run's first approach within 1 um of a contact).
  long steps_from_free = 0;
  History history;
};

/// The exact steps' propagators of one row (docs/integration.md, "Exact steps"), one per
/// tangent stiffness met, kept between the runs that share the row, the motion's spacing and the
/// integrator settings (simulate_row: the free and the pounding run of a sample). A run uses a
/// stiffness' propagator from the kExactWarmup-th grid point at which it met that stiffness on
/// (briefer branches, a storey yielding for a few steps, cost less by Dormand-Prince than a
/// propagator); counted per run, so that a run takes the same steps with or without the cache.
struct ExactStepCache {
  static constexpr int kExactWarmup = 32;
  struct Entry {
    Eigen::MatrixXd K;  ///< tangent stiffness [N/m]
    bool ready = false;
    LinearStep step;
  };
  std::vector<Entry> entries;
  const AssembledRow* row = nullptr;  ///< the row and grid step [s] of the entries (a run of
  double h = 0.0;                     ///< another row or step clears them)
};

struct RowProblem {
  const AssembledRow* row = nullptr;
  const GroundMotion* motion = nullptr;  ///< null: no ground motion
  /// One law per contact site; empty: no pounding (the buildings move independently).
  std::vector<const ContactLaw*> laws;
  Eigen::VectorXd u0, v0;  ///< initial state (empty: at rest) [m], [m/s]
  double t_end = 0.0;      ///< [s]
  bool record_history = false;
  bool track_energy = false;  ///< integrate the energy balance (RowResult::energy)
  /// Stop as soon as every contact has ended and all sites separate (free impacts).
  bool stop_after_separation = false;
  /// Propagators shared with the other runs of this row (null: kept for this run only).
  ExactStepCache* exact_cache = nullptr;
};

/// Integrates the problem. Throws NumericalError on a non-finite state, step-size underflow or
/// an accumulation of instantaneous impacts (chatter).
RowResult solve(const RowProblem& p, const IntegratorSettings& s);

struct RunPair {
  RowResult free;      ///< without contacts (as solve() of p without its laws)
  RowResult pounding;  ///< with p's contact laws (as solve(p))
};

/// The runs of a sample without and with its contacts (p.laws: one per site), their common part
/// integrated once: until a site first comes within 1 um of touching (on the interpolant of the
/// free run's step, on which contact events are located), no contact is active and no contact
/// switch can fire, so the pounding run's steps are the free run's; it continues from the free
/// run's state at the start of that step. When no site comes that near, the two runs are one.
/// The free run is solve()'s without the laws, bit for bit. The pounding run is solve(p)'s bit
/// for bit as long as solve(p) took the free run's steps up to there; a rejected trial step
/// whose (inaccurate) interpolant crossed a gap can make solve(p) choose other step sizes before
/// its first contact, and then the two agree to the integration tolerance (docs/speed.md).
/// The propagators of exact steps are shared (p.exact_cache, or one of the call's own). Throws
/// as solve().
RunPair solve_free_and_pounding(const RowProblem& p, const IntegratorSettings& s);

}  // namespace pound

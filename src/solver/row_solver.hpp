#pragma once
// Time integration of buildings in a row with lumped-mass contacts (physics.md sections 1-2):
//   M u'' + C u' + K u = -M 1 ag(t) + P(u, u')
// by Dormand-Prince 5(4) with exact location of every contact event: the instants where a
// penetration delta crosses zero are found by Illinois iteration on re-taken Runge-Kutta steps,
// so no step straddles the start or end of a contact, where the force (and for the
// stereomechanical model the velocity) is discontinuous. Steps also end on every sample of the
// ground motions, where ag(t) has kinks; each building has its own ground (ground/row_ground.hpp)
// and the contacts act on absolute displacements (physics.md section 5a). Kernel only: no files, no
// printing.
#include <Eigen/Dense>
#include <limits>
#include <memory>
#include <vector>

#include "contact/contact_law.hpp"
#include "ground/row_ground.hpp"
#include "solver/exact_steps.hpp"
#include "solver/integrator_settings.hpp"
#include "solver/row_result.hpp"
#include "solver/run_recorder.hpp"
#include "structure/building_row.hpp"

namespace pound {

struct RowProblem {
  const AssembledRow* row = nullptr;
  /// The ground under each building (issue 28; its channels share one sample grid); null: none.
  const RowGround* ground = nullptr;
  /// One law per contact site; empty: no pounding (the buildings move independently).
  std::vector<const ContactLaw*> laws;
  /// Crushing faces (issue 36; docs/contact-models.md): the cap on every site's contact force
  /// [N], > 0. Where a law's force would pass it the face crushes: F stays at the cap and a
  /// permanent indentation grows with the approach until unloading; the law then acts on the
  /// penetration less the indentation. Infinite: no cap. Laws with a force history only.
  double force_cap = std::numeric_limits<double>::infinity();
  Eigen::VectorXd u0, v0;  ///< initial state (empty: at rest) [m], [m/s]
  double t_end = 0.0;      ///< [s]
  bool record_history = false;
  bool track_energy = false;  ///< integrate the energy balance (RowResult::energy)
  /// Stop as soon as every contact has ended and all sites separate (free impacts).
  bool stop_after_separation = false;
  /// Propagators shared with the other runs of this row (null: kept for this run only).
  ExactStepCache* exact_cache = nullptr;
  /// Collapse (issue 23): a building whose storey drift ratio passes this, or one of whose
  /// storeys fails (StoreyLaw::failed) under P-Delta, has collapsed. A run with contacts stops at
  /// the first collapse; a run without holds the building still and goes on (RowResult::collapse).
  /// Infinite: no check [-].
  double collapse_drift_ratio = std::numeric_limits<double>::infinity();
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

/// The same for the row `row` (p.row = &assemble(row)): where fork_apart_applies(row, p) (a
/// row of an elastic and a yielding building: solver/row_stepper.hpp) the free run building by
/// building and the pounding run forked at a common time (solve_free_and_pounding_apart); else
/// solve_free_and_pounding(p, s), bit for bit.
RunPair solve_free_and_pounding(const BuildingRow& row, const RowProblem& p,
                                const IntegratorSettings& s);

namespace detail {
class RowRun;
}

/// The stretches of a run without contact forces that a damped Sears run takes between its
/// contacts (issue 30, docs/speed.md): the lumped solver's exact and adaptive steps (every
/// storey law, P-Delta, tangent damping, collapse), from a state the caller gives to a time it
/// gives, so that the floors between contacts cost what they cost in a lumped run.
class FreeStretches {
 public:
  /// `p` without contact laws (p.laws empty); `s` the lumped integrator's settings. Both are
  /// kept by reference: they must outlive this object.
  FreeStretches(const RowProblem& p, const IntegratorSettings& s);
  ~FreeStretches();
  FreeStretches(const FreeStretches&) = delete;
  FreeStretches& operator=(const FreeStretches&) = delete;

  /// Continues from time t [s] with floor displacements u [m] and velocities v [m/s], each
  /// storey's state (continuous states in StoreyState::x), and the energy balance so far
  /// (input, damping, contact [J]; read when p.track_energy).
  void resume(double t, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
              const std::vector<StoreyState>& storeys, const double* energies);
  /// Steps to t_stop [s], recording into `rec` (the caller's run: its peaks, histories,
  /// collapse policy). True when a collapse stopped it; collapses of the last step are left in
  /// `rec` (RunRecorder::take_new_collapses).
  bool advance_to(double t_stop, RunRecorder& rec);

  double time() const;
  /// The state reached, into the caller's arrays (sized already: no allocation): displacements
  /// [m], velocities [m/s], relative accelerations [m/s^2], and each storey's state with its
  /// continuous states in x.
  void state(Eigen::VectorXd& u, Eigen::VectorXd& v, Eigen::VectorXd& acc) const;
  void storeys(std::vector<StoreyState>& out) const;
  /// The energy balance so far: input, damping, contact [J] (p.track_energy).
  void energies(double* e) const;

 private:
  std::unique_ptr<detail::RowRun> run_;
};

}  // namespace pound

#pragma once
// Free impact of two axial bars with the damped Sears model (thesis ch. 7; docs/sears.md).
//
// Bar 1 moves at v0 towards bar 2, which is at rest; bar 1's right end (x = l1) meets bar 2's
// left end (x = 0) at t = 0 with both bars unstrained. Each bar is a rigid body (its centre of
// mass, mode 0) plus N damped internal axial modes (ModalBank). The contact force follows from
// the overlap of the two faces, delta = u1(l1) - u2(0), through SlabContactLaw. The run continues
// after separation until the bars can no longer touch again (free vibration can bring the
// faces back: the thesis' pendulums chatter), counting contact phases.
#include <vector>

#include "contact/impact_result.hpp"
#include "sears/slab.hpp"
#include "sears/slab_contact_law.hpp"
#include "sears/step_rule.hpp"

namespace pound::sears {

/// How the contact force is coupled to the modal and rigid-body updates within one step.
enum class Coupling {
  /// Default. The force is linear over the step (as the exact recurrence assumes) and its end
  /// value is solved implicitly: every state at the end of the step is affine in that force,
  /// so the overlap is delta_pred - S F and F = law(delta_pred - S F) is one monotone scalar
  /// equation (the fixed point a predictor-corrector iteration would converge to).
  /// Second order in dt; unconditionally stable for any contact stiffness.
  implicit_linear_force,
  /// Thesis scheme (Th. 8.8): the force found at the end of the previous step is held constant
  /// over the step, then recomputed from the new overlap. First order in dt.
  lagged_force,
};

struct SearsImpactSpec {
  Slab bar1;               ///< the striker, moving at v0 [m/s] in +x
  Slab bar2;               ///< the struck bar, at rest
  double v0_m_s = 0.0;     ///< approach velocity [m/s], > 0
  int modes = 100;         ///< N internal modes per bar [-]
  double xi_s = 0.05;      ///< modal damping ratio of the slabs' axial vibration [-]
  SlabContactLaw contact;  ///< force-overlap law at the faces
  double dt_s = 0.0;       ///< step [s]; 0 = automatic (sears/step_rule.hpp)
  Coupling coupling = Coupling::implicit_linear_force;
  double max_time_s = 0.0;      ///< give up (NumericalError) after this time; 0 = automatic [s]
  bool record_history = false;  ///< fill SearsImpactOutcome::history (one sample per step)
};

/// State at the end of one step (recorded only when asked).
struct SearsImpactSample {
  double t_s = 0.0;        ///< [s]
  double force_N = 0.0;    ///< contact force [N]
  double overlap_m = 0.0;  ///< delta = u1(l1) - u2(0) [m]
};

/// Everything a run measures; `impact` is what `pound impact --json` reports.
struct SearsImpactOutcome {
  ImpactResult impact;
  double dt_s = 0.0;                    ///< step used [s]
  long steps = 0;                       ///< steps taken
  double end_time_s = 0.0;              ///< time when no further contact was possible [s]
  double first_phase_impulse_Ns = 0.0;  ///< impulse of the first contact phase [N s]
  double first_phase_duration_s = 0.0;  ///< [s]
  double peak_face_accel1 = 0.0;        ///< peak |acceleration| of bar 1's contact face [m/s^2]
  double peak_face_accel2 = 0.0;        ///< bar 2's contact face [m/s^2]
  double peak_centre_accel1 = 0.0;      ///< peak |acceleration| of bar 1's centre [m/s^2]
  double peak_centre_accel2 = 0.0;      ///< [m/s^2]
  double initial_energy_J = 0.0;        ///< kinetic energy before impact [J]
  /// Largest |total energy(t) - initial energy| over the run: rigid-body kinetic + modal +
  /// contact potential + energy dissipated by modal damping + crushing work (the work
  /// balance) [J].
  double max_energy_error_J = 0.0;
  double dissipated_J = 0.0;  ///< energy dissipated by slab damping [J]
  /// Crushing faces at the force cap (issue 36; SlabContactLaw::crush_increment): the
  /// permanent indentation at the end [m] and its work, PF_max x crush_m [J] (0 without a cap).
  double crush_m = 0.0, crushing_J = 0.0;
  std::vector<SearsImpactSample> history;  ///< from t = 0, when spec.record_history
};

/// Runs one impact. Throws InputError for invalid specs (including a too-large dt, naming the
/// largest allowed value) and NumericalError when no final separation happens by max_time_s.
SearsImpactOutcome run_sears_impact(const SearsImpactSpec& spec);

/// The fields every contact model reports (`pound impact`).
ImpactResult simulate_sears_impact(const SearsImpactSpec& spec);

/// Step limits for a spec (automatic and largest allowed dt).
StepLimits sears_impact_step_limits(const SearsImpactSpec& spec);

}  // namespace pound::sears

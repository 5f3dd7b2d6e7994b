#pragma once
// What one run of a building row returns, whichever solver integrated it (the adaptive
// lumped-mass solver, solver/row_solver.hpp, or the damped Sears solver,
// sears/sears_simulation.hpp); solver/run_recorder.hpp fills it the same way for both.
#include <Eigen/Dense>
#include <limits>
#include <vector>

namespace pound {

struct SiteResult {
  int impacts = 0;                ///< contact phases started
  double peak_force = 0.0;        ///< [N] (NaN for instantaneous impacts: no force history)
  double peak_penetration = 0.0;  ///< [m]
  double impulse = 0.0;           ///< total impulse transmitted [N s]
  double first_contact = -1.0;    ///< time of the first contact [s], -1 when none
  double last_separation = -1.0;  ///< time of the last separation [s], -1 when none
  /// The contact face's permanent indentation at the end (crushing at a force cap; 0 without)
  /// [m]: the at-rest gap has widened by it.
  double crush = 0.0;
  /// Largest relative approach u_L - u_R of the site's floors over a run WITHOUT contact laws
  /// (the free run) [m]: the smallest at-rest gap that this motion would not close (its peak
  /// between steps from the cubic Hermite interpolant, as the contact events are located).
  /// NaN in a run with contacts.
  double peak_approach = std::numeric_limits<double>::quiet_NaN();
  /// Column sites (issue 36): the peak shear demand on the struck face's columns,
  /// column_shear_demand() at the steps' ends [N]; in the free run the sway shear alone. NaN at
  /// a slab site.
  double peak_column_shear = std::numeric_limits<double>::quiet_NaN();
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
/// model, in the slabs' axial vibration at the end). crushing is the work of the crushing
/// faces at a force cap, cap x indentation per site (docs/contact-models.md), not in contact.
struct EnergyBalance {
  double input = 0.0, kinetic = 0.0, strain = 0.0, damping = 0.0, hysteretic = 0.0, contact = 0.0;
  double crushing = 0.0;
  /// input - (kinetic + strain + damping + hysteretic + contact + crushing): zero up to the
  /// integration error [J].
  double residual() const {
    return input - (kinetic + strain + damping + hysteretic + contact + crushing);
  }
};

/// Why a building collapsed (issue 23).
enum class CollapseCause {
  none,
  drift,          ///< a storey's drift ratio passed the collapse drift ratio
  failed_storey,  ///< a storey lost all strength under its P-Delta load
};

/// Whether and where a building of the row collapsed in a run.
struct BuildingCollapse {
  bool collapsed = false;
  double time = -1.0;  ///< [s]; -1 when standing
  int storey = 0;      ///< 1-based storey of the building where it happened; 0 when standing
  CollapseCause cause = CollapseCause::none;
};

struct RowResult {
  Eigen::VectorXd peak_disp;       ///< max |u| per floor DOF [m]
  Eigen::VectorXd peak_drift;      ///< max |u_j - u_{j-1}| per floor DOF (its storey) [m]
  Eigen::VectorXd peak_abs_accel;  ///< max |u'' + ag| per floor DOF [m/s^2]
  std::vector<SiteResult> sites;
  Eigen::VectorXd hysteretic_energy;  ///< per floor DOF: dissipated by its storey [J]
  EnergyBalance energy;               ///< when the run tracks it (else zeros)
  Eigen::VectorXd u_end, v_end;       ///< state at the end [m], [m/s]
  double t_end = 0.0;                 ///< time reached [s]
  /// Per building (when the run checks collapse; else empty). A run with contacts stops at the
  /// first collapse (`stopped`): every building's peaks are those up to then. A run without
  /// contacts holds a collapsed building still and goes on with the others; its energy balance
  /// is the one at its first collapse.
  std::vector<BuildingCollapse> collapse;
  bool stopped = false;  ///< ended at a collapse before the end of the run
  long steps = 0, rejected = 0, events = 0;
  long exact_steps = 0;  ///< of `steps`, exact steps of the linear system (linear_step.hpp)
  /// Of `steps`, those the pounding run shares with the free run (solve_free_and_pounding:
  /// taken once, before the pounding run's first approach within 1 um of a contact).
  long steps_from_free = 0;
  History history;
};

}  // namespace pound

#pragma once
// Buildings in a row pounding through damped Sears contacts (thesis ch. 8; docs/sears.md).
//
// Every slab that can collide (a slab of a ContactSite: both of a slab-to-slab site, the
// striking one of a slab-to-column site, issue 36) is an axial bar (Slab) whose rigid-body mode
// is the building's own floor DOF (Th. 8.5) and whose N internal modes are stepped by ModalBank
// (Th. 8.7); the other floors stay lumped, and a struck column point is a weighted point of its
// floors (SitePoint) with the columns' k_col in series with the law (sears_row_layout.hpp). One
// step (Th. 8.8, made implicit in the contact forces as for the free impact):
//   1. the building DOFs by Newmark's average-acceleration method (as in the thesis): the
//      end-of-step displacements are u_pred - G F, G = Khat^-1 [e_L - e_R per site] (e_L, e_R
//      the sides' points: w_k on their DOFs);
//   2. the internal modes by the exact linear-force recurrence: end-of-step faces are
//      predictions plus the modal step flexibility times F;
//   3. the face overlaps are therefore delta = delta_pred - S F with S constant and symmetric
//      positive definite (building part d^T Khat^-1 d plus modal same/cross flexibilities);
//   4. F_s = law_s(delta_s) for all sites at once by nonlinear Gauss-Seidel (each sweep solves
//      one site's monotone scalar equation; converges: it minimises a strictly convex function),
//      then every state is advanced with the forces linear over the step.
// Both integrators are second order; the step follows sears/step_rule.hpp with the building
// periods and the record spacing as further bounds.
// Event stepping (default; docs/speed.md): while no contact acts and a rigorous bound on the
// faces' approach (TranslationBound for the floors, ModalBank::face_motion_bound for the
// internal vibration) shows that none can start within the next coarse step, one coarse step
// replaces `ratio` fine ones: Newmark for the floors, the exact free recurrence for the modes.
#include <Eigen/Dense>
#include <limits>
#include <vector>

#include "ground/row_ground.hpp"
#include "motion/ground_motion.hpp"
#include "sears/slab_contact_law.hpp"
#include "simulation/simulate_row.hpp"
#include "solver/integrator_settings.hpp"
#include "solver/row_result.hpp"
#include "structure/building_row.hpp"

namespace pound::sears {

/// Slab of every floor of one building; each floor's mass is its own (A = m / (rho l)).
struct FloorSlabProperties {
  double length_m = 0.0;   ///< slab length along the row [m]
  double E_Pa = 0.0;       ///< Young's modulus [Pa]
  double rho_kg_m3 = 0.0;  ///< density [kg/m^3]
  double poisson = 0.0;    ///< Poisson's ratio [-]
  /// Per-floor values where the floors differ (floor 1 first); empty: the values above for
  /// every floor.
  std::vector<double> length_per_floor_m{}, E_per_floor_Pa{}, rho_per_floor_kg_m3{};
};

/// Time stepping of solve_sears_row (docs/speed.md).
enum class SearsStepping {
  fixed,  ///< the step rule's step throughout (the reference path)
  event,  ///< coarse steps while a rigorous bound excludes contact, the fine step otherwise
};

/// A coarse step is at most this fraction of the shortest building period (Newmark average
/// acceleration: period error (w h)^2 / 12 = 8e-5 at h = T / 200; at T / 50 grazing contacts,
/// whose force is a small difference of displacements, moved by up to 3 %) [-].
inline constexpr double kCoarseStepPerBuildingPeriod = 1.0 / 200.0;
/// A coarse step is taken only if the bound on the faces' approach, times this factor, is below
/// the current gap: it covers the difference between the Newmark step and the exact motion the
/// bound holds for, and round-off [-].
inline constexpr double kCoarseBoundSafety = 2.0;
/// A sleeping slab's site keeps F = 0 only while the bound of its overlap is below
/// -kGuardRoundOff times the magnitudes that enter it (round-off of the awake path) [-].
inline constexpr double kGuardRoundOff = 1e-9;
/// An awake slab is considered for dormancy after the first coarse step of a run and then every
/// kDormancyRetry coarse steps (its bounds cost about one free step) [-].
inline constexpr long kDormancyRetry = 32;

struct SearsRowModel {
  std::vector<FloorSlabProperties> slabs;  ///< one per building of the row
  int modes = 100;                         ///< N internal modes per colliding floor [-]
  double xi_s = 0.05;                      ///< slab modal damping ratio [-]
  double chi = 1.0 / 8.0;                  ///< wave-speed factor [-]
  ContactKind contact = ContactKind::flat;
  double D = 1.0;        ///< flat: fraction factor (Th. 8.2) [-]
  double hertz_k = 0.0;  ///< hertz: stiffness [N/m^1.5]; 0: from the radii below
  /// hertz: radii of the left and right contact faces of every pair [m] (kFlatRadius for a
  /// flat face); k = (4/3) E* sqrt(R*) from the two slabs' E and Poisson's ratios (Th. 7.2).
  double hertz_radius_left = 0.0, hertz_radius_right = 0.0;
  double force_cap_N = std::numeric_limits<double>::infinity();  ///< PF_max (Th. 9.1) [N]
  double dt_s = 0.0;                                             ///< (fine) step; 0 = automatic
  SearsStepping stepping = SearsStepping::event;
  /// Event stepping: slabs with no force at the start of a run of fine steps sleep (are not
  /// stepped) while a bound shows their sites stay apart, and in runs of coarse steps slabs go
  /// dormant while bounds show that their free vibration changes no decision and no peak
  /// (docs/speed.md). false: every slab takes every step (for comparison; the results agree to
  /// round-off with contact_step_tolerance = 0: longer steps depend on which slabs sleep).
  bool sleeping_slabs = true;
  /// Event stepping: a step through contacts may span up to SearsSteps::longest fine steps
  /// while every site's contact force, linear over the step, departs from its quadratic
  /// interpolant through the last three step ends by at most this fraction of the force: the
  /// second divided difference F'' / 2 gives the departure F'' h^2 / 8 (docs/speed.md, "Longer
  /// steps through smooth contact forces"). A step in which a contact starts or ends is a fine
  /// one. 0: every step through contacts is a fine one [-].
  double contact_step_tolerance = 1e-3;
  /// Approach velocity used for the Hertz contact time scale of the step rule [m/s].
  double hertz_reference_velocity = 1.0;
  /// A contact phase counts as an impact when its peak force is at least this fraction of the
  /// largest force at its site during the run (see ContactPhase, docs/sears.md) [-].
  double impact_force_fraction = 0.01;
};

/// One contact phase of a site: from the instant the faces overlap (delta > 0, Th. 8.1 law
/// active) to the instant they part, both located by linear interpolation of the overlap.
/// Every phase is kept, however small its force ("raw" count); count_impacts() applies the
/// impact threshold. With a zero gap the buildings touch at small amplitude whenever their
/// relative motion reverses, which opens phases carrying a negligible force; with too few modes
/// the truncated series also lets a face creep ahead of the wave front and open microscopic
/// phases. Neither is an impact in the engineering sense, hence the threshold.
struct ContactPhase {
  double start_s = 0.0;       ///< overlap begins [s] (0 when the faces overlap at the start)
  double end_s = -1.0;        ///< faces part [s]; -1 while still in contact at the end
  double peak_force_N = 0.0;  ///< [N]
  double impulse_Ns = 0.0;    ///< integral of the force over the phase [N s]
};

/// Contact phases of one site and the impact count with the threshold applied.
struct SiteContacts {
  std::vector<ContactPhase> phases;  ///< every phase in time order; phases.size() = raw count
  int impacts = 0;               ///< phases with peak force >= fraction x the site's largest [-]
  double first_impact_s = -1.0;  ///< start of the first counted phase [s]; -1 when none
};

/// Fills impacts and first_impact_s of `c` from its phases: a phase counts when its peak force
/// is positive and at least `fraction` times the largest peak force of the site. A relative
/// threshold keeps the count independent of the record's scale, as every other measure is for
/// a flat (linear) contact with a zero gap (the problem is then positively homogeneous).
void count_impacts(SiteContacts& c, double fraction);

struct SlabPeaks {
  int building = 0;           ///< 0-based
  int floor = 0;              ///< 1-based
  double face_accel = 0.0;    ///< peak |absolute acceleration| of its contact face(s) [m/s^2]
  double centre_accel = 0.0;  ///< peak |absolute acceleration| of the slab centre [m/s^2]
};

struct SearsRowProblem {
  const BuildingRow* row = nullptr;
  /// The ground under each building (issue 28; its channels share one sample grid); null: none.
  const RowGround* ground = nullptr;
  double t_end = 0.0;           ///< [s]
  bool contacts = true;         ///< false: the buildings vibrate independently
  bool record_history = false;  ///< one History entry per step
  bool track_energy = false;    ///< the energy balance (RowResult::energy)
  Eigen::VectorXd u0, v0;       ///< initial floor state (empty: at rest) [m], [m/s]
  /// Collapse (issue 23), as RowProblem::collapse_drift_ratio: a run with contacts stops at the
  /// first collapse, one without holds the building still [-]; infinite: no check.
  double collapse_drift_ratio = std::numeric_limits<double>::infinity();
  /// The lumped solver's settings (tolerances, exact steps) for the stretches without contact
  /// (SearsSteps::lumped) and for the run without contacts of simulate_sears_row.
  IntegratorSettings integrator;
};

/// How a run was stepped.
struct SearsStepCounts {
  long fine = 0;                  ///< steps through contacts: the fine (step rule) size or longer
  long fine_in_contact = 0;       ///< of those, steps with a contact force at either end
  long coarse = 0;                ///< coarse steps (event stepping)
  long bound_violations = 0;      ///< coarse steps that ended with an overlap (must stay 0)
  long slab_sleeps = 0;           ///< slabs put to sleep for a run of fine steps (event stepping)
  long slab_wakes = 0;            ///< sleeping slabs woken before the end of their interval
  long dormant_runs = 0;          ///< slabs gone dormant in runs of coarse steps
  long dormant_slab_steps = 0;    ///< coarse steps skipped by dormant slabs (per slab)
  long dormant_wakes = 0;         ///< dormant slabs woken (a bound did not settle a question)
  long storey_iterations = 0;     ///< extra passes for yielding storeys (inelastic buildings)
  long long_steps = 0;            ///< fine steps (counted in `fine`) longer than the fine step
  long long_step_rejections = 0;  ///< longer steps solved again shorter (force not smooth)
  long lumped = 0;                ///< steps of h_L on the lumped solver (SearsSteps::lumped)
  long lumped_stretches = 0;      ///< stretches of them (each from a state the Newmark steps left)
};

struct SearsRowResult {
  RowResult row;                       ///< the fields the lumped solver reports
  std::vector<SlabPeaks> slabs;        ///< colliding floors only
  std::vector<SiteContacts> contacts;  ///< per site (row.sites[s].impacts is the raw count)
  double dt_s = 0.0;                   ///< (fine) step used [s]
  double coarse_dt_s = 0.0;            ///< coarse step [s] (= dt_s for fixed stepping)
  SearsStepCounts counts;
};

/// Fine and coarse steps: coarse = ratio x fine. Fixed stepping: the step rule's step
/// (sears/step_rule.hpp: automatic, or the model's dt, checked), ratio 1. Event stepping: the
/// coarse step is the largest step <= min(record spacing, kCoarseStepPerBuildingPeriod x the
/// shortest building period) that divides the record spacing; the automatic fine step is the
/// largest step <= the fixed path's that divides the coarse one (a given dt is kept, and the ratio
/// rounded down). When that coarse step is not longer than the fine one (few modes, soft contacts),
/// ratio = 1: every step is of the fixed path's size.
struct SearsSteps {
  double fine_s = 0.0;
  double coarse_s = 0.0;
  long ratio = 1;
  /// Event stepping: the longest step through contacts, in fine steps: at most `ratio` and the
  /// step rule's largest allowed step (sears/step_rule.hpp); 1 without longer steps [-].
  long longest = 1;
  /// Event stepping: coarse steps per step of the lumped solver, whose exact and adaptive steps
  /// carry the floors through stretches without contact (issue 30; docs/speed.md): its grid is
  /// h_L = record spacing / ceil(record spacing / min(record spacing, T_min,b / 20)) (the lumped
  /// solver's, row_run.cpp), and the coarse step divides it; 0: none (fixed stepping) [-].
  long lumped = 0;
  double lumped_s() const { return static_cast<double>(lumped) * coarse_s; }  ///< h_L [s]
};
/// `record_dt` the ground's sample spacing [s] (0: no ground motion).
SearsSteps sears_row_steps(const BuildingRow& row, double record_dt, const SearsRowModel& model);

/// One run. Throws InputError (bad model, too large dt) or NumericalError (non-finite state).
SearsRowResult solve_sears_row(const SearsRowProblem& p, const SearsRowModel& model);

struct SearsRowSimulation {
  RowSimulation base;                  ///< as simulate_row() returns for the lumped models
  std::vector<SlabPeaks> slabs;        ///< peak face and slab-centre accelerations (pounding run)
  std::vector<SiteContacts> contacts;  ///< per site: phases and thresholded impact count
  double dt_s = 0.0;                   ///< (fine) step [s]
  double coarse_dt_s = 0.0;            ///< coarse step [s]
  SearsStepCounts counts_free, counts_pounding;
};

/// With and without pounding, and the response measures of physics.md section 4, on `ground`
/// (one motion per building). The run without pounding is the lumped solver's free run
/// (solver/row_solver.hpp, with `integrator`): without contacts the floors' physics is the
/// same, so its numbers are those of every lumped contact model (issue 30).
SearsRowSimulation simulate_sears_row(const BuildingRow& row, const RowGround& ground,
                                      const SearsRowModel& model,
                                      const RowSimulationOptions& opt = {},
                                      const IntegratorSettings& integrator = {});
/// The same with one motion under every building.
SearsRowSimulation simulate_sears_row(const BuildingRow& row, const GroundMotion& motion,
                                      const SearsRowModel& model,
                                      const RowSimulationOptions& opt = {},
                                      const IntegratorSettings& integrator = {});

}  // namespace pound::sears

#pragma once
// One run of a damped Sears row, solve_sears_row() (sears_simulation.hpp; docs/sears.md
// "Buildings in a row", docs/speed.md), shared by sears_row_run.cpp (set-up, the run's loop,
// coarse steps, recording, the end), sears_contact_step.cpp (steps through contacts: the
// contact forces, longer steps, sleeping slabs, yielding storeys) and sears_located.cpp (the
// stretches without contact where the translation bound is not proved). Members are named after the
// symbols of the equations (u, v, F, S, H, ...). Internal to src/sears.
#include <Eigen/Dense>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

#include "sears/newmark_row.hpp"
#include "sears/newmark_storeys.hpp"
#include "sears/sears_row_layout.hpp"
#include "sears/sears_simulation.hpp"
#include "sears/slab_set.hpp"
#include "sears/translation_bound.hpp"
#include "solver/row_solver.hpp"
#include "solver/run_recorder.hpp"

namespace pound::sears::detail {

// Longer steps through smooth contact forces (docs/speed.md): the next step's length is
// kStepSafety times the one the error estimate allows; kNoLongStep marks a step that must be
// a fine one (SearsRowRun::step_error).
inline constexpr double kStepSafety = 0.9;
inline constexpr double kNoLongStep = std::numeric_limits<double>::infinity();

// The operators of one loaded step of h = m fine steps (m = 1 .. SearsSteps::longest): with the
// contact forces P = -sum_s F_s (e_L - e_R), a_{i+1} = a_hat - H F, H = Mt^-1 [e_L - e_R],
// u_{i+1} = u_hat - h^2/4 H F, the overlaps' compliance S, and for yielding storeys R = Mt^-1 B.
struct StepOperators {
  double h;
  NewmarkOperator nm;
  Eigen::MatrixXd H, S, R;
};

class SearsRowRun {
 public:
  SearsRowRun(const SearsRowProblem& p, const SearsRowModel& model);
  SearsRowResult run();

 private:
  void build_operators();
  void initial_state();
  Eigen::VectorXd solve_mass(const Eigen::VectorXd& x) const;
  void loads(const Eigen::VectorXd& f, std::vector<EndLoads>& to) const;
  // Each ground channel's acceleration at t [m/s^2] (FloorGround::channel_acc).
  const double* ag_at(double t) { return ground.channel_acc(t); }
  // Each site's relative ground displacement and velocity at t into d, w [m], [m/s].
  void ground_at(double t, std::vector<double>& d, std::vector<double>& w) {
    ground.relative_all(t, d.data(), w.data());
  }
  // The slabs of site s (index into layout.floors), -1 for a struck column point (issue 36).
  int left_slab(int s) const { return layout.site_left_floor[s]; }
  int right_slab(int s) const { return layout.site_right_floor[s]; }
  // Site s's sides as points of the floors (ContactSite::left, ::right; a slab: its floor).
  const SitePoint& left_point(int s) const { return assembled.sites[s].left; }
  const SitePoint& right_point(int s) const { return assembled.sites[s].right; }
  // The per-site accessors below take `slabs_only`: slab_only, or a constant true/false where
  // a loop was chosen once per run from it (the run's slab-only paths: with every side a slab
  // (slab()), each side is its floor's DOF, 1 x u being u, so the same bits).
  static bool slab(bool slabs_only, int k) { return slabs_only || k >= 0; }  // k a slab index
  // Overlap at the start of the step at site s (its slabs awake).
  double overlap_now(int s, bool slabs_only) const;
  double overlap_now(int s) const { return overlap_now(s, slab_only); }
  // Approach u_L - u_R of the faces of site s (floors plus internal vibration); with a dormant
  // slab, its upper bound.
  double approach_bound(int s, bool slabs_only) const;
  double approach_bound(int s) const { return approach_bound(s, slab_only); }
  double overlap_bound(int s, bool slabs_only) const {
    return approach_bound(s, slabs_only) - gap(s);
  }
  // Site s's gap [m], widened by its faces' permanent indentation (crushing, issue 36).
  double gap(int s) const { return gap_[s]; }
  bool site_dormant(int s, bool slabs_only) const {
    const int l = left_slab(s), r = right_slab(s);
    return (slab(slabs_only, l) && slabs.dormant(l)) || (slab(slabs_only, r) && slabs.dormant(r));
  }
  bool site_dormant(int s) const { return site_dormant(s, slab_only); }
  // Whether a slab of site s sleeps (a guarded site), and whether every slab of it does.
  bool site_asleep(int s, bool slabs_only) const {
    const int l = left_slab(s), r = right_slab(s);
    return (slab(slabs_only, l) && slabs.asleep(l)) || (slab(slabs_only, r) && slabs.asleep(r));
  }
  bool site_all_asleep(int s, bool slabs_only) const {
    const int l = left_slab(s), r = right_slab(s);
    return (!slab(slabs_only, l) || slabs.asleep(l)) && (!slab(slabs_only, r) || slabs.asleep(r));
  }
  void wake_site(int s);  // the slabs of site s awake, delta(s) exact
  // Sleeping slabs (runs of fine steps).
  void update_guards();
  void fall_asleep();
  void finish_sleep();
  void predict_overlaps();
  bool guards_hold();
  template <bool Slabs>
  void predict_overlaps_of();  // Slabs = slab_only, chosen once per run
  template <bool Slabs>
  bool guards_hold_of();
  // Steps through contacts (sears_contact_step.cpp).
  long fine_step(long i);
  long trial_multiple(long i, const Eigen::VectorXd& f) const;
  long room(long i, const Eigen::VectorXd& f) const;
  double step_error(long m);
  template <bool Slabs>
  double step_error_of(long m, double tol);  // Slabs = slab_only
  void storey_pass(double h, const Eigen::MatrixXd& R, bool contacts);
  void step_slabs(long i, long m);
  // Coarse steps (no contact), and stretches on the lumped solver's steps (issue 30).
  void coarse_step(double t_next);
  bool contact_free(double h);
  template <bool Slabs>
  bool contact_free_of(double h);  // contact_free's tests, Slabs = slab_only
  void start_stretch(long i);      // the lumped solver resumes from the floors at point i
  long lumped_stretch(long i);
  void leave_stretch();
  // Stretches on the located approach where the translation bound is not proved (a massless
  // base with tangent damping or P-Delta; sears_located.cpp).
  bool located_open();
  bool located_clear(double h, double t_next);
  long located_stretch(long i);
  void save_recorder();
  void restore_recorder();
  // Results after a step.
  void add_energy(double h, double t_start, double t_next);  // the step [t_start, t_next]
  void record_sites(bool coarse, double h, double t_next);
  void crush_faces();  // after record_sites: the indentations grown in the step
  template <bool Slabs>
  void record_site(int s, bool coarse, double h, double t_next);  // Slabs = slab_only
  void record_peaks(bool coarse, const double* ag, double t_next, double h);
  // Collapse (solver/row_solver.hpp): failed storeys under P-Delta; after collapses, true when
  // the run stops (contacts: the first; without: all buildings held).
  void check_failures(double t);
  bool on_collapse();
  void hold_still(Eigen::VectorXd& a) const {  // held floors: no acceleration
    for (int i : held_dofs) a(i) = 0.0;
  }
  EnergyBalance energy_now() const;
  void record_slab(int k, bool coarse, const double* ag);
  void finish();

  // The layout with its modal banks for these steps.
  static RowContactLayout layout_for(const BuildingRow& row, const AssembledRow& a,
                                     const SearsRowModel& model, const SearsSteps& stepping);

  const SearsRowProblem& p;
  const SearsRowModel& model;
  const BuildingRow& row;
  const AssembledRow assembled;
  // The ground under the floors and sites (issue 28), and each site's relative ground
  // displacement ug_L - ug_R and velocity at current_t (gd, gv) and at the end of the step being
  // solved (gd_next, gv_next) [m], [m/s]: the contacts act on absolute displacements.
  FloorGround ground;
  std::vector<double> gd, gv, gd_next, gv_next;
  const SearsSteps stepping;
  const double dt, hc;  // fine and coarse step [s]
  const long steps;     // fine steps in the run
  long per_sample = 0;  // fine steps per record sample (0: the record spacing is not a multiple)
  const bool event;
  RowContactLayout layout;
  const int n, ns, nf;  // floor DOFs, contact sites, colliding floors

  // ops[m - 1]: steps of m fine steps through contacts; the modal banks' recurrence m - 1.
  std::vector<StepOperators> ops;
  const NewmarkOperator nm_coarse;  // coarse steps carry no contact force (event stepping)
  long longest = 1;                 // ops.size(): the longest step through contacts [fine steps]
  int op = 0;                       // ops[op]: the step being solved
  TranslationBound bound;
  // Stretches without contact on the lumped solver's exact and adaptive steps of h_L
  // (SearsSteps::lumped): its problem (no contact laws) and stepper; null without.
  RowProblem lumped_problem;
  IntegratorSettings lumped_settings;  // (FreeStretches keeps references to both)
  std::unique_ptr<FreeStretches> lumped;
  std::vector<double> lumped_bound;         // ModalBank::face_motion_bound(h_L) per slab [m]
  bool lumped_bound_valid = false;          // lumped_bound holds since the last fine step
  std::vector<StoreyState> lumped_storeys;  // the storeys' states a stretch ended in
  // Located stretches (sears_located.cpp): whether the row takes them (no valid translation
  // bound), the fine step before which none starts again (one was re-taken there), the
  // recorder as it was at the lumped step's start (a step found too near a contact is re-taken
  // by fine steps) with the length of its histories, and the step's end state [m], [m/s],
  // [m/s^2].
  bool located = false;
  long located_retry = 0;
  std::optional<RunRecorder> rec_start;
  std::size_t rec_history = 0;
  Eigen::VectorXd lu, lv, la;

  // Yielding storeys (sears/newmark_storeys.hpp): a_i+1 = a_hat + R r_i+1 - H F, R = Mt^-1 B
  // for each step size; r iterated with the storeys' return maps.
  NewmarkStoreys storeys;
  Eigen::MatrixXd R_coarse;
  Eigen::VectorXd r_next, a_base, u_end, v_end;
  // Energy balance (p.track_energy): the work terms of each step, trapezoidal in the step's
  // end values, which Newmark's average-acceleration scheme balances exactly for linear storeys.
  Eigen::VectorXd u_prev, v_prev;
  double e_input = 0.0, e_damping = 0.0, e_contact = 0.0;
  // Crushing faces at [sears] force_cap (issue 36; SlabContactLaw::crush_increment): each
  // site's permanent indentation c [m], which widens its gap (gap()), and its value when the
  // site's current contact phase began (the recorded penetration includes the phase's own
  // crush, as the lumped laws' does); the crushing work, the sum of PF_max x c [J].
  std::vector<double> crush, crush_phase;
  std::vector<double> gap_;  // gap(): each site's ContactSite::gap + crush, kept with crush [m]
  double e_crushing = 0.0;
  // Every site a slab site (structure/building_row.hpp slab_site) between floors of unit ground
  // influence: the per-step overlaps and bounds by the floors' DOFs, as before issue 36 (the
  // same operations: 1 x u is u); whether a site has a force cap (else no crush_faces); plain:
  // neither column sites nor caps (one test a step for both).
  bool slab_only = false, any_cap = false, plain = false;
  std::vector<double> ag_avg_, mdu_;  // per channel: mean ag [m/s^2], sum M du [kg m]

  // Floor state [m], [m/s], [m/s^2]; contact forces [N] and overlaps [m] per site.
  NewmarkFloors floors;
  Eigen::VectorXd &u, &v, &acc;
  Eigen::VectorXd F, F_next, delta_pred, delta, u_hat, a_next;
  SearsRowResult out;
  RunRecorder rec;
  SlabSet slabs;
  std::vector<bool> in_contact;
  std::vector<EndLoads> begin, end;
  // Longer steps through smooth contact forces (docs/speed.md): the forces at the start of the
  // previous step [N] and its length [s] (0: none since the start), the next step's multiple.
  Eigen::VectorXd F_prev;
  double h_prev = 0.0;
  long m_next = 1;
  std::vector<double> modal_bound;
  std::vector<double> site_approach;  // TranslationBound::approach per site, contact_free() [m]
  // Runs without contacts: each site's face approach and its rate at the last step's end, for
  // the peak approach between steps (SiteResult::peak_approach) [m], [m/s].
  std::vector<double> free_approach, free_approach_rate;
  bool modal_bound_valid = false;  // modal_bound holds since the last fine step
  // Sites with a sleeping slab ("guarded") keep F = 0 as long as the upper bound of their
  // end-of-step overlap stays negative (guards_hold); otherwise their sleeping slabs wake and the
  // step's forces are solved again with the site included.
  std::vector<char> guarded;
  long coarse_in_run = 0;  // coarse steps since the last fine step
  // Collapse: a storey that can fail under P-Delta (kg > 0, a law other than elastic); the
  // floors held still (a run without contacts after its buildings collapsed); the energy balance
  // at its first collapse.
  bool failure_check = false;
  double current_t = 0.0;  // the time reached [s]
  std::vector<int> held_dofs;
};

// The faces: a slab's floor plus its internal displacement at the face (Th. 8.3); a struck
// column point (no bar, issue 36) moves with its floors only.
inline double SearsRowRun::overlap_now(int s, bool slabs_only) const {
  const int l = left_slab(s), r = right_slab(s);
  if (slabs_only) {
    const ContactSite& site = assembled.sites[s];
    return u(site.dof_left) - u(site.dof_right) + slabs.disp(l).right - slabs.disp(r).left -
           gap(s) + gd[s];
  }
  return left_point(s).of(u.data()) - right_point(s).of(u.data()) +
         (l >= 0 ? slabs.disp(l).right : 0.0) - (r >= 0 ? slabs.disp(r).left : 0.0) - gap(s) +
         gd[s];
}

inline double SearsRowRun::approach_bound(int s, bool slabs_only) const {
  const int l = left_slab(s), r = right_slab(s);
  if (slabs_only) {
    const ContactSite& site = assembled.sites[s];
    return u(site.dof_left) - u(site.dof_right) + slabs.right_face_upper(l) -
           slabs.left_face_lower(r) + gd[s];
  }
  return left_point(s).of(u.data()) - right_point(s).of(u.data()) +
         (l >= 0 ? slabs.right_face_upper(l) : 0.0) - (r >= 0 ? slabs.left_face_lower(r) : 0.0) +
         gd[s];
}

}  // namespace pound::sears::detail

#pragma once
// The adaptive integration of one run of a building row (solver/row_solver.hpp), shared by
// row_run.cpp (start, steps, exact steps, recording, the end) and row_events.cpp (locating and
// applying switching events). Internal to src/solver.
#include <Eigen/Dense>
#include <limits>
#include <memory>
#include <vector>

#include "solver/ark_imex.hpp"
#include "solver/dopri5.hpp"
#include "solver/exact_steps.hpp"
#include "solver/hermite.hpp"
#include "solver/row_dynamics.hpp"
#include "solver/row_solver.hpp"
#include "solver/row_switches.hpp"
#include "solver/run_recorder.hpp"
#include "solver/step_watch.hpp"

namespace pound::detail {

// The adaptive integration of one run (row_solver.hpp): Dormand-Prince steps between switching
// events, each event located on re-taken steps, exact steps of the linear system between events
// where the row allows them. The equations are RowDynamics', the events RowSwitches', the exact
// steps' grid and propagators ExactSteps', and what the run reports RunRecorder's.
class RowRun {
 public:
  RowRun(const RowProblem& p, const IntegratorSettings& s);
  // The pounding run forked from a free run (solve_free_and_pounding): the free solver's state
  // at the top of the loop iteration whose step it was accepting, with the contacts of
  // `pounding` (the same problem with its laws) switched on.
  RowRun(const RowRun& free, const RowProblem& pounding);
  RowResult run();      // from the initial state
  RowResult advance();  // from the current state to the end
  // Steps from the current state to t_end [s] (no finish()); true when a collapse stopped the
  // run (a run with contacts, or every building held).
  bool advance_until(double t_end, bool one_step = false);
  // The row scheduler (RowStepper, row_stepper.hpp): the initial state (as run() starts), one
  // accepted step at a time (advance_until's loop until the time moves; events applied at the
  // step's end are part of it; true when a collapse stopped the run), and the result at the end.
  void begin() { start(); }
  bool advance_step(double t_end) { return advance_until(t_end, true); }
  RowResult end() {
    finish();
    return rec_.result();
  }
  // Continues from a given state at time t [s] (FreeStretches, row_solver.hpp): floor
  // displacements u [m] and velocities v [m/s], each storey's discrete state (and its
  // continuous states in StoreyState::x), the energy balance so far (input, damping, contact
  // [J]). The first call also prepares the run (work arrays, step limits).
  void resume(double t, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
              const std::vector<StoreyState>& storeys, const double* energies);
  double time() const { return t_; }
  const Eigen::VectorXd& state() const { return y_; }        // y (row_dynamics.hpp)
  const Eigen::VectorXd& derivative() const { return k1_; }  // dy at (time(), state())
  const RowDynamics& dynamics() const { return dyn_; }
  // Each storey's discrete state with its continuous states (from y) in x, into `out`.
  void storey_states(std::vector<StoreyState>& out) const;
  RunRecorder& recorder() { return rec_; }
  // A free run to fork into `pounding` at the start of the first step in which a site comes
  // within kForkMargin of touching (before run()).
  void fork_into(const RowProblem* pounding) { fork_to_ = pounding; }
  const std::shared_ptr<RowRun>& fork() const { return fork_; }
  // Whether the fork was armed (every site open by more than kForkMargin at the start).
  bool fork_armed() const { return fork_armed_; }
  // A free run that collapsed before its pounding run forked: the pounding run (which stops at
  // the first collapse) must be solved on its own.
  bool needs_own_pounding_run() const { return own_pounding_run_; }
  static constexpr double fork_margin() { return kForkMargin; }  // [m]
  // Dense output of chosen points and storey shears (solve_apart, row_apart.hpp), filled from
  // the next step on; null: none.
  void watch(StepWatch* w) { watch_ = w; }

 private:
  enum class Located { none, retry, applied };
  // A switch's value fa at the step fraction a and fb at b: the crossing lies in (a, b].
  struct Bracket {
    double a, fa, b, fb;
  };

  // The derivative dy at a new state y (and a massless base's velocities into y: project()).
  void rhs(double t, Eigen::VectorXd& y, Eigen::VectorXd& dy) {
    dyn_.rhs(t, y, dy);
    dyn_.project(y, dy);
  }
  void step(double t, double h, const Eigen::VectorXd& y, const Eigen::VectorXd& k1,
            Eigen::VectorXd& y1, Eigen::VectorXd& err, Eigen::VectorXd& k7) {
    auto f = [this](double tt, const Eigen::VectorXd& yy, Eigen::VectorXd& dy) {
      dyn_.rhs(tt, yy, dy);
    };
    if (implicit_.empty()) {
      dopri5_step(f, t, h, y, k1, y1, err, work_);
      k7 = work_.k7;
    } else {  // stiff base dashpots (issue 38): IMEX, the derivative at the end not a stage
      ark_imex_step(f, t, h, y, k1, y1, err, implicit_, ark_work_);
      dyn_.rhs(t + h, y1, k7);
    }
    dyn_.project(y1, k7);
  }
  double error_norm(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                    const Eigen::VectorXd& err) const;
  double error_norm_on_soil(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                            const Eigen::VectorXd& err) const;
  void set_base_errors();
  int find_event(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, const Eigen::VectorXd& dy0,
                 const Eigen::VectorXd& dy1, double h, double& theta,
                 const std::vector<char>* ignore = nullptr) const {
    return switches_.find_event(dyn_, y0, y1, dy0, dy1, h, theta, ignore);
  }
  SwitchValue switch_at(int k, const Eigen::VectorXd& y, const Eigen::VectorXd& dy) const {
    return switches_.value(dyn_, k, y, dy);
  }

  // Event location (Illinois iteration on re-taken steps).
  Located locate(int ev, double theta, double hs, double en, bool trial_failed);
  bool bracket_event(int ev, double theta, double hs, Bracket& br);
  double refine_event(int ev, double guess, Bracket br);
  void apply_event(int k, double t, Eigen::VectorXd& y);
  void apply_contact_event(int i, double t, Eigen::VectorXd& y);
  void storey_changed(int dof);
  void retry(double hn);
  void reject(double hf, double enf);

  void start();
  void set_step_limits();
  bool exact_step();
  void exact_rates(double t1);
  bool contacts_open() const;
  double next_stop(double t_end);
  void accept(double hs, double en, double t_stop);
  bool separated() const;
  // After collapses: a run with contacts stops (true); a run without holds each collapsed
  // building still and keeps its energy balance of the first collapse; true when all collapsed.
  bool on_collapse();
  EnergyBalance energy_now() const;
  void finish();
  void update_peaks(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                    const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double h);
  void fork_if_near_contact(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, double h);
  void record(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& dy);
  void check_finite(double t, const Eigen::VectorXd& y) const {
    RunRecorder::check_finite(y, t, "row solver");
  }

  const RowProblem* p_;
  const IntegratorSettings& s_;
  const AssembledRow& row_;
  const int n_, ns_;
  // The row's storeys, or elastic ones for a hand-built row: shared by a solver and its fork
  // (never changed), so that the components of either refer to a live vector.
  std::shared_ptr<const std::vector<RowStorey>> storeys_owner_;
  const std::vector<RowStorey>& storeys_;
  const bool track_, fixed_;
  RowDynamics dyn_;
  RowSwitches switches_;
  ExactSteps exact_;
  RunRecorder rec_;
  Dopri5Work work_;
  // The entries integrated implicitly (the stiff dashpots of massive bases on their own
  // velocities; empty: Dormand-Prince), chosen once per run (set_step_limits).
  ImplicitSet implicit_;
  ArkImexWork ark_work_;
  // The base DOFs' entries of the error test (IntegratorSettings::base_error_by_floors; empty:
  // every tested entry against its own scale, as on fixed bases), chosen once per run
  // (set_base_errors): base DOF d of the building whose floors are [first, end); its error's
  // lever on the floors wu [-] (1 on a sway, the building's height H [m] on a rotation [rad]),
  // its velocity's wv = wu tau [s] (tau the DOF's own relaxation time 1 / max(C_dd / M_d,
  // sqrt(K_dd / M_d)), 0 where the velocity is not a state of its own: massless or condensed).
  struct BaseEntry {
    int d, first, end;
    double wu, wv;
  };
  std::vector<BaseEntry> base_entries_;
  // The largest Dormand-Prince step [s] the bases' dashpots allow (infinity: no bound but h_max).
  double h_explicit_ = std::numeric_limits<double>::infinity();

  // The fork of a free run (solve_free_and_pounding). Until a site comes within kForkMargin of
  // touching, the pounding run's steps are the free run's (no contact is active, no contact
  // switch can fire, and every site is open by more than contacts_open()'s 1 nm), so the
  // pounding run starts from the free run's state there. The margin is ten times the cubic
  // interpolant's error over a step of T_min / 20 (about 1e-7 m, docs/integration.md), so that
  // the pounding run's own interpolants do not see a crossing before it either.
  static constexpr double kForkMargin = 1e-6;  // [m]
  const RowProblem* fork_to_ = nullptr;
  bool fork_armed_ = false;
  std::shared_ptr<RowRun> fork_;
  bool own_pounding_run_ = false;
  StepWatch* watch_ = nullptr;

  // Integration state: time, next step and largest step [s], record spacing [s], the fixed
  // grid's and the record's last points passed, the state y and its derivative k1, the trial
  // step's end y1 (derivative k7, error err) and the re-taken steps' (ytry, ktry, etry).
  double t_ = 0.0, h_ = 0.0, h_max_ = 0.0, rec_dt_ = 0.0;
  long grid_ = 0, next_sample_ = 1;
  bool any_contact_ = false;
  bool resumed_ = false;                   // resume() prepared the run
  std::vector<double> step_a0_, step_a1_;  // each channel's ag at an exact step's ends [m/s^2]
  Eigen::VectorXd y_, y1_, err_, k1_, k7_, ytry_, etry_, ktry_;
  // Per switch id: a crushing switch whose crossing in the current step was a false alarm
  // (advance_until; all 0 between steps).
  std::vector<char> false_alarm_;
};

}  // namespace pound::detail

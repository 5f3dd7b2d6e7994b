#pragma once
// What a run of a building row reports, recorded the same way by both solvers (the adaptive
// lumped-mass solver, solver/row_solver.cpp, and the damped Sears solver,
// sears/sears_row_run.cpp): the peak floor values (physics.md section 4), the free run's
// approach at every contact site, the contact phases (impacts, first contact, last separation,
// peak force and penetration, impulse), the time histories and the end state. A solver calls it
// after its steps with the values it has; a new reported quantity is written here once.
// Kernel only: no files, no printing.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "solver/hermite.hpp"
#include "solver/row_result.hpp"
#include "structure/building_row.hpp"

namespace pound {

class RunRecorder {
 public:
  /// For the floors and sites of `row`, whose storeys stand on the floors `storeys[i].below`;
  /// `contacts`: a run with contact laws (otherwise the free run, whose approach at each site is
  /// recorded); `history`: keep time histories.
  RunRecorder(const AssembledRow& row, const std::vector<RowStorey>& storeys, bool contacts,
              bool history);

  /// Collapse (issue 23): a building whose storey drift passes ratio h (h = StoreyParameters::h
  /// of each storey) has collapsed; infinite ratio: no check. Call before start().
  void set_collapse(const std::vector<RowStorey>& storeys, double ratio);
  /// Zero peaks and sites; the free run's approach starts at the initial u_L - u_R [m].
  void start(const Eigen::VectorXd& u0);
  /// A free run forked into a run with contacts (solve_free_and_pounding): its sites start
  /// afresh, and the steps so far are the free run's.
  void contacts_on() {
    contacts_ = true;
    std::vector<SiteResult> fresh(static_cast<std::size_t>(ns_));
    for (int s = 0; s < ns_; ++s)  // the columns' shear so far is the pounding run's too
      fresh[s].peak_column_shear = r_.sites[s].peak_column_shear;
    r_.sites = fresh;
    r_.steps_from_free = r_.steps;
  }
  RowResult& result() { return r_; }
  const RowResult& result() const { return r_; }
  /// The lumped fork at a common time (RowStepper, row_stepper.hpp): a run with contacts of the
  /// whole row, resumed where its buildings' free runs stand, takes their peaks so far (each
  /// DOF k of `other`'s row is DOF dof_map[k] here) and their step counts (as the pounding
  /// run's steps shared with the free run). Call after start(u) at the resumed state.
  void merge_from(const RunRecorder& other, const std::vector<int>& dof_map);

  // --- Floors ------------------------------------------------------------------------------
  /// Peak absolute accelerations from the relative ones a_rel [m/s^2] and the ground's ag under
  /// each floor (held buildings excepted).
  void accel_peaks(const double* a_rel, const double* ag) {
    for (int i = 0; i < n_; ++i) {
      if (any_held_ && held_[i]) continue;
      const double a = a_rel[i] + ag[i];
      r_.peak_abs_accel(i) = std::max(r_.peak_abs_accel(i), std::fabs(a));
    }
  }
  /// Peak displacements and storey drifts [m] and absolute accelerations (from the relative
  /// ones a_rel and the ground's ag under each floor [m/s^2]) sampled at the end t [s] of a step
  /// of h [s]; a storey past its collapse drift collapses its building at the time its drift,
  /// linear over the step, passed it.
  void sampled_peaks(const Eigen::VectorXd& u, const double* a_rel, const double* ag, double t,
                     double h) {
    for (int k = 0; k < n_; ++k) {
      if (any_held_ && held_[k]) continue;
      const int b = below_[k];
      double d = b >= 0 ? u(k) - u(b) : u(k);
      if (rot_[k] >= 0) d -= rot_h_[k] * u(rot_[k]);  // on a flexible foundation
      const double a = a_rel[k] + ag[k];
      r_.peak_disp(k) = std::max(r_.peak_disp(k), std::fabs(u(k)));
      r_.peak_drift(k) = std::max(r_.peak_drift(k), std::fabs(d));
      r_.peak_abs_accel(k) = std::max(r_.peak_abs_accel(k), std::fabs(a));
      if (check_collapse_) {
        if (std::fabs(d) > collapse_drift_[k]) sampled_collapse(k, d, t, h);
        last_drift_[k] = d;
      }
    }
  }
  /// Peak displacements and storey drifts over the step from t0 of length h [s] from the
  /// quintic Hermite interpolant of y = [u; v] and dy = [v; u''] at both ends (sixth-order
  /// accurate); a storey past its collapse drift collapses its building where the interpolant
  /// passes it.
  void peaks_over_step(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                       const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double t0, double h);

  // --- Collapse ------------------------------------------------------------------------------
  /// Building b collapsed at storey (1-based) at time t [s], unless it had before.
  void collapse(int b, int storey, double t, CollapseCause cause);
  /// Collapses recorded since the last call (and forgets them).
  int take_new_collapses() {
    const int n = new_collapses_;
    new_collapses_ = 0;
    return n;
  }
  bool collapsed(int b) const { return !r_.collapse.empty() && r_.collapse[b].collapsed; }
  int buildings() const { return nb_; }
  /// From now on every collapsed building's DOFs hold still (a free run's collapsed buildings):
  /// no peak changes there. Returns the DOFs held by this call; `all` tells whether every
  /// building has collapsed.
  std::vector<int> hold_collapsed(bool& all);
  bool held(int dof) const { return any_held_ && held_[dof]; }
  /// The collapse policy of both solvers (issue 23), at new collapses: a run with contacts
  /// stops (the pounding run ends at its first collapse); a run without keeps its energy
  /// balance as it was at its first collapse (`energy_now()` is called then, when the run tracks
  /// energy) and holds every collapsed building's floors still from now on, stopping when all
  /// have collapsed. Returns whether the run stops here (result().stopped); `hold` gets the
  /// floor DOFs to hold from now on, whose velocities (and accelerations) the caller zeroes.
  template <class EnergyNow>
  bool apply_collapse_policy(bool track_energy, EnergyNow energy_now, std::vector<int>& hold) {
    hold.clear();
    if (contacts_) return r_.stopped = true;
    if (track_energy && !energy_held_) {
      held_energy_ = energy_now();
      energy_held_ = true;
    }
    bool all = false;
    hold = hold_collapsed(all);
    if (all) r_.stopped = true;
    return all;
  }
  /// The energy balance to report: `now`, or the one held at a free run's first collapse.
  const EnergyBalance& final_energy(const EnergyBalance& now) const {
    return energy_held_ ? held_energy_ : now;
  }
  /// A storey that failed (StoreyLaw::failed, in its discrete state `s`) under its P-Delta load
  /// collapses its building at time t [s] (when the run checks collapse).
  void check_failed_storey(int dof, const RowStorey& st, const StoreyState& s, double t) {
    if (check_collapse_ && st.kg > 0.0 && !collapsed(building_[dof]) && st.law->failed(st.p, s))
      collapse(building_[dof], storey_no_[dof], t, CollapseCause::failed_storey);
  }

  // --- Contact sites -------------------------------------------------------------------------
  /// A contact phase starts at site s at time t [s].
  void contact_started(int s, double t) {
    SiteResult& sr = r_.sites[s];
    if (sr.first_contact < 0.0) sr.first_contact = t;
    ++sr.impacts;
  }
  /// The faces part at site s at time t [s].
  void contact_ended(int s, double t) { r_.sites[s].last_separation = t; }
  /// The contact force f [N] and penetration d [m] of site s, for their peaks.
  void force(int s, double f) { r_.sites[s].peak_force = std::max(r_.sites[s].peak_force, f); }
  void penetration(int s, double d) {
    r_.sites[s].peak_penetration = std::max(r_.sites[s].peak_penetration, d);
  }
  /// The shear demand v [N] on the struck columns of column site s at a step's end.
  void column_shear(int s, double v) {
    double& peak = r_.sites[s].peak_column_shear;
    if (!(peak >= v)) peak = v;  // NaN (no value yet) or lower
  }
  /// The impulse j [N s] transmitted at site s in a step.
  void impulse(int s, double j) { r_.sites[s].impulse += j; }
  /// Free run: the approach u_L - u_R of site s over a step, as the cubic the contact events are
  /// located on [m].
  void approach_over_step(int s, const Hermite& c) {
    double& peak = r_.sites[s].peak_approach;
    if (c.upper_bound() > peak) peak = std::max(peak, c.max_over_step());
  }

  // --- Histories -----------------------------------------------------------------------------
  bool keeps_history() const { return history_; }
  /// One entry: time t [s], displacements u [m], relative accelerations a_rel and the ground's
  /// ag under each floor [m/s^2], contact forces [N], storey shears [N].
  void history(double t, const Eigen::VectorXd& u, const Eigen::VectorXd& a_rel, const double* ag,
               const Eigen::VectorXd& force, const Eigen::VectorXd& shear);

  // --- The end -------------------------------------------------------------------------------
  /// The time reached [s] and the state there [m], [m/s].
  void finish(double t, const Eigen::VectorXd& u, const Eigen::VectorXd& v);

  /// Throws NumericalError naming `what` and the time t [s] when a value of x is not finite.
  static void check_finite(const Eigen::VectorXd& x, double t, const char* what) {
    if (!x.allFinite()) throw_non_finite(t, what);
  }

 private:
  [[noreturn]] static void throw_non_finite(double t, const char* what);
  // The drift of DOF k's storey at displacements u [m] (row.hpp storey_drift).
  double drift(const double* u, int k) const {
    double d = below_[k] >= 0 ? u[k] - u[below_[k]] : u[k];
    if (rot_[k] >= 0) d -= rot_h_[k] * u[rot_[k]];
    return d;
  }
  // peaks_over_step for a row with a flexible foundation (general_): the drift quintics with
  // the base's sway below the first storey and its rotation in every storey.
  void peaks_over_step_general(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                               const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double t0,
                               double h);
  // Collapse at the step end t of a step of h at storey k whose drift went from last_drift_[k]
  // to d (linear between).
  void sampled_collapse(int k, double d, double t, double h);
  // Collapse inside a step from t0 of h at storey k, d the quintic of its drift.
  void step_collapse(int k, const QuinticHermite& d, double t0, double h);
  // QuinticHermite::absmax_bound() of every floor's displacement (out[i]) and storey drift
  // (out[n + i]) over a step (run_recorder.cpp).
  static void peak_bounds(int n, const double* u0, const double* u1, const double* v0,
                          const double* v1, const double* a0, const double* a1, const double* below,
                          double h, double h2, double* out);

  int n_ = 0, ns_ = 0;
  int nf_ = 0;  // the floor DOFs, [0, nf_); the bases' sway and rotation after them
  bool contacts_ = false, history_ = false;
  std::vector<int> below_;      // per DOF: the floor DOF under its storey, -1 on the ground
  std::vector<double> weight_;  // per DOF: 1 where its storey stands on a floor, 0 on the ground
  std::vector<int> rot_;        // per DOF: its building's base rotation DOF, -1 (fixed base)
  std::vector<double> rot_h_;   // per DOF: its storey's height where rot_ >= 0 [m]
  bool general_ = false;        // a storey on a flexible foundation (issue 29)
  // Per DOF, the general path's drift as u_i + wb u_below + wr u_rot: the DOFs (the DOF itself
  // where there is none) and weights (0 there) [-, -m].
  std::vector<int> g_below_, g_rot_;
  std::vector<double> g_wb_, g_wr_;
  std::vector<double> bounds_;  // scratch of peaks_over_step (peak_bounds)
  std::vector<std::pair<SitePoint, SitePoint>> site_points_;  // per site: its two sides
  // Collapse: per DOF its storey's collapse drift [m] (infinite: none), building, storey number
  // within it, and the drift at the last sample [m]; the buildings held still.
  bool check_collapse_ = false;
  int nb_ = 0, new_collapses_ = 0;
  std::vector<double> collapse_drift_, last_drift_;
  std::vector<int> building_, storey_no_;
  bool any_held_ = false;
  std::vector<char> held_;
  bool energy_held_ = false;  // the energy balance at a free run's first collapse
  EnergyBalance held_energy_;
  RowResult r_;
};

// Defined here so that the solvers inline it into their steps.
inline void RunRecorder::peaks_over_step(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                                         const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1,
                                         double t0, double h) {
  // Displacement and drift extrema inside the step from the quintic Hermite interpolant of the
  // displacements, velocities and accelerations at both ends (sixth-order accurate: exact steps
  // of h_max = T_min / 20 leave the peaks within 1e-8 of the motion between them).
  if (general_) {
    peaks_over_step_general(y0, y1, dy0, dy1, t0, h);
    return;
  }
  const int n = n_;
  const double h2 = h * h;
  const double* bound = bounds_.data();
  peak_bounds(n, y0.data(), y1.data(), y0.data() + n, y1.data() + n, dy0.data() + n, dy1.data() + n,
              weight_.data(), h, h2, bounds_.data());
  for (int i = 0; i < n; ++i) {  // QuinticHermite::raise_peak, its bound from peak_bounds
    const bool disp = !(bound[i] <= r_.peak_disp(i)), drift = !(bound[n + i] <= r_.peak_drift(i));
    if (!disp && !drift) continue;
    const QuinticHermite c{y0(i),         y1(i),           h * y0(n + i),
                           h * y1(n + i), h2 * dy0(n + i), h2 * dy1(n + i)};
    if (disp) r_.peak_disp(i) = c.refine_peak(r_.peak_disp(i));
    const int b = below_[i];
    if (b < 0) {  // a first storey: its drift is the floor's displacement
      r_.peak_drift(i) = r_.peak_disp(i);
      if (check_collapse_ && r_.peak_drift(i) > collapse_drift_[i]) step_collapse(i, c, t0, h);
      continue;
    }
    if (!drift) continue;
    QuinticHermite d = c;
    d.g0 -= y0(b);
    d.g1 -= y1(b);
    d.m0 -= h * y0(n + b);
    d.m1 -= h * y1(n + b);
    d.c0 -= h2 * dy0(n + b);
    d.c1 -= h2 * dy1(n + b);
    r_.peak_drift(i) = d.refine_peak(r_.peak_drift(i));
    if (check_collapse_ && r_.peak_drift(i) > collapse_drift_[i]) step_collapse(i, d, t0, h);
  }
}

}  // namespace pound

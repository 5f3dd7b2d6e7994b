#include "solver/row_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "core/error.hpp"
#include "solver/dopri5.hpp"
#include "solver/hermite.hpp"
#include "solver/linear_step.hpp"
#include "solver/row_forces.hpp"

namespace pound {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// QuinticHermite::absmax_bound() of every floor's displacement (out[i]) and of every storey's
// drift (out[n + i]; below[i] = 1 where the storey joins floor i - 1, 0 where it stands on the
// ground, so that the drift of a first storey is its floor's displacement) over a step of
// length h from the values u, velocities v and accelerations a at both ends. One pass over the
// floors, compiled for AVX2 and the baseline (no fused multiply-add, so the same bits), instead
// of a bound and a branch per quintic (update_peaks refines only where a bound could raise a
// peak).
__attribute__((target_clones("avx2", "default"))) void peak_bounds(
    int n, const double* __restrict u0, const double* __restrict u1, const double* __restrict v0,
    const double* __restrict v1, const double* __restrict a0, const double* __restrict a1,
    const double* __restrict below, double h, double h2, double* __restrict out) {
  const auto bound = [](double g0, double g1, double m0, double m1, double c0, double c1) {
    return QuinticHermite::absmax_bound(g0, g1, m0, m1, c0, c1);
  };
  for (int i = 0; i < n; ++i)
    out[i] = bound(u0[i], u1[i], h * v0[i], h * v1[i], h2 * a0[i], h2 * a1[i]);
  if (n > 0) out[n] = out[0];  // floor 0 stands on the ground
  for (int i = 1; i < n; ++i) {
    const double w = below[i];
    out[n + i] = bound(u0[i] - w * u0[i - 1], u1[i] - w * u1[i - 1],
                       h * v0[i] - w * (h * v0[i - 1]), h * v1[i] - w * (h * v1[i - 1]),
                       h2 * a0[i] - w * (h2 * a0[i - 1]), h2 * a1[i] - w * (h2 * a1[i - 1]));
  }
}

// Switching events. A switch is a function of the state that changes the equations where it
// rises through zero: a contact starting (delta) or ending (-delta), and the kinks of a
// piecewise storey law (hysteresis/storey_law.hpp: yielding, unloading). Switches 0..ns-1 are
// the contact sites, then the storeys' switches.
//
// State vector y = [u (n); v (n); x (storey continuous states); J (impulse per site);
// E (energy balance: input, damping, contact, when tracked)]. The error test covers u, v, x.
// The floors' internal forces are RowForces' (solver/row_forces.hpp).
class Solver {
 public:
  Solver(const RowProblem& p, const IntegratorSettings& s);
  // The pounding run forked from a free run (solve_free_and_pounding): the free solver's state
  // at the top of the loop iteration whose step it was accepting, with the contacts of
  // `pounding` (the same problem with its laws) switched on.
  Solver(const Solver& free, const RowProblem& pounding);
  RowResult run();      // from the initial state
  RowResult advance();  // from the current state to the end
  // A free run to fork into `pounding` at the start of the first step in which a site comes
  // within kForkMargin of touching (before run()).
  void fork_into(const RowProblem* pounding) { fork_to_ = pounding; }
  const std::shared_ptr<Solver>& fork() const { return fork_; }
  // Whether the fork was armed (every site open by more than kForkMargin at the start).
  bool fork_armed() const { return fork_armed_; }

 private:
  enum class Located { none, retry, applied };
  struct StoreySwitch {
    int dof = 0;    // the storey below this floor DOF
    int local = 0;  // the law's switch index
  };

  // Right-hand side: u' = v, v' = -M^-1 (C v + f(u, x)) - 1 ag + M^-1 P, x' (storey laws),
  // J' = contact force per site, E' (energy rates). f = K u for linear storeys (physics.md
  // section 1); otherwise f_j = V_j - V_{j+1} with the storey shears V of the laws.
  void rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy);
  void storey_changed(int dof);
  void energy_rates(const Eigen::VectorXd& y, double ag, double* dE) const;
  // Contact force per site [N] into force_ (zero where no contact is active).
  void contact_forces(const Eigen::VectorXd& y) {
    for (int i = 0; i < ns_; ++i) {
      double f = 0.0;
      if (active_[i]) {
        const double d = gap_function(y, i);
        f = p_->laws[i]->force(d, gap_rate(y, i), v0_[i]);
      }
      force_(i) = f;
    }
  }

  double gap_function(const Eigen::VectorXd& y, int i) const {
    const auto& s = row_.sites[i];
    return y(s.dof_left) - y(s.dof_right) - s.gap;  // physics.md section 1: delta_j
  }
  double gap_rate(const Eigen::VectorXd& y, int i) const {
    const auto& s = row_.sites[i];
    return y(n_ + s.dof_left) - y(n_ + s.dof_right);
  }
  double drift(const Eigen::VectorXd& v, int off, int dof) const {
    const int b = storeys_[dof].below;
    return v(off + dof) - (b >= 0 ? v(off + b) : 0.0);
  }
  const double* x_of(const Eigen::VectorXd& y, int dof) const {
    return xoff_[dof] >= 0 ? y.data() + xoff_[dof] : nullptr;
  }
  double storey_shear(const Eigen::VectorXd& y, int dof) const {
    const RowStorey& st = storeys_[dof];
    return st.law->shear(st.p, storey_[dof], drift(y, 0, dof), x_of(y, dof));
  }

  // Switch k at state y with derivative dy (signed: it happens where the value rises through 0).
  SwitchValue switch_at(int k, const Eigen::VectorXd& y, const Eigen::VectorXd& dy) const {
    if (k < ns_) {
      const double sign = active_[k] ? -1.0 : 1.0;
      return {sign * gap_function(y, k), sign * gap_rate(y, k)};
    }
    return storey_switch_at(k, y, dy);
  }
  SwitchValue storey_switch_at(int k, const Eigen::VectorXd& y, const Eigen::VectorXd& dy) const;
  Hermite switch_hermite(int k, const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                         const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double h) const {
    const SwitchValue a = switch_at(k, y0, dy0), b = switch_at(k, y1, dy1);
    return {a.value, b.value, h * a.rate, h * b.rate};
  }
  int switch_count() const { return (pounding_ ? ns_ : 0) + static_cast<int>(sw_.size()); }
  int switch_id(int i) const { return pounding_ ? i : ns_ + i; }

  double error_norm(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                    const Eigen::VectorXd& err) const;
  void step(double t, double h, const Eigen::VectorXd& y, const Eigen::VectorXd& k1,
            Eigen::VectorXd& y1, Eigen::VectorXd& err, Eigen::VectorXd& k7) {
    auto f = [this](double tt, const Eigen::VectorXd& yy, Eigen::VectorXd& dy) { rhs(tt, yy, dy); };
    dopri5_step(f, t, h, y, k1, y1, err, work_);
    k7 = work_.k7;
  }
  int find_event(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, const Eigen::VectorXd& dy0,
                 const Eigen::VectorXd& dy1, double h, double& theta) const;
  Located locate(int ev, double theta, double hs, double en, bool trial_failed);
  void apply_event(int k, double t, Eigen::VectorXd& y);
  void apply_contact_event(int i, double t, Eigen::VectorXd& y);
  // Throws when switch k piles up events at one instant (what() names it; called then only).
  template <class What>
  void guard_chatter(int k, double t, What what);
  void retry(double hn);
  void reject(double hf, double enf);

  void start();
  // Exact steps between events (docs/integration.md, "Exact steps"): at a point of the grid
  // t_k = k h_sub with no contact active, the row is linear in its state with the current
  // branches' stiffness and offsets and a piecewise-linear ag, so one step of linear_step()
  // reaches t_k+1 exactly. false (nothing changed) when a switch fires inside the step: the
  // Dormand-Prince path then takes the step and locates the event.
  bool exact_step();
  bool on_exact_grid();
  bool contacts_open() const;
  bool exact_setup();
  double next_stop();
  void accept(double hs, double en, double t_stop);
  void finish();
  void update_peaks(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                    const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double h);
  void fork_if_near_contact(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, double h);
  void record(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& dy);
  void check_finite(double t, const Eigen::VectorXd& y) const {
    if (!y.allFinite())
      throw NumericalError("non-finite state at t = " + std::to_string(t) +
                           " s (the response diverged; check stiffness, masses and step)");
  }

  const RowProblem* p_;
  const IntegratorSettings& s_;
  const AssembledRow& row_;
  const int n_, ns_;
  // The row's storeys, or elastic ones for a hand-built row: shared by a solver and its fork
  // (never changed), so that forces_ of either refers to a live vector.
  std::shared_ptr<const std::vector<RowStorey>> storeys_owner_;
  const std::vector<RowStorey>& storeys_;
  const bool linear_, track_, fixed_;
  bool affine_ = false;  // every storey law piecewise linear: f = K_t u + offsets (bands below)
  bool pounding_ = false;
  int nx_ = 0;                        // storey continuous states
  int iJ_ = 0, iE_ = 0, N_ = 0;       // offsets of the impulses and energies; state size
  std::vector<int> xoff_;             // per DOF: offset of its storey's states in y, -1: none
  std::vector<StoreySwitch> sw_;      // storey switches (ids ns_, ns_ + 1, ...)
  std::vector<StoreyState> storey_;   // per DOF: the discrete state of its storey law
  std::vector<char> active_;          // contact active per site
  std::vector<double> v0_;            // approach velocity at the start of the current contact [m/s]
  std::vector<double> last_event_t_;  // per switch id [s]
  std::vector<int> chatter_;          // per switch id
  Eigen::VectorXd force_;             // contact force per site [N]
  mutable Eigen::VectorXd scratch_;   // damping forces C v [N] (energy rates)
  RowForces forces_;                  // internal forces of the floors
  // Per storey the drift interval in which its switches cannot fire [m].
  std::vector<char> has_safe_;
  std::vector<double> safe_lo_, safe_hi_;
  std::vector<double> below_;   // per DOF: 1 where its storey joins floor DOF - 1, 0 on the ground
  std::vector<double> bounds_;  // scratch of update_peaks: the peak bounds (peak_bounds)
  Dopri5Work work_;
  RowResult r_;

  // Exact steps: eligible row, grid step [s], index of the last grid point reached, the
  // propagators (RowProblem::exact_cache or this run's own), the current stiffness' entry (-1:
  // look it up again, after a switch), the offsets' response P1 [0; -M^-1] off [m, m/s].
  bool exact_ = false;
  double h_sub_ = 0.0;
  long sub_ = 0;
  long exact_declined_ = -1;  // the grid point whose exact step was declined
  ExactStepCache own_cache_;
  ExactStepCache* cache_ = &own_cache_;
  int config_ = -1;
  bool c_off_ready_ = false;
  Eigen::VectorXd c_off_;
  Eigen::MatrixXd k_scratch_;  // the current stiffness, to look up its entry [N/m]
  std::vector<int> visits_;    // per entry: grid points of this run met with its stiffness

  // The fork of a free run (solve_free_and_pounding). Until a site comes within kForkMargin of
  // touching, the pounding run's steps are the free run's (no contact is active, no contact
  // switch can fire, and every site is open by more than contacts_open()'s 1 nm), so the
  // pounding run starts from the free run's state there. The margin is ten times the cubic
  // interpolant's error over a step of T_min / 20 (about 1e-7 m, docs/integration.md), so that
  // the pounding run's own interpolants do not see a crossing before it either. declined_at_top_
  // and visited_ undo what the current loop iteration changed before its step was accepted.
  static constexpr double kForkMargin = 1e-6;  // [m]
  const RowProblem* fork_to_ = nullptr;
  bool fork_armed_ = false;
  std::shared_ptr<Solver> fork_;
  long declined_at_top_ = -1;
  int visited_ = -1;  // the cache entry whose visits this iteration counted (-1: none)

  // Integration state.
  double t_ = 0.0, h_ = 0.0, h_max_ = 0.0, rec_dt_ = 0.0;
  long grid_ = 0, next_sample_ = 1;
  bool any_contact_ = false;
  Eigen::VectorXd y_, y1_, err_, k1_, k7_, ytry_, etry_, ktry_;
};

Solver::Solver(const RowProblem& p, const IntegratorSettings& s)
    : p_(&p),
      s_(s),
      row_(*p.row),
      n_(row_.dofs()),
      ns_(static_cast<int>(row_.sites.size())),
      storeys_owner_(std::make_shared<const std::vector<RowStorey>>(
          static_cast<int>(row_.storeys.size()) == n_ ? row_.storeys : elastic_storeys(row_))),
      storeys_(*storeys_owner_),
      linear_(row_.linear),
      track_(p.track_energy),
      fixed_(s.control == StepControl::fixed),
      forces_(row_, storeys_) {
  pounding_ = !p.laws.empty();
  if (pounding_ && static_cast<int>(p.laws.size()) != ns_)
    throw std::logic_error("one contact law per site expected");
  active_.assign(ns_, false);
  v0_.assign(ns_, 0.0);
  xoff_.assign(n_, -1);
  storey_.assign(n_, StoreyState{});
  for (int i = 0; i < n_; ++i) {
    const StoreyLaw& law = *storeys_[i].law;
    if (law.continuous_states() > 0) {
      xoff_[i] = 2 * n_ + nx_;
      nx_ += law.continuous_states();
    }
    for (int k = 0; k < law.switches(); ++k) sw_.push_back({i, k});
  }
  affine_ = !linear_;
  for (int i = 0; i < n_; ++i) {
    double slope, offset;
    affine_ = affine_ && storeys_[i].law->branch_line(storeys_[i].p, storey_[i], slope, offset);
  }
  has_safe_.assign(n_, 0);
  safe_lo_.assign(n_, 0.0);
  safe_hi_.assign(n_, 0.0);
  below_.assign(n_, 0.0);
  for (int i = 0; i < n_; ++i) {  // a row's floors stand on the floor before them or the ground
    const int b = storeys_[i].below;
    if (b != -1 && b != i - 1)
      throw std::logic_error("storey below floor DOF " + std::to_string(i));
    below_[i] = b < 0 ? 0.0 : 1.0;
  }
  bounds_.assign(2 * n_, 0.0);
  iJ_ = 2 * n_ + nx_;
  iE_ = iJ_ + ns_;
  N_ = iE_ + (track_ ? 3 : 0);
  force_.setZero(ns_);
  scratch_.setZero(n_);
  work_.resize(N_);
}

void Solver::rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy) {
  contact_forces(y);
  const double ag = p_->motion ? p_->motion->at(t) : 0.0;
  dy.resize(N_);
  const double* u = y.data();
  const double* v = u + n_;
  const double* im = row_.inv_mass.data();
  double* du = dy.data();
  double* dv = du + n_;
  std::copy(v, v + n_, du);
  if (linear_)
    forces_.linear(u, v, ag, dv);
  else if (affine_)
    forces_.affine(u, v, ag, dv);
  else
    forces_.general(y, storey_, xoff_, ag, dy.data());
  for (int i = 0; i < ns_; ++i) {
    const double f = force_(i);
    du[iJ_ + i] = f;
    if (f == 0.0) continue;
    const auto& site = row_.sites[i];
    dv[site.dof_left] -= im[site.dof_left] * f;
    dv[site.dof_right] += im[site.dof_right] * f;
  }
  if (track_) energy_rates(y, ag, du + iE_);
}

// After storey `dof` changed branch: its line (piecewise-linear rows) and safe interval.
void Solver::storey_changed(int dof) {
  if (affine_) forces_.set_lines(storey_);
  config_ = -1;
  c_off_ready_ = false;
  const RowStorey& st = storeys_[dof];
  has_safe_[dof] = st.law->safe_drift(st.p, storey_[dof], safe_lo_[dof], safe_hi_[dof]);
  if (has_safe_[dof]) {  // find_event's margin for round-off
    const double margin = 1e-12 * (std::fabs(safe_lo_[dof]) + std::fabs(safe_hi_[dof]));
    safe_lo_[dof] += margin;
    safe_hi_[dof] -= margin;
  }
}

// E' = [input -ag 1^T M v, damping v^T C v, contact sum_s F_s (v_L - v_R)] [W].
void Solver::energy_rates(const Eigen::VectorXd& y, double ag, double* dE) const {
  const double* v = y.data() + n_;
  double* cv = scratch_.data();
  forces_.damping(v, cv);
  double mv = 0.0, vcv = 0.0, contact = 0.0;
  for (int i = 0; i < n_; ++i) {
    mv += v[i] / row_.inv_mass(i);
    vcv += v[i] * cv[i];
  }
  for (int i = 0; i < ns_; ++i) contact += force_(i) * gap_rate(y, i);
  dE[0] = -ag * mv;
  dE[1] = vcv;
  dE[2] = contact;
}

SwitchValue Solver::storey_switch_at(int k, const Eigen::VectorXd& y,
                                     const Eigen::VectorXd& dy) const {
  const StoreySwitch& w = sw_[k - ns_];
  const RowStorey& st = storeys_[w.dof];
  return st.law->switch_value(w.local, st.p, storey_[w.dof], drift(y, 0, w.dof),
                              drift(y, n_, w.dof), drift(dy, n_, w.dof));
}

double Solver::error_norm(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                          const Eigen::VectorXd& err) const {
  double sum = 0.0;
  const int m = 2 * n_ + nx_;
  for (int i = 0; i < m; ++i) {
    const double sc = s_.atol + s_.rtol * std::max(std::fabs(y0(i)), std::fabs(y1(i)));
    const double r = err(i) / sc;
    sum += r * r;
  }
  return std::sqrt(sum / m);
}

// Earliest switch in the step (t0, y0) -> (t0 + h, y1): its id and an estimate of theta, from
// the cubic Hermite interpolant of each switching function. Returns -1 when none.
int Solver::find_event(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                       const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double h,
                       double& theta) const {
  int best = -1;
  theta = 2.0;
  for (int j = 0, m = switch_count(); j < m; ++j) {
    const int k = switch_id(j);
    if (k >= ns_) {
      const int dof = sw_[k - ns_].dof;
      if (has_safe_[dof]) {
        // Skip a storey whose drift stays inside its safe interval (shrunk by 1e-12 of its
        // ends, storey_changed): a bound of the drift's cubic over the step (its basis
        // functions of the end slopes are at most 4/27).
        const double d0 = drift(y0, 0, dof), d1 = drift(y1, 0, dof);
        const double m4 =
            4.0 / 27.0 * h * (std::fabs(drift(y0, n_, dof)) + std::fabs(drift(y1, n_, dof)));
        if (std::max(d0, d1) + m4 < safe_hi_[dof] && std::min(d0, d1) - m4 > safe_lo_[dof])
          continue;
      }
    }
    const Hermite c = switch_hermite(k, y0, y1, dy0, dy1, h);
    if (c.upper_bound() < 0.0) continue;  // no crossing
    bool ev;
    if (k < ns_ && !active_[k] && c.g0 > 0.0)  // across within the location tolerance: only
      ev = c.m0 > 0.0 || c.g1 > c.g0;          // a renewed approach counts
    else
      ev = c.g1 > 0.0 || (c.m0 > 0.0 && c.max_over_step() > 0.0);
    if (!ev) continue;
    // First sign change of the cubic, scanned then bisected.
    double lo = 0.0, th = 1.0;
    const int nscan = 32;
    for (int i = 1; i <= nscan; ++i) {
      const double x = double(i) / nscan;
      if (c.at(x) > 0.0) {
        th = x;
        break;
      }
      lo = x;
    }
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + th);
      if (c.at(mid) > 0.0)
        th = mid;
      else
        lo = mid;
    }
    if (th < theta) {
      theta = th;
      best = k;
    }
  }
  return best;
}

// Locates switch ev in the step of length hs from (t_, y_) by Illinois iteration on re-taken
// steps (g(h') = the switching function after a step h'), advances to it and applies it.
Solver::Located Solver::locate(int ev, double theta, double hs, double en, bool trial_failed) {
  double a = 0.0, fa = switch_at(ev, y_, k1_).value;
  double b = hs, fb = switch_at(ev, y1_, k7_).value;
  double hc = theta * hs;
  bool found = false;
  int side = 0;
  if (fb <= 0.0) {
    // A switch rising and falling back inside the step: confirm the interior extremum.
    step(t_, hc, y_, k1_, ytry_, etry_, ktry_);
    const double fc = switch_at(ev, ytry_, ktry_).value;
    if (!(fc > 0.0)) return Located::none;  // false alarm: the cubic overshot
    b = hc;
    fb = fc;
  }
  if (fa >= 0.0 && switch_at(ev, y_, k1_).rate <= 0.0) {
    // At the step start the function is across zero by round-off (delta ~ 1e-19 m left by the
    // location of the previous event) but moving back: the event is the renewed crossing after
    // the dip, not one at t (which would switch off and on at one instant, over and over).
    // Bracket it from the dip's deepest point.
    const Hermite c = switch_hermite(ev, y_, y1_, k1_, k7_, hs);
    double st[2], deepest = 0.0, th_dip = -1.0;
    const int nst = c.stationary(st);
    for (int k = 0; k < nst; ++k)
      if (c.at(st[k]) < deepest) {
        deepest = c.at(st[k]);
        th_dip = st[k];
      }
    if (th_dip > 0.0 && th_dip * hs < b) {
      step(t_, th_dip * hs, y_, k1_, ytry_, etry_, ktry_);
      const double fd = switch_at(ev, ytry_, ktry_).value;
      if (fd < 0.0) {
        a = th_dip * hs;
        fa = fd;
      }
    }
  }
  if (fa >= 0.0) {  // already at or across the crossing at the step start: event at t
    hc = 0.0;
    found = true;
  }
  // Storey switches land strictly across (a kink of the law must not be undone by round-off).
  const bool must_cross = ev >= ns_;
  // The first try is the interpolant's crossing; then Newton's step on the switch's rate at the
  // last try when it falls inside the bracket, else Illinois (each try is a re-taken step).
  // Newton stops for good once a try does not halve |f|: the rate is that of the motion, and
  // a long re-taken step (through a contact) may not follow it closely enough.
  double guess = theta * hs, f_last = kNaN;
  bool newton = true;
  for (int it = 0; it < 100 && !found; ++it) {
    hc = guess;
    if (!(hc > a && hc < b)) hc = (a * fb - b * fa) / (fb - fa);
    if (!(hc > a && hc < b)) hc = 0.5 * (a + b);
    step(t_, hc, y_, k1_, ytry_, etry_, ktry_);
    const SwitchValue c = switch_at(ev, ytry_, ktry_);
    const double fc = c.value;
    // Newton aims at 0 (contacts) or half the tolerance across (storeys must cross).
    if (it > 0 && !(std::fabs(fc) <= 0.5 * f_last)) newton = false;
    f_last = std::fabs(fc);
    guess = newton && c.rate != 0.0 ? hc + ((must_cross ? 0.5e-15 : 0.0) - fc) / c.rate : kNaN;
    if (fc > 0.0) {
      b = hc;
      fb = fc;
      if (side == 1) fa *= 0.5;
      side = 1;
    } else {
      a = hc;
      fa = fc;
      if (side == -1) fb *= 0.5;
      side = -1;
    }
    // On the crossing to round-off, and moving across it: a grazing contact that opens at
    // delta ~ 1e-18 m has |delta| < 1e-15 m at its own start as well, where the faces still
    // approach; accepting that point as its end would close and reopen the contact at one
    // instant, over and over (found in a campaign: "impacts accumulate").
    if (std::fabs(fc) < 1e-15 && c.rate > 0.0 && (!must_cross || fc > 0.0)) {
      found = true;
    } else if (b - a < 1e-13 * std::max(1.0, t_)) {
      // Bracket collapsed: land just across the crossing.
      if (fc <= 0.0) {
        hc = b;
        step(t_, hc, y_, k1_, ytry_, etry_, ktry_);
      }
      found = true;
    }
  }
  if (!found) throw NumericalError("event location failed at t = " + std::to_string(t_));
  if (trial_failed) {
    // The step to the event replaces a rejected one: it must be re-taken (an event at t
    // itself rests on the rejected trial only), pass the error test, and its own (accurate)
    // interpolant must show no earlier event of another switch.
    if (!(hc > 0.0)) {
      reject(hs, en);
      return Located::retry;
    }
    const double enc = error_norm(y_, ytry_, etry_);
    if (!(enc <= 1.0)) {
      reject(hc, enc);
      return Located::retry;
    }
    double th2;
    const int ev2 = find_event(y_, ytry_, k1_, ktry_, hc, th2);
    if (ev2 >= 0 && ev2 != ev) {  // retry up to the earlier event
      retry(std::max(th2, 0.1) * hc);
      return Located::retry;
    }
  }
  if (hc > 0.0) {
    update_peaks(y_, ytry_, k1_, ktry_, hc);
    y_ = ytry_;
    t_ += hc;
    ++r_.steps;
  }
  apply_event(ev, t_, y_);
  rhs(t_, y_, k1_);
  record(t_, y_, k1_);
  return Located::applied;
}

template <class What>
void Solver::guard_chatter(int k, double t, What what) {
  // Switches piling up at one instant (Zeno behaviour).
  if (t - last_event_t_[k] < 1e-9) {
    if (++chatter_[k] > 1000)
      throw NumericalError(what() + ": " + (k < ns_ ? "impacts" : "yield events") +
                           " accumulate at t = " + std::to_string(t) + " s (chatter)" +
                           (k < ns_ ? "; use a force-based contact model" : std::string()));
  } else {
    chatter_[k] = 0;
  }
  last_event_t_[k] = t;
}

void Solver::apply_event(int k, double t, Eigen::VectorXd& y) {
  ++r_.events;
  if (k < ns_) {
    apply_contact_event(k, t, y);
    any_contact_ = true;
    return;
  }
  const StoreySwitch& w = sw_[k - ns_];
  const RowStorey& st = storeys_[w.dof];
  guard_chatter(k, t, [&] {
    return "building " + std::to_string(st.building + 1) + ", storey " +
           std::to_string(w.dof - row_.offset[st.building] + 1);
  });
  st.law->on_switch(w.local, st.p, storey_[w.dof], drift(y, 0, w.dof), x_of(y, w.dof));
  storey_changed(w.dof);
}

void Solver::apply_contact_event(int i, double t, Eigen::VectorXd& y) {
  auto& sr = r_.sites[i];
  if (active_[i]) {
    active_[i] = false;
    sr.last_separation = t;
    return;
  }
  const double rate = gap_rate(y, i);
  const ContactLaw& law = *p_->laws[i];
  guard_chatter(i, t, [&] {
    return "contact site " + std::to_string(i) + " (pair " +
           std::to_string(row_.sites[i].pair + 1) + ", floor " +
           std::to_string(row_.sites[i].level + 1) + ")";
  });
  if (sr.first_contact < 0) sr.first_contact = t;
  ++sr.impacts;
  if (!law.impulsive()) {
    active_[i] = true;
    v0_[i] = std::max(rate, 0.0);
    return;
  }
  // Stereomechanical impact (Goldsmith): velocity jump conserving momentum, separation
  // velocity e times the approach velocity.
  if (rate > 0.0) {
    const auto& s = row_.sites[i];
    const double mL = 1.0 / row_.inv_mass(s.dof_left), mR = 1.0 / row_.inv_mass(s.dof_right);
    const double jump = (1.0 + law.restitution()) * rate;
    const double impulse = mL * mR / (mL + mR) * jump;
    const double e_before =
        0.5 * (mL * std::pow(y(n_ + s.dof_left), 2) + mR * std::pow(y(n_ + s.dof_right), 2));
    y(n_ + s.dof_left) -= impulse / mL;
    y(n_ + s.dof_right) += impulse / mR;
    y(iJ_ + i) += impulse;
    if (track_)  // the kinetic energy the jump removes: mu v0^2 (1 - e^2) / 2
      y(iE_ + 2) += e_before - 0.5 * (mL * std::pow(y(n_ + s.dof_left), 2) +
                                      mR * std::pow(y(n_ + s.dof_right), 2));
    sr.peak_force = kNaN;
  }
  sr.last_separation = t;
}

void Solver::record(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& dy) {
  // Absolute acceleration u'' + ag = M^-1 (P - C v - f): dy already holds u'' = that - ag.
  const double ag = p_->motion ? p_->motion->at(t) : 0.0;
  for (int i = 0; i < n_; ++i) {
    const double a = dy(n_ + i) + ag;
    r_.peak_abs_accel(i) = std::max(r_.peak_abs_accel(i), std::fabs(a));
  }
  contact_forces(y);
  for (int i = 0; i < ns_; ++i) {
    auto& sr = r_.sites[i];
    if (active_[i]) sr.peak_force = std::max(sr.peak_force, force_(i));
  }
  if (p_->record_history) {
    r_.history.t.push_back(t);
    r_.history.u.push_back(y.head(n_));
    r_.history.a_abs.push_back(dy.segment(n_, n_).array() + ag);
    r_.history.force.push_back(force_);
    Eigen::VectorXd shear(n_);
    for (int i = 0; i < n_; ++i) shear(i) = storey_shear(y, i);
    r_.history.shear.push_back(shear);
  }
}

void Solver::update_peaks(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                          const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double h) {
  // Displacement and drift extrema inside the step from the quintic Hermite interpolant of the
  // displacements, velocities and accelerations at both ends (sixth-order accurate: exact steps
  // of h_max = T_min / 20 leave the peaks within 1e-8 of the motion between them).
  if (fork_armed_ && !fork_) fork_if_near_contact(y0, y1, h);
  const double h2 = h * h;
  const double* bound = bounds_.data();
  peak_bounds(n_, y0.data(), y1.data(), y0.data() + n_, y1.data() + n_, dy0.data() + n_,
              dy1.data() + n_, below_.data(), h, h2, bounds_.data());
  for (int i = 0; i < n_; ++i) {  // QuinticHermite::raise_peak, its bound from peak_bounds
    const bool disp = !(bound[i] <= r_.peak_disp(i)), drift = !(bound[n_ + i] <= r_.peak_drift(i));
    if (!disp && !drift) continue;
    const QuinticHermite c{y0(i),           y1(i), h * y0(n_ + i), h * y1(n_ + i), h2 * dy0(n_ + i),
                           h2 * dy1(n_ + i)};
    if (disp) r_.peak_disp(i) = c.refine_peak(r_.peak_disp(i));
    const int b = storeys_[i].below;
    if (b < 0) {  // a first storey: its drift is the floor's displacement
      r_.peak_drift(i) = r_.peak_disp(i);
      continue;
    }
    if (!drift) continue;
    QuinticHermite d = c;
    d.g0 -= y0(b);
    d.g1 -= y1(b);
    d.m0 -= h * y0(n_ + b);
    d.m1 -= h * y1(n_ + b);
    d.c0 -= h2 * dy0(n_ + b);
    d.c1 -= h2 * dy1(n_ + b);
    r_.peak_drift(i) = d.refine_peak(r_.peak_drift(i));
  }
  for (int i = 0; i < ns_; ++i) {
    if (!active_[i]) continue;
    const Hermite c{gap_function(y0, i), gap_function(y1, i), h * gap_rate(y0, i),
                    h * gap_rate(y1, i)};
    r_.sites[i].peak_penetration = std::max(r_.sites[i].peak_penetration, c.max_over_step());
  }
  // Free run: the peak approach u_L - u_R of each site from the same interpolant the contact
  // events are located on (find_event), so that a pounding run of this motion touches at a
  // site exactly when this peak exceeds its gap (up to the location tolerance).
  for (int i = 0; i < ns_ && !pounding_; ++i) {
    const auto& s = row_.sites[i];
    const Hermite c{y0(s.dof_left) - y0(s.dof_right), y1(s.dof_left) - y1(s.dof_right),
                    h * gap_rate(y0, i), h * gap_rate(y1, i)};
    double& peak = r_.sites[i].peak_approach;
    if (c.upper_bound() > peak) peak = std::max(peak, c.max_over_step());
  }
}

// Called with the step (t_, y_) -> (t_ + h, y1) about to be accepted, before it changes anything
// but scratch: forks the pounding run when a site's gap function, on the interpolant the contact
// events are located on (find_event), rises above -kForkMargin in the step.
void Solver::fork_if_near_contact(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, double h) {
  for (int i = 0; i < ns_; ++i) {
    const Hermite c{gap_function(y0, i) + kForkMargin, gap_function(y1, i) + kForkMargin,
                    h * gap_rate(y0, i), h * gap_rate(y1, i)};
    if (c.upper_bound() > 0.0 && c.max_over_step() > 0.0) {
      fork_ = std::make_shared<Solver>(*this, *fork_to_);
      return;
    }
  }
}

Solver::Solver(const Solver& free, const RowProblem& pounding) : Solver(free) {
  if (static_cast<int>(pounding.laws.size()) != ns_)
    throw std::logic_error("one contact law per site expected");
  p_ = &pounding;
  pounding_ = true;
  fork_to_ = nullptr;
  fork_armed_ = false;
  fork_.reset();
  if (free.cache_ == &free.own_cache_) cache_ = &own_cache_;
  if (visited_ >= 0) --visits_[visited_];
  exact_declined_ = declined_at_top_;
  r_.sites.assign(ns_, SiteResult{});
  r_.steps_from_free = r_.steps;
}

// A rejected step: the next try from t has length hn [s].
void Solver::retry(double hn) {
  ++r_.rejected;
  h_ = hn;
  if (h_ < 1e-14 * std::max(1.0, t_))
    throw NumericalError("step size underflow at t = " + std::to_string(t_) + " s");
}

// Rejected for its local error enf > 1, a step of length hf is retried shorter (elementary
// controller, HNW II.4 eq. 4.13, factor limited to [0.1, 0.9]).
void Solver::reject(double hf, double enf) {
  if (!std::isfinite(enf)) enf = 1e10;
  retry(hf * std::max(0.1, 0.9 * std::pow(enf, -0.2)));
}

// Initial state, step limits and the switches already on at t = 0.
void Solver::start() {
  r_.peak_disp.setZero(n_);
  r_.peak_drift.setZero(n_);
  r_.peak_abs_accel.setZero(n_);
  r_.sites.assign(ns_, SiteResult{});
  last_event_t_.assign(ns_ + sw_.size(), -1.0);
  chatter_.assign(ns_ + sw_.size(), 0);
  for (auto* v : {&y1_, &err_, &k1_, &k7_, &ytry_, &etry_, &ktry_}) v->resize(N_);
  y_ = Eigen::VectorXd::Zero(N_);
  if (p_->u0.size()) y_.head(n_) = p_->u0;
  if (p_->v0.size()) y_.segment(n_, n_) = p_->v0;
  for (int i = 0; i < ns_ && !pounding_; ++i)
    r_.sites[i].peak_approach = y_(row_.sites[i].dof_left) - y_(row_.sites[i].dof_right);
  fork_armed_ = fork_to_ != nullptr && !pounding_;
  for (int i = 0; i < ns_ && fork_armed_; ++i)
    fork_armed_ = gap_function(y_, i) + kForkMargin < 0.0;
  // Storeys loaded monotonically from rest to the initial drifts.
  for (int i = 0; i < n_ && !linear_; ++i) {
    const RowStorey& st = storeys_[i];
    st.law->advance(st.p, StoreyState{}, 0.0, drift(y_, 0, i), storey_[i]);
    for (int k = 0; k < st.law->continuous_states(); ++k) y_(xoff_[i] + k) = storey_[i].x[k];
    storey_changed(i);
  }
  double tmin_period = std::numeric_limits<double>::infinity();
  for (const auto& per : row_.periods)
    for (int i = 0; i < per.size(); ++i)
      if (per(i) > 0) tmin_period = std::min(tmin_period, per(i));
  h_max_ = s_.h_max > 0 ? s_.h_max : tmin_period / 20.0;
  rec_dt_ = p_->motion ? p_->motion->dt : 0.0;
  if (s_.h_max <= 0 && rec_dt_ > 0) h_max_ = std::min(h_max_, rec_dt_);
  const bool h_max_known = std::isfinite(h_max_);
  if (!h_max_known) h_max_ = std::max(p_->t_end, 1e-6);
  // Exact steps for rows that are linear between events (no storey state integrated, no
  // energy balance), on a grid of h_max that holds every record sample.
  exact_ = s_.exact_free && !fixed_ && !track_ && h_max_known && (linear_ || affine_) && nx_ == 0;
  if (exact_) {
    h_sub_ = h_max_;
    if (rec_dt_ > 0) h_sub_ = rec_dt_ / std::ceil(rec_dt_ / h_max_ * (1 - 1e-12));
    sub_ = 0;
    if (p_->exact_cache) cache_ = p_->exact_cache;
    if (cache_->row != &row_ || cache_->h != h_sub_) {
      cache_->entries.clear();
      cache_->row = &row_;
      cache_->h = h_sub_;
    }
    config_ = -1;
    c_off_ready_ = false;
  }
  if (fixed_ && !(s_.dt > 0)) throw InputError("fixed-step integration needs dt > 0");
  h_ = fixed_ ? s_.dt : std::min(h_max_, 1e-4);
  // Contacts already closed at t = 0 (a negative gap or initial overlap) start at once, and
  // storeys already beyond a kink switch.
  for (int i = 0; i < ns_ && pounding_; ++i)
    if (gap_function(y_, i) > 0.0) apply_event(i, t_, y_);
  rhs(t_, y_, k1_);
  for (std::size_t j = 0; j < sw_.size(); ++j)
    if (switch_at(ns_ + static_cast<int>(j), y_, k1_).value > 0.0) {
      apply_event(ns_ + static_cast<int>(j), t_, y_);
      rhs(t_, y_, k1_);
    }
  record(t_, y_, k1_);
}

// The cache entry of the current tangent stiffness (added when new); its propagator is formed
// at its kExactWarmup-th grid point. Returns whether it is ready.
bool Solver::exact_setup() {
  auto& entries = cache_->entries;
  if (config_ < 0) {
    forces_.stiffness(affine_, k_scratch_);
    for (std::size_t i = 0; i < entries.size() && config_ < 0; ++i)
      if (entries[i].K == k_scratch_) config_ = static_cast<int>(i);
    if (config_ < 0) {
      entries.push_back({k_scratch_, false, {}});
      config_ = static_cast<int>(entries.size()) - 1;
    }
    if (visits_.size() < entries.size()) visits_.resize(entries.size(), 0);
  }
  if (visits_[config_] < ExactStepCache::kExactWarmup) {
    visited_ = config_;
    if (++visits_[config_] < ExactStepCache::kExactWarmup) return false;
  }
  ExactStepCache::Entry& e = entries[config_];
  if (!e.ready) {
    // z = [u; v], z' = A z + B w, w = [off; ag]: u' = v, v' = -M^-1 (K u + C v + off) - ag
    // (physics.md section 1, without contact forces; docs/hysteresis.md for K_t and off).
    const int n = n_;
    const Eigen::VectorXd& im = row_.inv_mass;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    A.topRightCorner(n, n).setIdentity();
    A.bottomLeftCorner(n, n) = -(im.asDiagonal() * e.K);
    A.bottomRightCorner(n, n) = -(im.asDiagonal() * row_.C);
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(2 * n, n + 1);
    B.block(n, 0, n, n) = -Eigen::MatrixXd(im.asDiagonal());
    B.block(n, n, n, 1).setConstant(-1.0);
    // Balance displacements against velocities by the row's largest frequency scale.
    const double w = std::sqrt(A.bottomLeftCorner(n, n).cwiseAbs().rowwise().sum().maxCoeff());
    Eigen::VectorXd scale = Eigen::VectorXd::Ones(2 * n);
    if (w > 0.0 && std::isfinite(w)) scale.head(n).setConstant(1.0 / w);
    e.step = linear_step(A, B, h_sub_, scale);
    e.ready = true;
  }
  if (!c_off_ready_) {
    const std::vector<double>& off = forces_.offsets();
    c_off_.setZero(2 * n_);
    if (affine_)
      for (int j = 0; j < n_; ++j)
        if (off[j] != 0.0) c_off_ += e.step.p1.col(j) * off[j];
    c_off_ready_ = true;
  }
  return true;
}

// Whether t_ is on the exact steps' grid (advancing sub_ to the last grid point <= t_).
bool Solver::on_exact_grid() {
  while (double(sub_ + 1) * h_sub_ <= t_ * (1 + 1e-14) + 1e-15) ++sub_;
  return std::fabs(t_ - double(sub_) * h_sub_) <= 1e-14 * std::max(1.0, t_) + 1e-15;
}

// No contact active, and every site open by more than kTouching: floors touching at rest (a zero
// gap at t = 0) or just apart may close within a step by an amount the step's interpolant does
// not resolve; Dormand-Prince's steps, from its small initial step on, do.
bool Solver::contacts_open() const {
  constexpr double kTouching = 1e-9;  // [m]
  for (int i = 0; i < ns_ && pounding_; ++i)
    if (active_[i] || gap_function(y_, i) > -kTouching) return false;
  return true;
}

bool Solver::exact_step() {
  if (!exact_setup()) return false;
  const double t1 = double(sub_ + 1) * h_sub_;
  const double h = t1 - t_;
  const LinearStep& L = cache_->entries[config_].step;
  // ag over the step: linear between its ends (the grid holds every record sample); zero on a
  // step after the record's last sample (GroundMotion::at).
  double a0 = 0.0, a1 = 0.0;
  if (p_->motion && t_ + 0.5 * h < p_->motion->duration()) {
    a0 = p_->motion->at(std::max(t_, 0.0));
    a1 = p_->motion->at(std::min(t1, p_->motion->duration()));
  }
  y1_ = y_;
  linear_step_apply(L, a0, a1, c_off_.data(), y_.data(), y1_.data());
  rhs(t1, y1_, k7_);
  check_finite(t1, y1_);
  if (pounding_ || !sw_.empty()) {
    double theta;
    if (find_event(y_, y1_, k1_, k7_, h, theta) >= 0) return false;
  }
  update_peaks(y_, y1_, k1_, k7_, h);
  y_.swap(y1_);
  k1_.swap(k7_);
  t_ = t1;
  ++sub_;
  ++r_.steps;
  ++r_.exact_steps;
  record(t_, y_, k1_);
  return true;
}

// The next step ends at the next record sample, grid point or the end [s].
double Solver::next_stop() {
  double t_stop = p_->t_end;
  if (rec_dt_ > 0) {
    while (next_sample_ * rec_dt_ <= t_ * (1 + 1e-14) + 1e-15) ++next_sample_;
    t_stop = std::min(t_stop, next_sample_ * rec_dt_);
  }
  if (fixed_) {
    while ((grid_ + 1) * s_.dt <= t_ * (1 + 1e-14) + 1e-15) ++grid_;
    t_stop = std::min(t_stop, (grid_ + 1) * s_.dt);
  }
  if (exact_) {  // Dormand-Prince steps (through events) end on the exact steps' grid
    on_exact_grid();
    t_stop = std::min(t_stop, double(sub_ + 1) * h_sub_);
  }
  return t_stop;
}

// Accepts the trial step (y_ -> y1_) and chooses the next step length.
void Solver::accept(double hs, double en, double t_stop) {
  update_peaks(y_, y1_, k1_, k7_, hs);
  y_.swap(y1_);  // y1_ and k7_ are the next trial's scratch
  k1_.swap(k7_);
  t_ += hs;
  if (t_stop - t_ < 1e-14 * std::max(1.0, t_)) t_ = t_stop;
  ++r_.steps;
  record(t_, y_, k1_);
  if (!fixed_) {
    const double fac = en > 0 ? std::min(5.0, std::max(0.2, 0.9 * std::pow(en, -0.2))) : 5.0;
    double hn = hs * fac;
    if (hs < h_) hn = std::max(hn, h_);  // the step was cut short by a sample or the end
    h_ = std::min(h_max_, hn);
  }
}

void Solver::finish() {
  r_.u_end = y_.head(n_);
  r_.v_end = y_.segment(n_, n_);
  r_.t_end = t_;
  for (int i = 0; i < ns_; ++i) r_.sites[i].impulse = y_(iJ_ + i);
  r_.hysteretic_energy.setZero(n_);
  double strain = 0.0;
  for (int i = 0; i < n_; ++i) {
    const RowStorey& st = storeys_[i];
    const double d = drift(y_, 0, i);
    r_.hysteretic_energy(i) = st.law->dissipated(st.p, storey_[i], d, x_of(y_, i));
    strain += st.law->stored(st.p, storey_[i], d, x_of(y_, i));
  }
  if (!track_) return;
  EnergyBalance& e = r_.energy;
  for (int i = 0; i < n_; ++i) e.kinetic += 0.5 * std::pow(y_(n_ + i), 2) / row_.inv_mass(i);
  e.strain = strain;
  e.hysteretic = r_.hysteretic_energy.sum();
  e.input = y_(iE_);
  e.damping = y_(iE_ + 1);
  e.contact = y_(iE_ + 2);
}

RowResult Solver::run() {
  start();
  return advance();
}

RowResult Solver::advance() {
  const double t_end = p_->t_end;
  const bool events = pounding_ || !sw_.empty();
  while (t_ < t_end * (1 - 1e-14)) {
    declined_at_top_ = exact_declined_;
    visited_ = -1;
    if (r_.steps + r_.rejected > s_.max_steps)
      throw NumericalError("more than " + std::to_string(s_.max_steps) +
                           " steps by t = " + std::to_string(t_) + " s");
    if (exact_ && on_exact_grid() && sub_ != exact_declined_ &&
        double(sub_ + 1) * h_sub_ <= t_end * (1 + 1e-14) && contacts_open()) {
      if (exact_step()) continue;
      exact_declined_ = sub_;  // Dormand-Prince to the next grid point (rejections included)
    }
    const double t_stop = next_stop();
    double hs = fixed_ ? t_stop - t_ : std::min(h_, t_stop - t_);
    if (t_ + hs > t_stop * (1 - 1e-14)) hs = t_stop - t_;
    step(t_, hs, y_, k1_, y1_, err_, k7_);
    double en = 0.0;
    bool trial_failed = false;
    if (!fixed_) {
      en = error_norm(y_, y1_, err_);
      trial_failed = !(en <= 1.0);
    }
    double theta;
    int ev = -1;
    if (trial_failed) {
      // A switch inside the step puts a kink of the force (a jump of its derivative) into it:
      // there the error estimate falls only like h^2, not h^5, and the controller would creep
      // up on the event through many rejected steps. When the trial's interpolant shows an
      // event, it is located at once on re-taken steps, which must then pass the error test;
      // otherwise the step is rejected as usual.
      if (events && y1_.allFinite()) ev = find_event(y_, y1_, k1_, k7_, hs, theta);
      if (ev < 0) {
        reject(hs, en);
        continue;
      }
    } else {
      check_finite(t_ + hs, y1_);
      if (events) ev = find_event(y_, y1_, k1_, k7_, hs, theta);
    }
    if (ev >= 0) {
      const Located l = locate(ev, theta, hs, en, trial_failed);
      if (l == Located::retry) continue;
      if (l == Located::applied) {
        if (p_->stop_after_separation && any_contact_) {
          bool all_open = true;
          for (int i = 0; i < ns_; ++i) all_open = all_open && !active_[i] && gap_rate(y_, i) < 0.0;
          if (all_open) break;
        }
        continue;
      }
      if (trial_failed) {  // false alarm on a rejected trial
        reject(hs, en);
        continue;
      }
    }
    accept(hs, en, t_stop);
  }
  finish();
  return r_;
}

}  // namespace

RowResult solve(const RowProblem& p, const IntegratorSettings& s) {
  Solver solver(p, s);
  return solver.run();
}

RunPair solve_free_and_pounding(const RowProblem& p, const IntegratorSettings& s) {
  RowProblem free = p, pounding = p;
  free.laws.clear();
  ExactStepCache cache;  // the free run's propagators serve the pounding run too
  if (!p.exact_cache) free.exact_cache = pounding.exact_cache = &cache;
  Solver fs(free, s);
  if (!pounding.laws.empty()) fs.fork_into(&pounding);
  RunPair out;
  out.free = fs.run();
  if (pounding.laws.empty()) {
    out.pounding = out.free;  // the same problem
  } else if (fs.fork()) {
    out.pounding = fs.fork()->advance();
  } else if (fs.fork_armed()) {  // no site came near touching: the runs are one
    out.pounding = out.free;
    out.pounding.sites.assign(p.row->sites.size(), SiteResult{});
    out.pounding.steps_from_free = out.pounding.steps;
  } else {  // a site touching at the start
    out.pounding = Solver(pounding, s).run();
  }
  return out;
}

}  // namespace pound

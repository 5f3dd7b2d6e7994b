#include "solver/row_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "core/error.hpp"
#include "solver/dopri5.hpp"
#include "solver/exact_steps.hpp"
#include "solver/hermite.hpp"
#include "solver/row_dynamics.hpp"
#include "solver/row_switches.hpp"
#include "solver/run_recorder.hpp"

namespace pound {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The adaptive integration of one run (row_solver.hpp): Dormand-Prince steps between switching
// events, each event located on re-taken steps, exact steps of the linear system between events
// where the row allows them. The equations are RowDynamics', the events RowSwitches', the exact
// steps' grid and propagators ExactSteps', and what the run reports RunRecorder's.
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
  // A switch's value fa at the step fraction a and fb at b: the crossing lies in (a, b].
  struct Bracket {
    double a, fa, b, fb;
  };

  void rhs(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dy) { dyn_.rhs(t, y, dy); }
  void step(double t, double h, const Eigen::VectorXd& y, const Eigen::VectorXd& k1,
            Eigen::VectorXd& y1, Eigen::VectorXd& err, Eigen::VectorXd& k7) {
    auto f = [this](double tt, const Eigen::VectorXd& yy, Eigen::VectorXd& dy) { rhs(tt, yy, dy); };
    dopri5_step(f, t, h, y, k1, y1, err, work_);
    k7 = work_.k7;
  }
  double error_norm(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                    const Eigen::VectorXd& err) const;
  int find_event(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, const Eigen::VectorXd& dy0,
                 const Eigen::VectorXd& dy1, double h, double& theta) const {
    return switches_.find_event(dyn_, y0, y1, dy0, dy1, h, theta);
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
  bool contacts_open() const;
  double next_stop();
  void accept(double hs, double en, double t_stop);
  bool separated() const;
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

  // The fork of a free run (solve_free_and_pounding). Until a site comes within kForkMargin of
  // touching, the pounding run's steps are the free run's (no contact is active, no contact
  // switch can fire, and every site is open by more than contacts_open()'s 1 nm), so the
  // pounding run starts from the free run's state there. The margin is ten times the cubic
  // interpolant's error over a step of T_min / 20 (about 1e-7 m, docs/integration.md), so that
  // the pounding run's own interpolants do not see a crossing before it either.
  static constexpr double kForkMargin = 1e-6;  // [m]
  const RowProblem* fork_to_ = nullptr;
  bool fork_armed_ = false;
  std::shared_ptr<Solver> fork_;

  // Integration state: time, next step and largest step [s], record spacing [s], the fixed
  // grid's and the record's last points passed, the state y and its derivative k1, the trial
  // step's end y1 (derivative k7, error err) and the re-taken steps' (ytry, ktry, etry).
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
      track_(p.track_energy),
      fixed_(s.control == StepControl::fixed),
      dyn_(row_, storeys_, track_),
      switches_(row_, storeys_),
      rec_(row_, storeys_, !p.laws.empty(), p.record_history) {
  if (!p.laws.empty() && static_cast<int>(p.laws.size()) != ns_)
    throw std::logic_error("one contact law per site expected");
  dyn_.set_contacts(&p.laws);
  dyn_.set_motion(p.motion);
  work_.resize(dyn_.layout().size);
}

Solver::Solver(const Solver& free, const RowProblem& pounding) : Solver(free) {
  if (static_cast<int>(pounding.laws.size()) != ns_)
    throw std::logic_error("one contact law per site expected");
  p_ = &pounding;
  dyn_.set_contacts(&pounding.laws);
  fork_to_ = nullptr;
  fork_armed_ = false;
  fork_.reset();
  exact_.undo_iteration();
  rec_.contacts_on();
}

// Called with the step (t_, y_) -> (t_ + h, y1) about to be accepted, before it changes anything
// but scratch: forks the pounding run when a site's gap function, on the interpolant the contact
// events are located on (find_event), rises above -kForkMargin in the step.
void Solver::fork_if_near_contact(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, double h) {
  for (int i = 0; i < ns_; ++i) {
    const Hermite c{dyn_.penetration(y0, i) + kForkMargin, dyn_.penetration(y1, i) + kForkMargin,
                    h * dyn_.penetration_rate(y0, i), h * dyn_.penetration_rate(y1, i)};
    if (c.upper_bound() > 0.0 && c.max_over_step() > 0.0) {
      fork_ = std::make_shared<Solver>(*this, *fork_to_);
      return;
    }
  }
}

// After storey `dof` changed branch: its line (piecewise-linear rows), safe interval and the
// exact steps' stiffness.
void Solver::storey_changed(int dof) {
  dyn_.storey_changed(dof);
  exact_.invalidate();
  switches_.storey_changed(dof, dyn_.storey[dof]);
}

double Solver::error_norm(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                          const Eigen::VectorXd& err) const {
  double sum = 0.0;
  const int m = dyn_.layout().tested();
  for (int i = 0; i < m; ++i) {
    const double sc = s_.atol + s_.rtol * std::max(std::fabs(y0(i)), std::fabs(y1(i)));
    const double r = err(i) / sc;
    sum += r * r;
  }
  return std::sqrt(sum / m);
}

// The bracket of switch ev in the step of length hs from (t_, y_): from the step's ends, or, when
// the switch is back below zero at the end, from the interior point theta hs where the cubic
// crossed (false: the cubic overshot, no event). A switch across zero by round-off at the start
// but moving back is bracketed from its dip's deepest point.
bool Solver::bracket_event(int ev, double theta, double hs, Bracket& br) {
  br = {0.0, switch_at(ev, y_, k1_).value, hs, switch_at(ev, y1_, k7_).value};
  if (br.fb <= 0.0) {
    // A switch rising and falling back inside the step: confirm the interior extremum.
    const double hc = theta * hs;
    step(t_, hc, y_, k1_, ytry_, etry_, ktry_);
    const double fc = switch_at(ev, ytry_, ktry_).value;
    if (!(fc > 0.0)) return false;  // false alarm: the cubic overshot
    br.b = hc;
    br.fb = fc;
  }
  if (br.fa >= 0.0 && switch_at(ev, y_, k1_).rate <= 0.0) {
    // At the step start the function is across zero by round-off (delta ~ 1e-19 m left by the
    // location of the previous event) but moving back: the event is the renewed crossing after
    // the dip, not one at t (which would switch off and on at one instant, over and over).
    // Bracket it from the dip's deepest point.
    const Hermite c = switches_.hermite(dyn_, ev, y_, y1_, k1_, k7_, hs);
    double st[2], deepest = 0.0, th_dip = -1.0;
    const int nst = c.stationary(st);
    for (int k = 0; k < nst; ++k)
      if (c.at(st[k]) < deepest) {
        deepest = c.at(st[k]);
        th_dip = st[k];
      }
    if (th_dip > 0.0 && th_dip * hs < br.b) {
      step(t_, th_dip * hs, y_, k1_, ytry_, etry_, ktry_);
      const double fd = switch_at(ev, ytry_, ktry_).value;
      if (fd < 0.0) {
        br.a = th_dip * hs;
        br.fa = fd;
      }
    }
  }
  return true;
}

// The step length to switch ev's crossing inside the bracket, with ytry_ (ktry_, etry_) the state
// there. The first try is `guess` (the interpolant's crossing); then Newton's step on the switch's
// rate at the last try when it falls inside the bracket, else Illinois (each try is a re-taken
// step). Newton stops for good once a try does not halve |f|: the rate is that of the motion, and
// a long re-taken step (through a contact) may not follow it closely enough.
double Solver::refine_event(int ev, double guess, Bracket br) {
  // Storey switches land strictly across (a kink of the law must not be undone by round-off).
  const bool must_cross = ev >= ns_;
  double f_last = kNaN, hc = 0.0;
  bool newton = true;
  int side = 0;
  for (int it = 0; it < 100; ++it) {
    hc = guess;
    if (!(hc > br.a && hc < br.b)) hc = (br.a * br.fb - br.b * br.fa) / (br.fb - br.fa);
    if (!(hc > br.a && hc < br.b)) hc = 0.5 * (br.a + br.b);
    step(t_, hc, y_, k1_, ytry_, etry_, ktry_);
    const SwitchValue c = switch_at(ev, ytry_, ktry_);
    const double fc = c.value;
    // Newton aims at 0 (contacts) or half the tolerance across (storeys must cross).
    if (it > 0 && !(std::fabs(fc) <= 0.5 * f_last)) newton = false;
    f_last = std::fabs(fc);
    guess = newton && c.rate != 0.0 ? hc + ((must_cross ? 0.5e-15 : 0.0) - fc) / c.rate : kNaN;
    if (fc > 0.0) {
      br.b = hc;
      br.fb = fc;
      if (side == 1) br.fa *= 0.5;
      side = 1;
    } else {
      br.a = hc;
      br.fa = fc;
      if (side == -1) br.fb *= 0.5;
      side = -1;
    }
    // On the crossing to round-off, and moving across it: a grazing contact that opens at
    // delta ~ 1e-18 m has |delta| < 1e-15 m at its own start as well, where the faces still
    // approach; accepting that point as its end would close and reopen the contact at one
    // instant, over and over (found in a campaign: "impacts accumulate").
    if (std::fabs(fc) < 1e-15 && c.rate > 0.0 && (!must_cross || fc > 0.0)) return hc;
    if (br.b - br.a < 1e-13 * std::max(1.0, t_)) {
      // Bracket collapsed: land just across the crossing.
      if (fc <= 0.0) {
        hc = br.b;
        step(t_, hc, y_, k1_, ytry_, etry_, ktry_);
      }
      return hc;
    }
  }
  throw NumericalError("event location failed at t = " + std::to_string(t_));
}

// Locates switch ev in the step of length hs from (t_, y_) by Illinois iteration on re-taken
// steps (g(h') = the switching function after a step h'), advances to it and applies it.
Solver::Located Solver::locate(int ev, double theta, double hs, double en, bool trial_failed) {
  Bracket br;
  if (!bracket_event(ev, theta, hs, br)) return Located::none;
  // Already at or across the crossing at the step start: the event is at t.
  const double hc = br.fa >= 0.0 ? 0.0 : refine_event(ev, theta * hs, br);
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
    ++rec_.result().steps;
  }
  apply_event(ev, t_, y_);
  rhs(t_, y_, k1_);
  record(t_, y_, k1_);
  return Located::applied;
}

void Solver::apply_event(int k, double t, Eigen::VectorXd& y) {
  ++rec_.result().events;
  if (k < ns_) {
    apply_contact_event(k, t, y);
    any_contact_ = true;
    return;
  }
  switches_.apply_storey(dyn_, k, t, y);
  storey_changed(switches_.storey_dof(k));
}

void Solver::apply_contact_event(int i, double t, Eigen::VectorXd& y) {
  if (dyn_.active[i]) {
    dyn_.active[i] = false;
    rec_.contact_ended(i, t);
    return;
  }
  const double rate = dyn_.penetration_rate(y, i);
  const ContactLaw& law = *p_->laws[i];
  switches_.guard_chatter(i, t, [&] {
    return "contact site " + std::to_string(i) + " (pair " +
           std::to_string(row_.sites[i].pair + 1) + ", floor " +
           std::to_string(row_.sites[i].level + 1) + ")";
  });
  rec_.contact_started(i, t);
  if (!law.impulsive()) {
    dyn_.active[i] = true;
    dyn_.v0[i] = std::max(rate, 0.0);
    return;
  }
  // Stereomechanical impact (Goldsmith): velocity jump conserving momentum, separation
  // velocity e times the approach velocity.
  if (rate > 0.0) {
    const auto& s = row_.sites[i];
    const StateLayout& at = dyn_.layout();
    const double mL = 1.0 / row_.inv_mass(s.dof_left), mR = 1.0 / row_.inv_mass(s.dof_right);
    const double jump = (1.0 + law.restitution()) * rate;
    const double impulse = mL * mR / (mL + mR) * jump;
    const double e_before =
        0.5 * (mL * std::pow(y(n_ + s.dof_left), 2) + mR * std::pow(y(n_ + s.dof_right), 2));
    y(n_ + s.dof_left) -= impulse / mL;
    y(n_ + s.dof_right) += impulse / mR;
    y(at.impulses + i) += impulse;
    if (track_)  // the kinetic energy the jump removes: mu v0^2 (1 - e^2) / 2
      y(at.energies + 2) += e_before - 0.5 * (mL * std::pow(y(n_ + s.dof_left), 2) +
                                              mR * std::pow(y(n_ + s.dof_right), 2));
    rec_.result().sites[i].peak_force = kNaN;
  }
  rec_.contact_ended(i, t);
}

// A rejected step: the next try from t has length hn [s].
void Solver::retry(double hn) {
  ++rec_.result().rejected;
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

// The largest step, the record spacing, and exact steps for rows that are linear between events
// (no storey state integrated, no energy balance), on a grid of h_max that holds every record
// sample.
void Solver::set_step_limits() {
  const double tmin_period = shortest_period(row_);
  h_max_ = s_.h_max > 0 ? s_.h_max : tmin_period / 20.0;
  rec_dt_ = p_->motion ? p_->motion->dt : 0.0;
  if (s_.h_max <= 0 && rec_dt_ > 0) h_max_ = std::min(h_max_, rec_dt_);
  const bool h_max_known = std::isfinite(h_max_);
  if (!h_max_known) h_max_ = std::max(p_->t_end, 1e-6);
  if (s_.exact_free && !fixed_ && !track_ && h_max_known && (dyn_.linear() || dyn_.affine()) &&
      dyn_.layout().storey_states == 0)
    exact_.enable(row_, h_max_, rec_dt_, p_->exact_cache);
  if (fixed_ && !(s_.dt > 0)) throw InputError("fixed-step integration needs dt > 0");
  h_ = fixed_ ? s_.dt : std::min(h_max_, 1e-4);
}

// Initial state, step limits and the switches already on at t = 0.
void Solver::start() {
  const StateLayout& at = dyn_.layout();
  switches_.reset();
  for (auto* v : {&y1_, &err_, &k1_, &k7_, &ytry_, &etry_, &ktry_}) v->resize(at.size);
  y_ = Eigen::VectorXd::Zero(at.size);
  if (p_->u0.size()) y_.head(n_) = p_->u0;
  if (p_->v0.size()) y_.segment(n_, n_) = p_->v0;
  rec_.start(y_.head(n_));
  const bool pounding = dyn_.pounding();
  fork_armed_ = fork_to_ != nullptr && !pounding;
  for (int i = 0; i < ns_ && fork_armed_; ++i)
    fork_armed_ = dyn_.penetration(y_, i) + kForkMargin < 0.0;
  // Storeys loaded monotonically from rest to the initial drifts.
  for (int i = 0; i < n_ && !dyn_.linear(); ++i) {
    const RowStorey& st = storeys_[i];
    st.law->advance(st.p, StoreyState{}, 0.0, dyn_.drift(y_, 0, i), dyn_.storey[i]);
    for (int k = 0; k < st.law->continuous_states(); ++k)
      y_(at.storey_offset[i] + k) = dyn_.storey[i].x[k];
    storey_changed(i);
  }
  set_step_limits();
  // Contacts already closed at t = 0 (a negative gap or initial overlap) start at once, and
  // storeys already beyond a kink switch.
  for (int i = 0; i < ns_ && pounding; ++i)
    if (dyn_.penetration(y_, i) > 0.0) apply_event(i, t_, y_);
  rhs(t_, y_, k1_);
  for (int j = 0; j < switches_.storey_switches(); ++j)
    if (switch_at(ns_ + j, y_, k1_).value > 0.0) {
      apply_event(ns_ + j, t_, y_);
      rhs(t_, y_, k1_);
    }
  record(t_, y_, k1_);
}

// No contact active, and every site open by more than kTouching: floors touching at rest (a zero
// gap at t = 0) or just apart may close within a step by an amount the step's interpolant does
// not resolve; Dormand-Prince's steps, from its small initial step on, do.
bool Solver::contacts_open() const {
  constexpr double kTouching = 1e-9;  // [m]
  for (int i = 0; i < ns_ && dyn_.pounding(); ++i)
    if (dyn_.active[i] || dyn_.penetration(y_, i) > -kTouching) return false;
  return true;
}

// An exact step from the grid point t_ to the next (docs/integration.md, "Exact steps"); false
// (nothing changed) when the propagator is not ready or a switch fires inside the step: the
// Dormand-Prince path then takes the step and locates the event.
bool Solver::exact_step() {
  const LinearStep* L = exact_.propagator(dyn_, row_);
  if (!L) return false;
  const double t1 = exact_.next_point();
  const double h = t1 - t_;
  // ag over the step: linear between its ends (the grid holds every record sample); zero on a
  // step after the record's last sample (GroundMotion::at).
  double a0 = 0.0, a1 = 0.0;
  if (p_->motion && t_ + 0.5 * h < p_->motion->duration()) {
    a0 = p_->motion->at(std::max(t_, 0.0));
    a1 = p_->motion->at(std::min(t1, p_->motion->duration()));
  }
  y1_ = y_;
  linear_step_apply(*L, a0, a1, exact_.offsets_response(), y_.data(), y1_.data());
  rhs(t1, y1_, k7_);
  check_finite(t1, y1_);
  if (switches_.any(dyn_)) {
    double theta;
    if (find_event(y_, y1_, k1_, k7_, h, theta) >= 0) return false;
  }
  update_peaks(y_, y1_, k1_, k7_, h);
  y_.swap(y1_);
  k1_.swap(k7_);
  t_ = t1;
  exact_.advanced();
  ++rec_.result().steps;
  ++rec_.result().exact_steps;
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
  if (exact_.enabled()) {  // Dormand-Prince steps (through events) end on the exact steps' grid
    exact_.on_grid(t_);
    t_stop = std::min(t_stop, exact_.next_point());
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
  ++rec_.result().steps;
  record(t_, y_, k1_);
  if (!fixed_) {
    const double fac = en > 0 ? std::min(5.0, std::max(0.2, 0.9 * std::pow(en, -0.2))) : 5.0;
    double hn = hs * fac;
    if (hs < h_) hn = std::max(hn, h_);  // the step was cut short by a sample or the end
    h_ = std::min(h_max_, hn);
  }
}

// Free impacts (RowProblem::stop_after_separation): every contact has ended and all sites part.
bool Solver::separated() const {
  if (!p_->stop_after_separation || !any_contact_) return false;
  for (int i = 0; i < ns_; ++i)
    if (dyn_.active[i] || !(dyn_.penetration_rate(y_, i) < 0.0)) return false;
  return true;
}

void Solver::finish() {
  const StateLayout& at = dyn_.layout();
  rec_.finish(t_, y_.head(n_), y_.segment(n_, n_));
  RowResult& r = rec_.result();
  for (int i = 0; i < ns_; ++i) r.sites[i].impulse = y_(at.impulses + i);
  const double strain = dyn_.storey_energies(y_, r.hysteretic_energy);
  if (!track_) return;
  EnergyBalance& e = r.energy;
  for (int i = 0; i < n_; ++i) e.kinetic += 0.5 * std::pow(y_(n_ + i), 2) / row_.inv_mass(i);
  e.strain = strain;
  e.hysteretic = r.hysteretic_energy.sum();
  e.input = y_(at.energies);
  e.damping = y_(at.energies + 1);
  e.contact = y_(at.energies + 2);
}

RowResult Solver::run() {
  start();
  return advance();
}

RowResult Solver::advance() {
  const double t_end = p_->t_end;
  const bool events = switches_.any(dyn_);
  while (t_ < t_end * (1 - 1e-14)) {
    exact_.begin_iteration();
    if (rec_.result().steps + rec_.result().rejected > s_.max_steps)
      throw NumericalError("more than " + std::to_string(s_.max_steps) +
                           " steps by t = " + std::to_string(t_) + " s");
    if (exact_.enabled() && exact_.on_grid(t_) && !exact_.declined_here() &&
        exact_.next_point() <= t_end * (1 + 1e-14) && contacts_open()) {
      if (exact_step()) continue;
      exact_.decline();  // Dormand-Prince to the next grid point (rejections included)
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
        if (separated()) break;
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
  return rec_.result();
}

void Solver::record(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& dy) {
  // Absolute acceleration u'' + ag = M^-1 (P - C v - f): dy already holds u'' = that - ag.
  const double ag = dyn_.ag(t);
  rec_.accel_peaks(dy.data() + n_, ag);
  dyn_.contact_forces(y);
  const Eigen::VectorXd& force = dyn_.contact_force();
  for (int i = 0; i < ns_; ++i)
    if (dyn_.active[i]) rec_.force(i, force(i));
  if (rec_.keeps_history()) {
    Eigen::VectorXd shear(n_);
    for (int i = 0; i < n_; ++i) shear(i) = dyn_.storey_shear(y, i);
    rec_.history(t, y.head(n_), dy.segment(n_, n_), ag, force, shear);
  }
}

void Solver::update_peaks(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                          const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double h) {
  if (fork_armed_ && !fork_) fork_if_near_contact(y0, y1, h);
  rec_.peaks_over_step(y0, y1, dy0, dy1, h);
  const bool pounding = dyn_.pounding();
  for (int i = 0; i < ns_; ++i) {
    if (!dyn_.active[i]) continue;
    const Hermite c{dyn_.penetration(y0, i), dyn_.penetration(y1, i),
                    h * dyn_.penetration_rate(y0, i), h * dyn_.penetration_rate(y1, i)};
    rec_.penetration(i, c.max_over_step());
  }
  // Free run: the peak approach u_L - u_R of each site from the same interpolant the contact
  // events are located on (find_event), so that a pounding run of this motion touches at a
  // site exactly when this peak exceeds its gap (up to the location tolerance).
  for (int i = 0; i < ns_ && !pounding; ++i) {
    const auto& s = row_.sites[i];
    const Hermite c{y0(s.dof_left) - y0(s.dof_right), y1(s.dof_left) - y1(s.dof_right),
                    h * dyn_.penetration_rate(y0, i), h * dyn_.penetration_rate(y1, i)};
    rec_.approach_over_step(i, c);
  }
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

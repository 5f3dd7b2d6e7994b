// One run of a building row (solver/row_run.hpp): start, steps, exact steps, recording, the end.
#include "solver/row_run.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include "core/error.hpp"

namespace pound::detail {

RowRun::RowRun(const RowProblem& p, const IntegratorSettings& s)
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
      dyn_(row_, storeys_, track_, p.ground),
      switches_(row_, storeys_),
      rec_(row_, storeys_, !p.laws.empty(), p.record_history) {
  rec_.set_collapse(storeys_, p.collapse_drift_ratio);
  if (!p.laws.empty() && static_cast<int>(p.laws.size()) != ns_)
    throw std::logic_error("one contact law per site expected");
  dyn_.set_contacts(&p.laws);
  if (!p.laws.empty()) dyn_.set_force_cap(p.force_cap);
  step_a0_.assign(ExactSteps::ground_inputs(dyn_), 0.0);
  step_a1_ = step_a0_;
  false_alarm_.assign(2 * ns_ + switches_.storey_switches(), 0);
  work_.resize(dyn_.layout().size);
}

RowRun::RowRun(const RowRun& free, const RowProblem& pounding) : RowRun(free) {
  if (static_cast<int>(pounding.laws.size()) != ns_)
    throw std::logic_error("one contact law per site expected");
  p_ = &pounding;
  dyn_.set_contacts(&pounding.laws);
  dyn_.set_force_cap(pounding.force_cap);
  fork_to_ = nullptr;
  fork_armed_ = false;
  fork_.reset();
  watch_ = nullptr;
  exact_.undo_iteration();
  rec_.contacts_on();
}

// Called with the step (t_, y_) -> (t_ + h, y1) about to be accepted, before it changes anything
// but scratch: forks the pounding run when a site's gap function, on the interpolant the contact
// events are located on (find_event), rises above -kForkMargin in the step.
void RowRun::fork_if_near_contact(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, double h) {
  for (int i = 0; i < ns_; ++i) {
    const Hermite c{dyn_.penetration(y0, i) + kForkMargin, dyn_.penetration(y1, i) + kForkMargin,
                    h * dyn_.penetration_rate(y0, i), h * dyn_.penetration_rate(y1, i)};
    if (c.upper_bound() > 0.0 && c.max_over_step() > 0.0) {
      fork_ = std::make_shared<RowRun>(*this, *fork_to_);
      return;
    }
  }
}

// After storey `dof` changed branch: its line (piecewise-linear rows), safe interval and the
// exact steps' stiffness.
void RowRun::storey_changed(int dof) {
  dyn_.storey_changed(dof);
  exact_.invalidate();
  switches_.storey_changed(dof, dyn_.storey[dof]);
}

// The RMS norm of the local error estimate, each entry against atol + rtol max(|y0|, |y1|)
// (Hairer, Norsett & Wanner I, II.4, (4.10)-(4.11)); rows with flexible bases: error_norm_on_soil.
double RowRun::error_norm(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                          const Eigen::VectorXd& err) const {
  if (!base_entries_.empty()) return error_norm_on_soil(y0, y1, err);
  double sum = 0.0;
  const int m = dyn_.layout().tested();
  for (int i = 0; i < m; ++i) {
    const double sc = s_.atol + s_.rtol * std::max(std::fabs(y0(i)), std::fabs(y1(i)));
    const double r = err(i) / sc;
    sum += r * r;
  }
  return std::sqrt(sum / m);
}

// The norm on a row with flexible bases (issue 38): the floors' and storey states' entries as in
// error_norm; each base DOF's error measured by what it does to its building's floors, in their
// scale (Hairer, Norsett & Wanner I, II.4: sc_i is the entry's scale; here the base's entries
// take the floors' unit and scale). The floors' displacements are measured from the ground and
// carry the base's motion; a sway error e moves the first storey's deformation by e, a rotation
// error by h e at each storey, H e at the roof; a velocity error e_v moves its DOF by about
// e_v tau before the DOF's own spring or dashpot takes it back (tau = 1 / max(C/M, sqrt(K/M))).
// So r = wu e_u / sc and wv e_v / sc with sc = atol + rtol max(the building's largest floor
// |u|, wu |u_d|) [m]. The divisor stays the count of tested entries.
double RowRun::error_norm_on_soil(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                                  const Eigen::VectorXd& err) const {
  double sum = 0.0;
  const int m = dyn_.layout().tested();
  auto own = [&](int i) {
    const double sc = s_.atol + s_.rtol * std::max(std::fabs(y0(i)), std::fabs(y1(i)));
    const double r = err(i) / sc;
    sum += r * r;
  };
  for (int i = 0; i < row_.floors; ++i) own(i);
  for (int i = n_; i < n_ + row_.floors; ++i) own(i);
  for (int i = 2 * n_; i < m; ++i) own(i);
  // The floors' largest |u| once per building (its sway and rotation entries share the range).
  int first = -1, end = -1;
  double floors = 0.0;  // [m]
  for (const BaseEntry& b : base_entries_) {
    if (b.first != first || b.end != end) {
      first = b.first, end = b.end, floors = 0.0;
      for (int i = first; i < end; ++i)
        floors = std::max(floors, std::max(std::fabs(y0(i)), std::fabs(y1(i))));
    }
    const double scale = std::max(b.wu * std::max(std::fabs(y0(b.d)), std::fabs(y1(b.d))), floors);
    const double sc = s_.atol + s_.rtol * scale;
    const double ru = b.wu * err(b.d) / sc, rv = b.wv * err(n_ + b.d) / sc;
    sum += ru * ru + rv * rv;
  }
  return std::sqrt(sum / m);
}

// The base entries of the error test and the dashpots' bound on the explicit steps (issue 38),
// once per run from the row's data; rows on fixed bases keep neither.
void RowRun::set_base_errors() {
  base_entries_.clear();
  h_explicit_ = std::numeric_limits<double>::infinity();
  // (The IMEX pair keeps each entry's own scale: its lost order shows in the base velocities'
  // estimate, docs/speed.md "IMEX steps on soil".)
  if (!s_.base_error_by_floors || fixed_ || !implicit_.empty()) return;
  const auto& qs = dyn_.quasi_static();
  double fastest = 0.0;  // the largest C_dd / M_d of a base DOF with mass and its velocity [1/s]
  std::vector<std::pair<int, int>> bases;  // (base DOF, its building); none on fixed bases
  for (std::size_t b = 0; b < row_.sway.size(); ++b)
    for (int d : {row_.sway[b], b < row_.rot.size() ? row_.rot[b] : -1})
      if (d >= 0) bases.emplace_back(d, static_cast<int>(b));
  for (const auto& [d, b] : bases) {
    BaseEntry e{d, n_, 0, 1.0, 0.0};
    double height = 0.0;  // [m]
    for (int i = 0; i < row_.floors; ++i)
      if (row_.building_of[i] == b)
        e.first = std::min(e.first, i), e.end = std::max(e.end, i + 1), height += storeys_[i].p.h;
    if (e.end <= e.first) e.first = e.end = 0;  // a base without floors: its own scale only
    if (d == row_.rot[b]) e.wu = height;
    const double im = row_.inv_mass(d);
    const bool own_velocity = im != 0.0 && std::find(qs.begin(), qs.end(), d) == qs.end();
    if (own_velocity) {
      const double lambda = std::max(row_.C(d, d), 0.0) * im;
      const double omega = std::sqrt(std::max(row_.K(d, d), 0.0) * im);
      const double rate = std::max(lambda, omega);
      e.wv = rate > 0.0 ? e.wu / rate : e.wu;
      fastest = std::max(fastest, lambda);
    }
    base_entries_.push_back(e);
  }
  // Dormand-Prince is stable for -3.3 < h lambda < 0 on the real axis (Hairer & Wanner II,
  // IV.2, Fig. 2.1): with its entries weighed by their effect on the floors, the error test no
  // longer holds a base's fast real root inside it, this bound does (3.0: a margin for the
  // coupling's shift of the diagonal rate).
  constexpr double kExplicitBound = 3.0;
  if (fastest > 0.0) h_explicit_ = kExplicitBound / fastest;
}

// The largest step, the record spacing, and exact steps for rows that are linear between events
// (no storey state integrated, no energy balance), on a grid of h_max that holds every record
// sample.
void RowRun::set_step_limits() {
  // T_min of the modes that oscillate (an overdamped raft's mode needs no T / 20 steps: its
  // roots are real; structure/building_row.hpp step_period). A base whose roots are faster than
  // any step could follow is condensed to its quasi-static limit (issue 38;
  // RowDynamics::condense_stiff_roots; the exact steps' propagators do not know it:
  // Dormand-Prince steps the row, at the buildings' own rates).
  double tmin_period = step_period(row_);
  if (std::any_of(row_.sway.begin(), row_.sway.end(), [](int d) { return d >= 0; }) ||
      std::any_of(row_.rot.begin(), row_.rot.end(), [](int d) { return d >= 0; }))
    tmin_period = dyn_.condense_stiff_roots(s_.stiff_root, tmin_period);
  h_max_ = s_.h_max > 0 ? s_.h_max : tmin_period / 20.0;
  rec_dt_ = p_->ground ? p_->ground->dt() : 0.0;
  if (s_.h_max <= 0 && rec_dt_ > 0) h_max_ = std::min(h_max_, rec_dt_);
  const bool h_max_known = std::isfinite(h_max_);
  if (!h_max_known) h_max_ = std::max(p_->t_end, 1e-6);
  if (s_.exact_free && !fixed_ && !track_ && h_max_known && (dyn_.linear() || dyn_.affine()) &&
      dyn_.layout().storey_states == 0 && dyn_.quasi_static().empty())
    exact_.enable(row_, h_max_, rec_dt_, p_->exact_cache);
  implicit_ = ImplicitSet{};
  // The IMEX pair where the dashpots are too stiff for Dormand-Prince (imex_bases: beyond its
  // stability bound; otherwise where lambda h_max reaches imex_from), from the row's data.
  if (!fixed_ && h_max_known)
    implicit_ =
        stiff_base_dashpots(row_, dyn_, h_max_, s_.imex_bases ? kDormandPrinceBound : s_.imex_from);
  if (fixed_ && !(s_.dt > 0)) throw InputError("fixed-step integration needs dt > 0");
  set_base_errors();
  h_ = fixed_ ? s_.dt : std::min(std::min(h_max_, h_explicit_), 1e-4);
}

// Initial state, step limits and the switches already on at t = 0.
void RowRun::start() {
  const StateLayout& at = dyn_.layout();
  switches_.reset();
  for (auto* v : {&y1_, &err_, &k1_, &k7_, &ytry_, &etry_, &ktry_}) v->resize(at.size);
  y_ = Eigen::VectorXd::Zero(at.size);
  if (p_->u0.size()) y_.head(n_) = p_->u0;
  if (p_->v0.size()) y_.segment(n_, n_) = p_->v0;
  dyn_.set_ground_states(t_, y_);
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

void RowRun::resume(double t, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                    const std::vector<StoreyState>& storeys, const double* energies) {
  const StateLayout& at = dyn_.layout();
  if (!resumed_) {
    switches_.reset();
    for (auto* w : {&y_, &y1_, &err_, &k1_, &k7_, &ytry_, &etry_, &ktry_}) w->setZero(at.size);
    set_step_limits();
    resumed_ = true;
  }
  t_ = t;
  y_.setZero();
  y_.head(n_) = u;
  y_.segment(n_, n_) = v;
  dyn_.set_ground_states(t_, y_);
  for (int i = 0; i < n_; ++i) {
    dyn_.storey[i] = storeys[i];
    for (int k = 0; k < storeys_[i].law->continuous_states(); ++k)
      y_(at.storey_offset[i] + k) = storeys[i].x[k];
    if (!dyn_.linear()) storey_changed(i);
  }
  if (track_ && energies)
    for (int k = 0; k < 3; ++k) y_(at.energies + k) = energies[k];
  rhs(t_, y_, k1_);
  // Storeys already beyond a kink switch (as at the start).
  for (int j = 0; j < switches_.storey_switches(); ++j)
    if (switch_at(ns_ + j, y_, k1_).value > 0.0) {
      apply_event(ns_ + j, t_, y_);
      rhs(t_, y_, k1_);
    }
}

void RowRun::storey_states(std::vector<StoreyState>& out) const {
  out.assign(dyn_.storey.begin(), dyn_.storey.end());
  for (int i = 0; i < n_; ++i)
    if (const double* x = dyn_.continuous_states(y_, i))
      for (int k = 0; k < storeys_[i].law->continuous_states(); ++k) out[i].x[k] = x[k];
}

// No contact active, and every site open by more than kTouching: floors touching at rest (a zero
// gap at t = 0) or just apart may close within a step by an amount the step's interpolant does
// not resolve; Dormand-Prince's steps, from its small initial step on, do.
bool RowRun::contacts_open() const {
  constexpr double kTouching = 1e-9;  // [m]
  for (int i = 0; i < ns_ && dyn_.pounding(); ++i)
    if (dyn_.active[i] || dyn_.penetration(y_, i) > -kTouching) return false;
  return true;
}

// An exact step from the grid point t_ to the next (docs/integration.md, "Exact steps"); false
// (nothing changed) when the propagator is not ready or a switch fires inside the step: the
// Dormand-Prince path then takes the step and locates the event.
bool RowRun::exact_step() {
  if (!exact_.ready(dyn_, row_)) return false;
  const double t1 = exact_.next_point();
  const double h = t1 - t_;
  // Each channel's ag over the step: linear between its ends (the grid holds every record
  // sample); zero on a step after the channel's last sample (GroundMotion::at).
  const int m = ExactSteps::ground_inputs(dyn_);
  for (int c = 0; c < m; ++c) {
    step_a0_[c] = step_a1_[c] = 0.0;
    if (!p_->ground) continue;
    const GroundTrace& g = p_->ground->trace(c);
    if (t_ + 0.5 * h < g.duration()) {
      step_a0_[c] = g.acc(std::max(t_, 0.0));
      step_a1_[c] = g.acc(std::min(t1, g.duration()));
    }
  }
  y1_ = y_;
  exact_.step(m, step_a0_.data(), step_a1_.data(), y_, y1_);
  dyn_.set_ground_states(t1, y1_);
  if (exact_.has_rates())
    exact_rates(t1);
  else
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

// The derivative k7_ at an exact step's end y1_ (time t1 [s]) from the blocks' own
// z' = A z + B w (ExactSteps::rates; issue 38) instead of rhs: no contact is active
// (contacts_open), no storey state or energy is integrated, no base DOF is massless or condensed
// (exact steps, has_rates()), so the rest of dy is the impulses' zero rates and the ground
// states' ug' = vg, vg' = ag.
void RowRun::exact_rates(double t1) {
  const StateLayout& at = dyn_.layout();
  const double* agc = dyn_.ground_channel_acc(t1);
  exact_.rates(dyn_, agc, y1_, k7_);
  for (int i = 0; i < ns_; ++i) k7_(at.impulses + i) = 0.0;
  for (std::size_t c = 0; c < at.ground_offset.size(); ++c) {
    const int g = at.ground_offset[c];
    if (g < 0) continue;
    k7_(g) = y1_(g + 1);
    k7_(g + 1) = agc[c];
  }
}

// The next step ends at the next record sample, grid point or the end t_end [s].
double RowRun::next_stop(double t_end) {
  double t_stop = t_end;
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
void RowRun::accept(double hs, double en, double t_stop) {
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
    h_ = std::min(std::min(h_max_, h_explicit_), hn);
  }
}

// Free impacts (RowProblem::stop_after_separation): every contact has ended and all sites part.
bool RowRun::separated() const {
  if (!p_->stop_after_separation || !any_contact_) return false;
  for (int i = 0; i < ns_; ++i)
    if (dyn_.active[i] || !(dyn_.penetration_rate(y_, i) < 0.0)) return false;
  return true;
}

EnergyBalance RowRun::energy_now() const {
  const StateLayout& at = dyn_.layout();
  EnergyBalance e;
  Eigen::VectorXd hysteretic;
  const double strain = dyn_.storey_energies(y_, hysteretic);
  for (int i = 0; i < n_; ++i)  // (a massless base DOF has none)
    if (row_.inv_mass(i) != 0.0) e.kinetic += 0.5 * std::pow(y_(n_ + i), 2) / row_.inv_mass(i);
  e.strain = strain;
  e.hysteretic = hysteretic.sum();
  e.input = y_(at.energies);
  e.damping = y_(at.energies + 1);
  e.contact = y_(at.energies + 2);
  if (dyn_.capped()) {  // the work F ddelta of the crushing phases is the crushing's, cap x c
    for (int i = 0; i < ns_; ++i) e.crushing += dyn_.force_cap() * dyn_.indentation(y_, i);
    e.contact -= e.crushing;
  }
  return e;
}

void RowRun::finish() {
  const StateLayout& at = dyn_.layout();
  rec_.finish(t_, y_.head(n_), y_.segment(n_, n_));
  RowResult& r = rec_.result();
  for (int i = 0; i < ns_; ++i) r.sites[i].impulse = y_(at.impulses + i);
  if (dyn_.capped())
    for (int i = 0; i < ns_; ++i) r.sites[i].crush = dyn_.indentation(y_, i);
  dyn_.storey_energies(y_, r.hysteretic_energy);
  if (!track_) return;
  r.energy = rec_.final_energy(energy_now());
}

bool RowRun::on_collapse() {
  std::vector<int> hold;
  const bool stop = rec_.apply_collapse_policy(
      track_, [this] { return energy_now(); }, hold);
  if (dyn_.pounding()) return stop;
  // The pounding run must stop at this collapse: if it has not forked yet, it is solved alone.
  if (fork_armed_ && !fork_) {
    fork_armed_ = false;
    own_pounding_run_ = true;
  }
  for (int i : hold) {
    dyn_.hold(i);
    y_(n_ + i) = 0.0;
  }
  exact_.disable();  // the propagators would move the held floors
  rhs(t_, y_, k1_);
  return stop;
}

RowResult RowRun::run() {
  start();
  return advance();
}

RowResult RowRun::advance() {
  advance_until(p_->t_end);
  finish();
  return rec_.result();
}

bool RowRun::advance_until(double t_end, bool one_step) {
  const bool events = switches_.any(dyn_);
  const double t_begin = t_;
  while (t_ < t_end * (1 - 1e-14)) {
    if (one_step && t_ > t_begin) return false;  // advance_step: one step taken
    if (rec_.take_new_collapses() > 0 && on_collapse()) return true;
    exact_.begin_iteration();
    if (rec_.result().steps + rec_.result().rejected > s_.max_steps)
      throw NumericalError("more than " + std::to_string(s_.max_steps) +
                           " steps by t = " + std::to_string(t_) + " s");
    if (exact_.enabled() && exact_.on_grid(t_) && !exact_.declined_here() &&
        exact_.next_point() <= t_end * (1 + 1e-14) && contacts_open()) {
      if (exact_step()) continue;
      exact_.decline();  // Dormand-Prince to the next grid point (rejections included)
    }
    const double t_stop = next_stop(t_end);
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
      Located l = locate(ev, theta, hs, en, trial_failed);
      // A crushing switch's crossing may be a false alarm (its interpolant's slopes come from
      // finite differences, and nlve's force has an infinite slope at delta = 0): it must not
      // hide a real switch later in the step, which would then be applied late. Look again
      // without it (capped runs only: no other switch changes this path).
      while (l == Located::none && !trial_failed && ev >= switches_.first_crush()) {
        false_alarm_[ev] = 1;
        ev = find_event(y_, y1_, k1_, k7_, hs, theta, &false_alarm_);
        if (ev < 0) break;
        l = locate(ev, theta, hs, en, false);
      }
      if (dyn_.capped()) std::fill(false_alarm_.begin(), false_alarm_.end(), 0);
      if (l == Located::retry) continue;
      if (l == Located::applied) {
        if (separated()) return false;
        continue;
      }
      if (trial_failed) {  // false alarm on a rejected trial
        reject(hs, en);
        continue;
      }
    }
    accept(hs, en, t_stop);
  }
  return false;  // collapses of the last step are left to the caller (take_new_collapses)
}

void RowRun::record(double t, const Eigen::VectorXd& y, const Eigen::VectorXd& dy) {
  // Absolute acceleration u'' + ag = M^-1 (P - C v - f): dy already holds u'' = that - ag.
  const double* ag = dyn_.ground_acc(t);
  rec_.accel_peaks(dy.data() + n_, ag);
  dyn_.contact_forces(y);
  const Eigen::VectorXd& force = dyn_.contact_force();
  for (int i = 0; i < ns_; ++i)
    if (dyn_.active[i]) rec_.force(i, force(i));
  for (int i = 0; i < ns_ && !dyn_.slab_sites(); ++i) {  // column sites only
    const ContactSite& s = row_.sites[i];
    if (s.struck_dof >= 0)
      rec_.column_shear(i, column_shear_demand(s, dyn_.storey_shear(y, s.struck_dof), force(i)));
  }
  if (watch_)
    for (std::size_t k = 0; k < watch_->shear_dofs.size(); ++k)
      watch_->shear(static_cast<int>(k), dyn_.storey_shear(y, watch_->shear_dofs[k]));
  if (rec_.keeps_history()) {
    Eigen::VectorXd shear(n_);
    for (int i = 0; i < n_; ++i) shear(i) = dyn_.storey_shear(y, i);
    rec_.history(t, y.head(n_), dy.segment(n_, n_), ag, force, shear);
  }
}

void RowRun::update_peaks(const Eigen::VectorXd& y0, const Eigen::VectorXd& y1,
                          const Eigen::VectorXd& dy0, const Eigen::VectorXd& dy1, double h) {
  if (fork_armed_ && !fork_) fork_if_near_contact(y0, y1, h);
  if (watch_) watch_->add_step(t_, h, y0, y1, n_);
  rec_.peaks_over_step(y0, y1, dy0, dy1, t_, h);
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
  // The slab-only sites' path (RowDynamics::slab_sites) chosen once per step, not per site.
  auto approaches = [&](auto slabs) {
    for (int i = 0; i < ns_; ++i) {
      const Hermite c{dyn_.approach(y0, i, slabs), dyn_.approach(y1, i, slabs),
                      h * dyn_.penetration_rate(y0, i, slabs),
                      h * dyn_.penetration_rate(y1, i, slabs)};
      rec_.approach_over_step(i, c);
    }
  };
  if (pounding) return;
  if (dyn_.slab_sites())
    approaches(std::true_type{});
  else
    approaches(std::false_type{});
}

}  // namespace pound::detail

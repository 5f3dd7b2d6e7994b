// Steps through contacts of a damped Sears run (sears/sears_row_run.hpp): Th. 8.8 made implicit
// in the contact forces, longer steps through smooth contact forces, sleeping slabs and yielding
// storeys (docs/speed.md).
#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "sears/sears_row_run.hpp"
#include "sears/site_forces.hpp"

namespace pound::sears::detail {

namespace {
// sum |w_k x_k| over the DOFs of a site's point [m] (a slab: |x| of its floor).
double magnitude(const SitePoint& pt, const Eigen::VectorXd& x) {
  double m = std::fabs(pt.weight[0] * x(pt.dof[0]));
  for (int k = 1; k < pt.count; ++k) m += std::fabs(pt.weight[k] * x(pt.dof[k]));
  return m;
}
}  // namespace

__attribute__((always_inline)) inline void SearsRowRun::update_guards() {  // slab_only once
  if (slab_only)
    for (int s = 0; s < ns; ++s) guarded[s] = site_asleep(s, true);
  else
    for (int s = 0; s < ns; ++s) guarded[s] = site_asleep(s, false);
}

void SearsRowRun::fall_asleep() {  // at a point of the coarse grid, before fine steps
  for (int k = 0; k < nf; ++k) {
    const int sl = layout.floors[k].site_left, sr = layout.floors[k].site_right;
    const bool free_slab = (sl < 0 || (F(sl) == 0.0 && !in_contact[sl])) &&
                           (sr < 0 || (F(sr) == 0.0 && !in_contact[sr]));
    if (free_slab) slabs.fall_asleep(k, hc);
  }
  update_guards();
}

void SearsRowRun::finish_sleep() {  // at the next point of the coarse grid
  slabs.finish_sleep(stepping.ratio);
  update_guards();
}

// End-of-step overlaps without contact forces, delta_pred; for a guarded site an upper bound.
void SearsRowRun::predict_overlaps() {
  slabs.predict(begin, op);
  if (slab_only)
    predict_overlaps_of<true>();
  else
    predict_overlaps_of<false>();
}

template <bool Slabs>
void SearsRowRun::predict_overlaps_of() {
  for (int s = 0; s < ns; ++s) {
    const int l = left_slab(s), r = right_slab(s);  // -1: a struck column point, no bar
    const ContactSite& site = assembled.sites[s];   // Slabs: the sides are the slabs' floors
    const double wl = slab(Slabs, l) ? slabs.predicted_right_upper(l) : 0.0;
    const double wr = slab(Slabs, r) ? slabs.predicted_left_lower(r) : 0.0;
    const double ul = Slabs ? u_hat(site.dof_left) : left_point(s).of(u_hat.data());
    const double ur = Slabs ? u_hat(site.dof_right) : right_point(s).of(u_hat.data());
    delta_pred(s) = ul - ur + wl - wr - gap(s) + gd_next[s];
  }
}

// guards_hold's test (Slabs = slab_only: a slab's |1 x u| is |u|, so the same scale).
template <bool Slabs>
bool SearsRowRun::guards_hold_of() {
  bool hold = true;
  for (int s = 0; s < ns; ++s) {
    if (!guarded[s]) continue;
    const int kl = left_slab(s), kr = right_slab(s);  // -1: a struck column point, no bar
    const ContactSite& site = assembled.sites[s];
    const double bound_end = delta_pred(s) - ops[op].S.row(s).dot(F_next);
    double scale = Slabs ? std::fabs(u_hat(site.dof_left)) + std::fabs(u_hat(site.dof_right))
                         : magnitude(left_point(s), u_hat) + magnitude(right_point(s), u_hat);
    scale += std::fabs(gap(s));
    if (slab(Slabs, kl)) scale += std::fabs(slabs.asleep_faces(kl).right);
    if (slab(Slabs, kr)) scale += std::fabs(slabs.asleep_faces(kr).left);
    if (slab(Slabs, kl)) scale += slabs.asleep_bound(kl);
    if (slab(Slabs, kr)) scale += slabs.asleep_bound(kr);
    if (bound_end < -kGuardRoundOff * scale) continue;
    hold = false;
    if (slab(Slabs, kl) && slabs.asleep(kl)) slabs.wake(kl);
    if (slab(Slabs, kr) && slabs.asleep(kr)) slabs.wake(kr);
  }
  return hold;
}

// True when every guarded site's end-of-step overlap bound is below zero (with a margin for
// round-off); otherwise wakes the sleeping slabs of the failing sites and returns false.
bool SearsRowRun::guards_hold() {
  const bool hold = slab_only ? guards_hold_of<true>() : guards_hold_of<false>();
  if (!hold) {
    update_guards();
    for (int s = 0; s < ns; ++s)
      if (!guarded[s]) delta(s) = overlap_now(s);  // exact again (was stale while guarded)
  }
  return hold;
}

long SearsRowRun::room(long i, const Eigen::VectorXd& f) const {
  bool cross = longest > 1 && slabs.asleep_count() == 0 && per_sample > 0;
  for (int k = 0; k < nf && cross; ++k) {
    const int sl = layout.floors[k].site_left, sr = layout.floors[k].site_right;
    cross = (sl >= 0 && f(sl) > 0.0) || (sr >= 0 && f(sr) > 0.0);
  }
  const long r = cross ? per_sample - i % per_sample : stepping.ratio - i % stepping.ratio;
  return std::min(r, steps - i);
}

long SearsRowRun::trial_multiple(long i, const Eigen::VectorXd& f) const {
  const long r = room(i, f);
  if (r <= m_next) return r;
  const long k = (r + m_next - 1) / m_next;  // steps to cover the room
  return (r + k - 1) / k;
}

// One step of Th. 8.8 made implicit in the contact forces (sears_simulation.hpp), of m fine
// steps: m = 1 unless the contact forces are smooth enough for a longer step (docs/speed.md,
// "Longer steps through smooth contact forces"). A longer step is solved first (nothing of the
// state changes but sleeping slabs woken to the step's start) and taken only if the forces'
// linear interpolation error over it stays within model.contact_step_tolerance; otherwise the
// step is solved again shorter.
long SearsRowRun::fine_step(long i) {
  long m = trial_multiple(i, F);
  double worst = 0.0;
  loads(F, begin);
  for (;;) {
    op = static_cast<int>(m - 1);
    const StepOperators& o = ops[op];
    floors.predict(o.h, o.nm, ag_at((i + m) * dt), a_next);
    ground_at((i + m) * dt, gd_next, gv_next);
    hold_still(a_next);
    if (storeys.linear()) {
      u_hat = u + o.h * v + (0.25 * o.h * o.h) * (acc + a_next);
      F_next.setZero();
      if (p.contacts && ns > 0) {
        F_next = F;  // warm start (zero at guarded sites)
        do {
          predict_overlaps();
          solve_site_forces(layout.laws, o.S, delta_pred, guarded, F_next);
        } while (slabs.asleep_count() > 0 && !guards_hold());
      }
    } else {
      storey_pass(o.h, o.R, true);
    }
    worst = step_error(m);
    if (m == 1 || worst <= 1.0) break;
    ++out.counts.long_step_rejections;
    // The error grows as h^2.
    m = std::max(1L, std::min(m - 1, static_cast<long>(m * kStepSafety / std::sqrt(worst))));
  }
  const StepOperators& o = ops[op];
  if (ns > 0) a_next.noalias() -= o.H * F_next;
  floors.update(o.h, a_next);
  if (!storeys.linear()) storeys.commit();
  loads(F_next, end);
  // The next step's multiple (the error grows as h^2); the banks predict for it.
  m_next = worst > 0.0 ? static_cast<long>(m * kStepSafety / std::sqrt(worst)) : longest;
  m_next = std::clamp(m_next, 1L, longest);
  step_slabs(i, m);
  if (m > 1) ++out.counts.long_steps;
  F_prev = F;
  h_prev = o.h;
  return m;
}

// The awake slabs through the step of m fine steps from t = i dt just taken; the banks predict
// for the next step's multiple.
void SearsRowRun::step_slabs(long i, long m) {
  const long m_after = i + m < steps ? trial_multiple(i + m, F_next) : 1;
  for (int k = 0; k < nf; ++k) {
    if (slabs.asleep(k))
      slabs.skip(k, m);
    else
      slabs.step(k, begin[k], end[k], op, static_cast<int>(m_after - 1));
  }
}

double SearsRowRun::step_error(long m) {
  const double tol = model.contact_step_tolerance;
  if (longest == 1 || !(tol > 0.0)) return 0.0;
  return slab_only ? step_error_of<true>(m, tol) : step_error_of<false>(m, tol);
}

template <bool Slabs>
double SearsRowRun::step_error_of(long m, double tol) {
  const double h = m * dt;
  double w = 0.0;
  for (int s = 0; s < ns; ++s) {
    // A site whose slabs all sleep (both, or a column site's one) keeps F = 0 by their bound
    // over the whole coarse interval.
    // A contact that starts or ends within the step, any other site without force (a contact
    // could start and end within a longer step unseen, as within a coarse step without its
    // bound; with one slab awake the guard is checked at the step's end only), or no previous
    // step: the fine step.
    if (site_all_asleep(s, Slabs)) continue;
    const double f0 = F(s), f1 = F_next(s), fm = F_prev(s);
    if (f0 == 0.0 || f1 == 0.0 || !(h_prev > 0.0)) return kNoLongStep;
    // F[t_i-1, t_i, t_i+1] = F''/2; a quadratic departs from its chord over h by F'' h^2 / 8.
    const double d2 = 2.0 * ((f1 - f0) / h - (f0 - fm) / h_prev) / (h + h_prev);
    w = std::max(w, std::fabs(d2) * h * h / (8.0 * tol * std::max(f0, f1)));
  }
  return w;
}

// The step with yielding storeys: a_next = a_hat + R r_next (and - H F_next), r_next from the
// storeys' return maps at the end-of-step displacements, iterated to a fixed point; with
// `contacts` the contact forces are solved again in every pass (warm started).
void SearsRowRun::storey_pass(double h, const Eigen::MatrixXd& R, bool contacts) {
  a_base = a_next;
  r_next = storeys.correction();
  F_next.setZero();
  if (contacts && p.contacts && ns > 0) F_next = F;  // warm start (zero at guarded sites)
  for (int pass = 0;; ++pass) {
    a_next = a_base;
    a_next.noalias() += R * r_next;
    hold_still(a_next);
    u_hat = u + h * v + (0.25 * h * h) * (acc + a_next);
    if (contacts && p.contacts && ns > 0) {
      do {
        predict_overlaps();
        solve_site_forces(layout.laws, ops[op].S, delta_pred, guarded, F_next);
      } while (slabs.asleep_count() > 0 && !guards_hold());
      u_end = u_hat;
      u_end.noalias() -= (0.25 * h * h) * (ops[op].H * F_next);
    } else {
      u_end = u_hat;
    }
    if (storeys.tangent_damping()) {  // the end-of-step velocities, contact forces included
      v_end = v + (0.5 * h) * (acc + a_next);
      if (contacts && p.contacts && ns > 0) v_end.noalias() -= (0.5 * h) * (ops[op].H * F_next);
    }
    if (storeys.trial(u, u_end, v_end, r_next)) return;
    ++out.counts.storey_iterations;
    if (pass == 50)
      throw NumericalError(
          "damped Sears model: the yielding storeys did not converge in 50 passes of a step");
  }
}

}  // namespace pound::sears::detail

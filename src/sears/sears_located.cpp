// Stretches on the lumped solver's steps where the translation bound is not proved (issue 38;
// docs/speed.md, "The damped Sears path"): a massless base (first-order DOFs) under a building
// with tangent-stiffness damping or P-Delta (TranslationBound::valid() false). Instead of
// proving before a step of h_L that no contact can begin in it, each step is taken and then
// tested on its own dense output: per site s, with the floors' approach x = u_L - u_R (SitePoint
// sides) and the sites' relative ground displacement ug_L - ug_R,
//     overlap(t0 + tau) <= delta_s(t0) + [x(t0 + tau) - x(t0)] + [ug(t0 + tau) - ug(t0)]
//                          + B_L + B_R,
// B the slabs' face_motion_bound(h_L) (modal_bank.hpp: free modes only lose energy, so it holds
// for every later free step without any bound on the buildings), x on the quintic Hermite of
// its values, rates and accelerations at the step's ends (solver/hermite.hpp; sixth order, the
// interpolant the lumped solver's peaks are taken on) and ug on the cubic of its values and
// rates (exact: the ground's acceleration is linear between record samples, on which h_L ends).
// The step is kept when that bound plus a margin stays below zero at every site; the margin is
// the lumped fork's 1 um (RowRun::kForkMargin) plus a fine step's worth of approach, dt times
// the larger of the approach rates at the step's ends, which covers the interpolant's error and
// the difference between the lumped and the Newmark steps near a touch. Otherwise the step is
// undone (the recorder restored to the step's start, the run's state never left it) and the
// fine steps re-take it from its start, a point of the fine grid.
#include <algorithm>
#include <cmath>

#include "sears/sears_row_run.hpp"
#include "solver/hermite.hpp"

namespace pound::sears::detail {

namespace {
constexpr double kLocatedMargin = 1e-6;  // [m], RowRun::kForkMargin
}  // namespace

// The start of a located stretch: no site in contact or loaded, every overlap negative (a
// dormant slab's site with its exact overlap), and the slabs' bound over h_L.
bool SearsRowRun::located_open() {
  for (int s = 0; s < ns; ++s) {
    auto open = [&] { return !in_contact[s] && F(s) == 0.0 && delta(s) < 0.0; };
    if (open()) continue;
    if (!site_dormant(s)) return false;
    wake_site(s);
    if (!open()) return false;
  }
  if (!lumped_bound_valid) {
    for (int k = 0; k < nf; ++k)
      lumped_bound[k] = slabs.bank(k).face_motion_bound(stepping.lumped_s());
    lumped_bound_valid = true;
  }
  return true;
}

// The test above on the step of h [s] from the run's state (u, v, acc, gd, gv, delta) to the
// stretch's (lu, lv, la) at t_next [s].
bool SearsRowRun::located_clear(double h, double t_next) {
  ground_at(t_next, gd_next, gv_next);
  for (int s = 0; s < ns; ++s) {
    const SitePoint &l = left_point(s), &r = right_point(s);
    auto x = [&](const Eigen::VectorXd& q) { return l.of(q.data()) - r.of(q.data()); };
    const double x0 = x(u), r0 = x(v) + gv[s], r1 = x(lv) + gv_next[s];
    const QuinticHermite floor_part{0.0,       x(lu) - x0,     h * x(v),
                                    h * x(lv), h * h * x(acc), h * h * x(la)};
    const Hermite ground_part{0.0, gd_next[s] - gd[s], h * gv[s], h * gv_next[s]};
    const int sl = left_slab(s), sr = right_slab(s);
    const double margin = kLocatedMargin + dt * std::max(std::fabs(r0), std::fabs(r1)) +
                          (sl >= 0 ? lumped_bound[sl] : 0.0) + (sr >= 0 ? lumped_bound[sr] : 0.0);
    const bool differs = ground.differs(s);
    auto clear = [&](bool refine) {
      const double g =
          differs ? (refine ? ground_part.max_over_step() : ground_part.upper_bound()) : 0.0;
      const double f = refine ? floor_part.max_over_step() : floor_part.upper_bound();
      return delta(s) + std::max(0.0, f) + std::max(0.0, g) + margin < 0.0;
    };
    if (clear(false) || clear(true)) continue;
    if (!site_dormant(s)) return false;
    wake_site(s);  // its exact overlap at the step's start
    if (!clear(true)) return false;
  }
  return true;
}

// The lumped solver takes the floors over at the point i of the h_L grid: their state, the
// storeys' committed states and the energy terms so far.
void SearsRowRun::start_stretch(long i) {
  const double energy[3] = {e_input, e_damping, e_contact};
  lumped->resume(i * dt, u, v, storeys.committed_states(), energy);
  ++out.counts.lumped_stretches;
}

// From the point i of the h_L grid: steps of h_L on FreeStretches, each kept only when
// located_clear() shows it came nowhere near a contact, then recorded as lumped_stretch()
// records its steps. Returns the fine step index reached; a step that is not clear is re-taken
// by the fine steps, and no located stretch starts again at its start.
long SearsRowRun::located_stretch(long i) {
  const long per = stepping.lumped * stepping.ratio;  // fine steps per lumped step
  const double hl = stepping.lumped_s();
  start_stretch(i);
  lu.resize(n);
  lv.resize(n);
  la.resize(n);
  bool stop = false;
  while (!stop && i + per <= steps) {
    const double t_next = (i + per) * dt;
    save_recorder();
    stop = lumped->advance_to(t_next, rec);
    lumped->state(lu, lv, la);
    if (!located_clear(hl, t_next)) {
      restore_recorder();
      located_retry = i + 1;
      return i;
    }
    i += per;
    ++out.counts.lumped;
    for (int k = 0; k < nf; ++k) slabs.step_free(k, stepping.lumped);
    leave_stretch();
    record_sites(true, hl, t_next);
    record_peaks(true, ground.acc(t_next), t_next, hl);
    if (failure_check) check_failures(t_next);
    stop = stop || (rec.take_new_collapses() > 0 && on_collapse());
  }
  if (stop) rec.result().stopped = true;
  return i;
}

// The recorder at the step's start, its histories (which only grow) kept by their length.
void SearsRowRun::save_recorder() {
  History& h = rec.result().history;
  History kept = std::move(h);
  h = History{};
  if (rec_start)
    *rec_start = rec;
  else
    rec_start.emplace(rec);
  h = std::move(kept);
  rec_history = h.t.size();
}

void SearsRowRun::restore_recorder() {
  History kept = std::move(rec.result().history);
  rec = *rec_start;
  kept.t.resize(rec_history);
  for (auto* x : {&kept.u, &kept.a_abs, &kept.force, &kept.shear})
    if (x->size() > rec_history) x->resize(rec_history);
  rec.result().history = std::move(kept);
}

}  // namespace pound::sears::detail

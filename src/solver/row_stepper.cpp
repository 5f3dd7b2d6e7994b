// The lumped sample's two runs with the free run building by building (solver/row_stepper.hpp).
#include "solver/row_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "solver/hermite.hpp"
#include "solver/row_apart.hpp"
#include "solver/row_apart_parts.hpp"
#include "solver/row_run.hpp"

namespace pound {
namespace {

using detail::ApartPart;
using detail::ApartRow;
using detail::RowRun;

constexpr double kMargin = RowRun::fork_margin();  // [m]

// A point's displacement x [m] and velocity v [m/s] at t on the last step of a watch (its cubic
// Hermite, the interpolant contact events are located on); the watch holds a step (callers
// test).
void last_step_at(const detail::StepWatch& w, int point, double t, double& x, double& v) {
  const double* s = w.steps.data() + w.steps.size() - static_cast<std::size_t>(w.stride());
  detail::StepWatch::point_at(s, 2 + 4 * point, t, x, v);
}

// The row scheduler (docs/speed.md, "A row scheduler"): one RowRun per building, stepped in
// time order, the contact sites tested on each overlap of two buildings' steps, and the
// pounding run forked at the common time where a site first comes within the margin.
class RowStepper {
 public:
  RowStepper(const BuildingRow& row, const RowProblem& free, const RowProblem& pounding,
             const IntegratorSettings& s)
      : apart_(row, free), pounding_p_(pounding), s_(s), ra_(*free.row) {
    const std::size_t nb = apart_.parts.size();
    runs_.resize(nb);
    at_start_.resize(nb);
    stopped_.assign(nb, 0);
    for (std::size_t b = 0; b < nb; ++b) {
      runs_[b] = std::make_unique<RowRun>(apart_.parts[b].p, s);
      runs_[b]->watch(&apart_.parts[b].watch);
    }
    const double dt = free.ground ? free.ground->dt() : 0.0;  // steps end on every sample
    horizon_ = dt > 0 ? dt : free.t_end;
  }

  RunPair run(ForkStats& stats);

 private:
  int next_building() const;
  bool near_contact(int b) const;
  bool fires(int b, double ta) const;
  bool fork(double ta, ForkStats& stats);
  void side_now(int b, int point, double& x, double& v, double& a) const;

  ApartRow apart_;
  const RowProblem& pounding_p_;
  const IntegratorSettings& s_;
  const AssembledRow& ra_;
  double horizon_ = 0.0;  // the longest step a building can take [s]
  std::vector<std::unique_ptr<RowRun>> runs_;
  // Per building: its run at the start of its last step, kept where a site was within reach
  // of the margin there (near_contact); null elsewhere.
  std::vector<std::unique_ptr<RowRun>> at_start_;
  std::vector<char> stopped_;
  std::unique_ptr<RowRun> pounding_;
  ExactStepCache pounding_cache_;
};

// The building whose time is smallest among those not at the end (-1: none).
int RowStepper::next_building() const {
  int best = -1;
  for (std::size_t b = 0; b < runs_.size(); ++b) {
    if (stopped_[b] || runs_[b]->time() >= pounding_p_.t_end * (1 - 1e-14)) continue;
    if (best < 0 || runs_[b]->time() < runs_[static_cast<std::size_t>(best)]->time())
      best = static_cast<int>(b);
  }
  return best;
}

// Building b's point: displacement [m], velocity [m/s] and relative acceleration [m/s^2] now.
void RowStepper::side_now(int b, int point, double& x, double& v, double& a) const {
  const RowRun& r = *runs_[static_cast<std::size_t>(b)];
  const SitePoint& p = apart_.parts[static_cast<std::size_t>(b)].watch.points[point];
  const int n = apart_.parts[static_cast<std::size_t>(b)].a.dofs();
  x = p.of(r.state().data());
  v = p.of(r.state().data() + n);
  a = p.of(r.derivative().data() + n);
}

// Whether a site of building b, at b's time, is within reach of the margin over b's next step:
// its penetration plus twice what its rate and acceleration there move it in the longest step.
// Not a proof (the acceleration changes inside the step): where the fork then fires without
// the copy, the pounding run is solved on its own (correct, slower; ForkStats).
bool RowStepper::near_contact(int b) const {
  const double t = runs_[static_cast<std::size_t>(b)]->time(), h = horizon_;
  for (std::size_t i = 0; i < ra_.sites.size(); ++i) {
    const ContactSite& site = ra_.sites[i];
    if (site.pair != b && site.pair + 1 != b) continue;
    const int o = site.pair == b ? b + 1 : site.pair;
    const bool left = site.pair == b;
    double xb, vb, ab, xo, vo, ao;
    side_now(b, left ? apart_.left[i] : apart_.right[i], xb, vb, ab);
    side_now(o, left ? apart_.right[i] : apart_.left[i], xo, vo, ao);
    const detail::StepWatch& wo = apart_.parts[static_cast<std::size_t>(o)].watch;
    if (!wo.steps.empty()) last_step_at(wo, left ? apart_.right[i] : apart_.left[i], t, xo, vo);
    const double pen = left ? xb - xo - site.gap : xo - xb - site.gap;
    const double reach = 2.0 * (h * std::fabs(vb - vo) + 0.5 * h * h * std::fabs(ab - ao));
    if (pen + kMargin + reach > 0.0) return true;
  }
  return false;
}

// Whether a site of building b comes within the margin on the overlap of b's new step (from
// ta) with its neighbour's last step: both sides' cubics restricted to the overlap are the
// Hermite cubics of their values and rates at its ends, and so is the penetration
// (docs/speed.md, "The approach bound across two grids"), tested as fork_if_near_contact tests
// a row step.
bool RowStepper::fires(int b, double ta) const {
  const double tb = runs_[static_cast<std::size_t>(b)]->time();
  for (std::size_t i = 0; i < ra_.sites.size(); ++i) {
    const ContactSite& site = ra_.sites[i];
    if (site.pair != b && site.pair + 1 != b) continue;
    const int o = site.pair == b ? b + 1 : site.pair;
    const detail::StepWatch& wo = apart_.parts[static_cast<std::size_t>(o)].watch;
    const detail::StepWatch& wb = apart_.parts[static_cast<std::size_t>(b)].watch;
    if (wo.steps.empty()) continue;  // the neighbour's first step will test this stretch
    const double te = std::min(tb, wo.steps[wo.steps.size() - wo.stride() + 1]);
    if (!(te > ta)) continue;
    const bool left = site.pair == b;
    const int pb = left ? apart_.left[i] : apart_.right[i];
    const int po = left ? apart_.right[i] : apart_.left[i];
    double xb0, vb0, xb1, vb1, xo0, vo0, xo1, vo1;
    last_step_at(wb, pb, ta, xb0, vb0);
    last_step_at(wb, pb, te, xb1, vb1);
    last_step_at(wo, po, ta, xo0, vo0);
    last_step_at(wo, po, te, xo1, vo1);
    const double sg = left ? 1.0 : -1.0, h = te - ta;
    const Hermite c{sg * (xb0 - xo0) - site.gap + kMargin, sg * (xb1 - xo1) - site.gap + kMargin,
                    h * sg * (vb0 - vo0), h * sg * (vb1 - vo1)};
    if (c.upper_bound() > 0.0 && c.max_over_step() > 0.0) return true;
  }
  return false;
}

// The pounding run of the whole row from the buildings' states at ta (false: it cannot start
// there, and is solved on its own).
bool RowStepper::fork(double ta, ForkStats& stats) {
  const int n = ra_.dofs();
  Eigen::VectorXd u = Eigen::VectorXd::Zero(n), v = Eigen::VectorXd::Zero(n);
  std::vector<StoreyState> storeys(static_cast<std::size_t>(n)), own;
  double energies[3] = {0.0, 0.0, 0.0};
  for (std::size_t b = 0; b < runs_.size(); ++b) {
    RowRun* c = at_start_[b].get();
    if (!c || c->time() > ta) return false;
    stats.retaken = std::max(stats.retaken, ta - c->time());
    // Its last step re-taken from its start to ta (the stepping building is there already).
    if (c->advance_until(ta) || c->recorder().take_new_collapses() > 0) return false;
    const ApartPart& q = apart_.parts[b];
    const int nq = q.a.dofs();
    c->storey_states(own);
    for (int k = 0; k < nq; ++k) {
      const int d = q.to_row[static_cast<std::size_t>(k)];
      u(d) = c->state()(k);
      v(d) = c->state()(nq + k);
      storeys[static_cast<std::size_t>(d)] = own[static_cast<std::size_t>(k)];
    }
    const StateLayout& at = c->dynamics().layout();
    if (at.ground > at.energies)  // the energies are states of y (track_energy)
      for (int k = 0; k < 3; ++k) energies[k] += c->state()(at.energies + k);
  }
  for (const ContactSite& site : ra_.sites)  // the re-taken states still apart
    if (site.left.of(u.data()) - site.right.of(u.data()) - site.gap >= 0.0) return false;
  stats.u = u;
  stats.v = v;
  pounding_ = std::make_unique<RowRun>(pounding_p_, s_);
  pounding_->resume(ta, u, v, storeys, pounding_p_.track_energy ? energies : nullptr);
  RunRecorder& rec = pounding_->recorder();
  rec.start(u);
  for (std::size_t b = 0; b < runs_.size(); ++b)
    rec.merge_from(at_start_[b]->recorder(), apart_.parts[b].to_row);
  return true;
}

RunPair RowStepper::run(ForkStats& stats) {
  const int n = ra_.dofs();
  const Eigen::VectorXd u0 = pounding_p_.u0.size() ? pounding_p_.u0 : Eigen::VectorXd::Zero(n);
  bool armed = true;  // every site open by more than the margin at the start
  for (const ContactSite& site : ra_.sites)
    armed = armed && site.left.of(u0.data()) - site.right.of(u0.data()) - site.gap + kMargin < 0.0;
  bool own = !armed, forked = false;
  for (auto& r : runs_) r->begin();
  const double t_end = pounding_p_.t_end;
  for (int b; !forked && !own && (b = next_building()) >= 0;) {
    const std::size_t bb = static_cast<std::size_t>(b);
    at_start_[bb].reset();
    if (near_contact(b)) {
      at_start_[bb] = std::make_unique<RowRun>(*runs_[bb]);
      at_start_[bb]->watch(nullptr);
      ++stats.copies;
    }
    const double ta = runs_[bb]->time();
    stopped_[bb] = runs_[bb]->advance_step(t_end);
    const RowResult& r = runs_[bb]->recorder().result();
    for (const BuildingCollapse& c : r.collapse) own = own || c.collapsed;
    if (own || !fires(b, ta)) continue;
    forked = fork(ta, stats);
    own = !forked;
    if (forked) stats.t_fork = ta;
  }
  // The free run to the end, building by building.
  for (std::size_t b = 0; b < runs_.size(); ++b) {
    if (!stopped_[b]) runs_[b]->advance_until(t_end);
    apart_.parts[b].r = runs_[b]->end();
  }
  RunPair out;
  bool collapsed = false;
  for (const ApartPart& q : apart_.parts)
    for (const BuildingCollapse& c : q.r.collapse) collapsed = collapsed || c.collapsed;
  out.free = collapsed && apart_.p.track_energy ? solve(apart_.p, s_) : apart_.merge();
  stats.own_pounding_run = own;
  if (own) {
    out.pounding = RowRun(pounding_p_, s_).run();
  } else if (forked) {
    out.pounding = pounding_->advance();
  } else {  // no site came near touching: the runs are one (as solve_free_and_pounding's)
    out.pounding = out.free;
    out.pounding.sites.assign(ra_.sites.size(), SiteResult{});
    out.pounding.steps_from_free = out.pounding.steps;
  }
  return out;
}

}  // namespace

bool fork_apart_applies(const BuildingRow& row, const RowProblem& p) {
  // Two buildings: a third one, away from the site that comes near, would have no copy at the
  // start of its last step (near_contact), and the pounding run would be solved from t = 0.
  if (p.laws.empty() || p.record_history || !apart_pays(row) || row.buildings.size() != 2)
    return false;
  if (p.ground && p.ground->channels() != 1) return false;
  return std::all_of(p.row->sites.begin(), p.row->sites.end(),
                     [](const ContactSite& c) { return c.struck_dof < 0; });
}

RunPair solve_free_and_pounding_apart(const BuildingRow& row, const RowProblem& p,
                                      const IntegratorSettings& s, ForkStats* stats) {
  RowProblem free = p, pounding = p;
  free.laws.clear();
  free.exact_cache = nullptr;  // each building keeps its own propagators
  ForkStats local;
  RowStepper stepper(row, free, pounding, s);
  return stepper.run(stats ? *stats : local);
}

RunPair solve_free_and_pounding(const BuildingRow& row, const RowProblem& p,
                                const IntegratorSettings& s) {
  return fork_apart_applies(row, p) ? solve_free_and_pounding_apart(row, p, s)
                                    : solve_free_and_pounding(p, s);
}

}  // namespace pound

// A row's run without contacts stepped building by building (solver/row_apart.hpp).
#include "solver/row_apart.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "solver/hermite.hpp"
#include "solver/row_apart_parts.hpp"
#include "solver/row_run.hpp"

namespace pound {
namespace {

using detail::ApartPart;
using detail::ApartRow;
using detail::RowRun;
using detail::StepWatch;

constexpr double kInf = std::numeric_limits<double>::infinity();

// The row DOFs of building b in the order assemble() gives a row of b alone: its floors, then
// its base's sway and rotation where it has them.
std::vector<int> row_dofs(const AssembledRow& a, int b) {
  std::vector<int> d;
  for (int k = 0; k < a.floors; ++k)
    if (a.building_of[k] == b) d.push_back(k);
  if (!a.sway.empty() && a.sway[b] >= 0) d.push_back(a.sway[b]);
  if (!a.rot.empty() && a.rot[b] >= 0) d.push_back(a.rot[b]);
  return d;
}

// A site's side in its building's own DOFs (to_own: per row DOF its own DOF, -1 elsewhere).
SitePoint own_point(const SitePoint& s, const std::vector<int>& to_own) {
  SitePoint o;
  for (int k = 0; k < s.count; ++k) {
    if (to_own[s.dof[k]] < 0) throw std::logic_error("solve_apart: a site side off its building");
    o.add(to_own[s.dof[k]], s.weight[k]);
  }
  return o;
}

// One point of one building's dense output (StepWatch): on each step the cubic Hermite of its
// displacement x [m] with the velocity v [m/s] as its rate; after the last step (a building
// held still after its collapse) its last value, at rest.
class Side {
 public:
  Side(const StepWatch& w, int point, double x_start)
      : w_(w),
        stride_(w.stride()),
        off_(2 + 4 * point),
        count_(static_cast<long>(w.steps.size()) / stride_),
        x_start_(x_start) {}
  long count() const { return count_; }
  // Bounds of x over step k (Hermite::upper_bound's basis bounds), held past the last step.
  double upper(long k) const { return bound(k, 1.0); }
  double lower(long k) const { return bound(k, -1.0); }
  double end(long k) const { return k < count_ ? w_.steps[k * stride_ + 1] : kInf; }
  // Value and rate at t on step k (its cubic; past the last step, held).
  void at(long k, double t, double& x, double& v) const {
    if (k >= count_) {
      x = count_ ? w_.steps[(count_ - 1) * stride_ + off_ + 1] : x_start_;
      v = 0.0;
      return;
    }
    StepWatch::point_at(w_.steps.data() + k * stride_, off_, t, x, v);
  }

 private:
  double bound(long k, double sign) const {
    if (k >= count_) return count_ ? w_.steps[(count_ - 1) * stride_ + off_ + 1] : x_start_;
    const double* s = w_.steps.data() + k * stride_;
    const double h = s[1] - s[0], x0 = s[off_], x1 = s[off_ + 1];
    const double reach = 4.0 / 27.0 * h * (std::fabs(s[off_ + 2]) + std::fabs(s[off_ + 3]));
    return sign > 0 ? std::max(x0, x1) + reach * (1 + 1e-12)
                    : std::min(x0, x1) - reach * (1 + 1e-12);
  }
  const StepWatch& w_;
  const int stride_, off_;
  const long count_;
  const double x_start_;
};

// The peak of the approach xl - xr (+ the grounds' difference: trace_l, trace_r non-null where
// the sides stand on different channels) from `peak` (the approach at the start) on, over the
// union of the two sides' step grids: on each piece between consecutive grid points both sides
// are cubics, so their difference is the cubic Hermite of its values and rates at the piece's
// ends, tested as RunRecorder::approach_over_step tests a row step's.
double peak_approach(const Side& l, const Side& r, const GroundTrace* trace_l,
                     const GroundTrace* trace_r, double peak) {
  long il = 0, ir = 0;
  double t = 0.0;
  for (;;) {
    const double el = l.end(il), er = r.end(ir), tb = std::min(el, er);
    if (tb == kInf) break;  // both held still from here on
    // On one channel the approach over the piece is at most the left side's bound over its
    // step less the right side's: most pieces end here.
    if (tb > t && (trace_l || l.upper(il) - r.lower(ir) > peak)) {
      double xl0, vl0, xl1, vl1, xr0, vr0, xr1, vr1;
      l.at(il, t, xl0, vl0);
      l.at(il, tb, xl1, vl1);
      r.at(ir, t, xr0, vr0);
      r.at(ir, tb, xr1, vr1);
      double g0 = xl0 - xr0, g1 = xl1 - xr1, r0 = vl0 - vr0, r1 = vl1 - vr1;
      if (trace_l) {  // absolute displacements (physics.md section 5a)
        double vg, ug;
        trace_l->kinematics(t, vg, ug);
        g0 += ug, r0 += vg;
        trace_r->kinematics(t, vg, ug);
        g0 -= ug, r0 -= vg;
        trace_l->kinematics(tb, vg, ug);
        g1 += ug, r1 += vg;
        trace_r->kinematics(tb, vg, ug);
        g1 -= ug, r1 -= vg;
      }
      const double h = tb - t;
      const Hermite c{g0, g1, h * r0, h * r1};
      if (c.upper_bound() > peak) peak = std::max(peak, c.max_over_step());
    }
    t = std::max(t, tb);
    if (el <= tb) ++il;
    if (er <= tb) ++ir;
  }
  return peak;
}

// Building b of the row alone (Part): its own row, DOF maps (to_own: per row DOF its own DOF),
// ground channel and problem.
void set_up(ApartPart& q, const BuildingRow& row, const RowProblem& p, int b,
            std::vector<int>& to_own) {
  const AssembledRow& ra = *p.row;
  BuildingRow one;
  one.buildings = {row.buildings[static_cast<std::size_t>(b)]};
  q.a = assemble(one);
  q.to_row = row_dofs(ra, b);
  if (static_cast<int>(q.to_row.size()) != q.a.dofs())
    throw std::logic_error("solve_apart: a building's DOFs differ alone and in the row");
  for (int k = 0; k < q.a.dofs(); ++k) {
    if (q.a.inv_mass(k) != ra.inv_mass(q.to_row[k]))
      throw std::logic_error("solve_apart: a building's masses differ alone and in the row");
    to_own[q.to_row[k]] = k;
  }
  if (p.ground) q.ground = RowGround::uniform(p.ground->under(b).motion(), 1);
  q.p.row = &q.a;
  q.p.ground = p.ground ? &q.ground : nullptr;
  q.p.t_end = p.t_end;
  q.p.track_energy = p.track_energy;
  q.p.collapse_drift_ratio = p.collapse_drift_ratio;
  for (auto [from, to] : {std::pair{&p.u0, &q.p.u0}, std::pair{&p.v0, &q.p.v0}}) {
    if (!from->size()) continue;
    to->resize(q.a.dofs());
    for (int k = 0; k < q.a.dofs(); ++k) (*to)(k) = (*from)(q.to_row[k]);
  }
}

// The watches' step arrays (hundreds of kB a run), kept per thread from one run to the next:
// fresh ones would come from the system page by page in every sample (the heap hands them
// back when they are freed), at a page fault each.
std::vector<std::vector<double>>& watch_pool() {
  thread_local std::vector<std::vector<double>> pool;
  return pool;
}

}  // namespace

namespace detail {

ApartRow::ApartRow(const BuildingRow& row, const RowProblem& p_row) : p(p_row) {
  const AssembledRow& ra = *p.row;
  const int nb = static_cast<int>(row.buildings.size()), n = ra.dofs();
  // Each building alone, on its own channel; its watch: the sides of its sites and the
  // storeys its neighbours strike (column sites).
  parts = std::vector<ApartPart>(static_cast<std::size_t>(nb));
  to_own.assign(static_cast<std::size_t>(nb), std::vector<int>(n, -1));
  for (int b = 0; b < nb; ++b)
    set_up(parts[static_cast<std::size_t>(b)], row, p, b, to_own[static_cast<std::size_t>(b)]);
  const int ns = static_cast<int>(ra.sites.size());
  left.assign(ns, 0), right.assign(ns, 0), shear.assign(ns, -1);
  for (int i = 0; i < ns; ++i) {
    const ContactSite& site = ra.sites[static_cast<std::size_t>(i)];
    StepWatch& wl = parts[static_cast<std::size_t>(site.pair)].watch;
    StepWatch& wr = parts[static_cast<std::size_t>(site.pair + 1)].watch;
    left[i] = static_cast<int>(wl.points.size());
    wl.points.push_back(own_point(site.left, to_own[static_cast<std::size_t>(site.pair)]));
    right[i] = static_cast<int>(wr.points.size());
    wr.points.push_back(own_point(site.right, to_own[static_cast<std::size_t>(site.pair + 1)]));
    if (site.struck_dof >= 0) {
      const int b = ra.building_of[site.struck_dof];
      StepWatch& w = parts[static_cast<std::size_t>(b)].watch;
      shear[i] = static_cast<int>(w.shear_dofs.size());
      w.shear_dofs.push_back(to_own[static_cast<std::size_t>(b)][site.struck_dof]);
    }
  }
  // About three steps per record sample (Dormand-Prince through yielding), grown if needed.
  const double rec_dt = p.ground ? p.ground->dt() : 0.0;
  const std::size_t guess = rec_dt > 0 ? static_cast<std::size_t>(3.0 * p.t_end / rec_dt) : 0;
  std::vector<std::vector<double>>& pool = watch_pool();
  for (ApartPart& q : parts) {
    if (!pool.empty()) {
      q.watch.steps.swap(pool.back());
      pool.pop_back();
    }
    q.watch.reset();
    q.watch.steps.reserve(guess * static_cast<std::size_t>(q.watch.stride()));
  }
}

ApartRow::~ApartRow() {
  std::vector<std::vector<double>>& pool = watch_pool();
  for (ApartPart& q : parts) pool.push_back(std::move(q.watch.steps));
}

RowResult ApartRow::merge() const {
  const AssembledRow& ra = *p.row;
  const int nb = static_cast<int>(parts.size()), n = ra.dofs();
  const int ns = static_cast<int>(ra.sites.size());
  // The row's result in its DOFs.
  RowResult out;
  for (Eigen::VectorXd* v : {&out.peak_disp, &out.peak_drift, &out.peak_abs_accel,
                             &out.hysteretic_energy, &out.u_end, &out.v_end})
    v->setZero(n);
  out.stopped = true;
  for (int b = 0; b < nb; ++b) {
    const ApartPart& q = parts[static_cast<std::size_t>(b)];
    const RowResult& r = q.r;
    for (int k = 0; k < q.a.dofs(); ++k) {
      const int d = q.to_row[k];
      out.peak_disp(d) = r.peak_disp(k);
      out.peak_drift(d) = r.peak_drift(k);
      out.peak_abs_accel(d) = r.peak_abs_accel(k);
      if (r.hysteretic_energy.size()) out.hysteretic_energy(d) = r.hysteretic_energy(k);
      out.u_end(d) = r.u_end(k);
      out.v_end(d) = r.v_end(k);
    }
    if (!r.collapse.empty()) {
      out.collapse.resize(static_cast<std::size_t>(nb));
      out.collapse[static_cast<std::size_t>(b)] = r.collapse.front();
    }
    out.t_end = std::max(out.t_end, r.t_end);
    out.stopped = out.stopped && r.stopped;
    for (double EnergyBalance::*e :
         {&EnergyBalance::input, &EnergyBalance::kinetic, &EnergyBalance::strain,
          &EnergyBalance::damping, &EnergyBalance::hysteretic, &EnergyBalance::contact,
          &EnergyBalance::crushing})
      out.energy.*e += r.energy.*e;
    out.steps += r.steps;
    out.rejected += r.rejected;
    out.events += r.events;
    out.exact_steps += r.exact_steps;
  }
  // The sites: the approach on both grids, the struck columns' sway shear (no contact force:
  // column_shear_demand is face_share |V|).
  out.sites.assign(static_cast<std::size_t>(ns), SiteResult{});
  const Eigen::VectorXd u0 = p.u0.size() ? p.u0 : Eigen::VectorXd::Zero(n);
  for (int i = 0; i < ns; ++i) {
    const ContactSite& site = ra.sites[static_cast<std::size_t>(i)];
    const int bl = site.pair, br = site.pair + 1;
    const double xl = site.left.of(u0.data()), xr = site.right.of(u0.data());
    const Side l(parts[static_cast<std::size_t>(bl)].watch, left[i], xl);
    const Side r(parts[static_cast<std::size_t>(br)].watch, right[i], xr);
    const bool apart = p.ground && p.ground->channel(bl) != p.ground->channel(br);
    out.sites[static_cast<std::size_t>(i)].peak_approach =
        peak_approach(l, r, apart ? &p.ground->under(bl) : nullptr,
                      apart ? &p.ground->under(br) : nullptr, xl - xr);
    if (shear[i] >= 0) {
      const double v = parts[static_cast<std::size_t>(ra.building_of[site.struck_dof])]
                           .watch.peak_shear[static_cast<std::size_t>(shear[i])];
      out.sites[static_cast<std::size_t>(i)].peak_column_shear = site.face_share * v;
    }
  }
  return out;
}

}  // namespace detail

RowResult solve_apart(const BuildingRow& row, const RowProblem& p, const IntegratorSettings& s) {
  if (!p.laws.empty()) throw std::logic_error("solve_apart: a problem without contact laws");
  if (row.buildings.size() < 2 || p.record_history) return solve(p, s);
  ApartRow apart(row, p);
  bool collapsed = false;
  for (ApartPart& q : apart.parts) {
    RowRun run(q.p, s);
    run.watch(&q.watch);
    q.r = run.run();
    for (const BuildingCollapse& c : q.r.collapse) collapsed = collapsed || c.collapsed;
  }
  if (collapsed && p.track_energy) return solve(p, s);
  return apart.merge();
}

bool apart_pays(const BuildingRow& row) {
  const auto& b = row.buildings;
  return std::any_of(b.begin(), b.end(), [](const Building& x) { return x.inelastic(); }) &&
         std::any_of(b.begin(), b.end(), [](const Building& x) { return !x.inelastic(); });
}

}  // namespace pound

#include "solver/row_switches.hpp"

#include <cmath>

#include "core/error.hpp"

namespace pound {

RowSwitches::RowSwitches(const AssembledRow& row, const std::vector<RowStorey>& storeys)
    : row_(row), storeys_(storeys), ns_(static_cast<int>(row.sites.size())) {
  for (int i = 0; i < row.dofs(); ++i)
    for (int k = 0; k < storeys_[i].law->switches(); ++k) sw_.push_back({i, k});
  has_safe_.assign(row.dofs(), 0);
  safe_lo_.assign(row.dofs(), 0.0);
  safe_hi_.assign(row.dofs(), 0.0);
}

void RowSwitches::reset() {
  last_event_t_.assign(2 * ns_ + sw_.size(), -1.0);  // sites, storeys, crushing faces
  chatter_.assign(2 * ns_ + sw_.size(), 0);
}

SwitchValue RowSwitches::storey_value(const RowDynamics& dyn, int k, const Eigen::VectorXd& y,
                                      const Eigen::VectorXd& dy) const {
  const StoreySwitch& w = sw_[k - ns_];
  const RowStorey& st = storeys_[w.dof];
  const int n = row_.dofs();
  return st.law->switch_value(w.local, st.p, dyn.storey[w.dof], dyn.drift(y, 0, w.dof),
                              dyn.drift(y, n, w.dof), dyn.drift(dy, n, w.dof));
}

// Site i's crushing switch (docs/contact-models.md, "Crushing faces"). Outside a crushing phase,
// F / cap - 1 with F the law's force on delta - c, and its rate dF/dt = F_delta ddelta + F_r
// ddelta' from central differences of the law in each argument (steps of 1e-6 of |delta| plus
// 1e-12 m and of 1e-6 of |ddelta| plus 1e-9 m/s: the rate only shapes the interpolant and
// Newton's first tries; the crossing is located on the values). In a phase, -ddelta: it ends
// where the faces start to part (unloading). Closed contacts only.
SwitchValue RowSwitches::crush_value(const RowDynamics& dyn, int i, const Eigen::VectorXd& y,
                                     const Eigen::VectorXd& dy) const {
  if (!dyn.active[i]) return {-1.0, 0.0};
  const double r = dyn.penetration_rate(y, i);
  const double a = dyn.penetration_rate(dy, i);  // d(ddelta)/dt: dy holds the accelerations
  if (dyn.crushing[i]) return {-r, -a};
  const double cap = dyn.force_cap(), d = dyn.penetration(y, i), v0 = dyn.v0[i];
  const ContactLaw& law = dyn.law(i);
  const double hd = 1e-6 * std::fabs(d) + 1e-12, hr = 1e-6 * std::fabs(r) + 1e-9;  // [m], [m/s]
  const double f_d = (law.force(d + hd, r, v0) - law.force(d - hd, r, v0)) / (2.0 * hd);
  const double f_r = (law.force(d, r + hr, v0) - law.force(d, r - hr, v0)) / (2.0 * hr);
  return {law.force(d, r, v0) / cap - 1.0, (f_d * r + f_r * a) / cap};
}

void RowSwitches::apply_crush(RowDynamics& dyn, int k, double t, const Eigen::VectorXd& y) {
  const int i = k - first_crush();
  guard_chatter(k, t, [&] { return "crushing face of contact site " + std::to_string(i + 1); });
  if (dyn.crushing[i]) {  // unloading: the indentation grown in the phase stays
    dyn.crush[i] = dyn.indentation(y, i);
    dyn.crushing[i] = 0;
  } else {  // the law's force reached the cap: its own penetration is held from here
    dyn.crush_law_penetration[i] = dyn.penetration(y, i);
    dyn.crushing[i] = 1;
  }
}

void RowSwitches::storey_changed(int dof, const StoreyState& s) {
  const RowStorey& st = storeys_[dof];
  has_safe_[dof] = st.law->safe_drift(st.p, s, safe_lo_[dof], safe_hi_[dof]);
  if (has_safe_[dof]) {  // find_event's margin for round-off
    const double margin = 1e-12 * (std::fabs(safe_lo_[dof]) + std::fabs(safe_hi_[dof]));
    safe_lo_[dof] += margin;
    safe_hi_[dof] -= margin;
  }
}

__attribute__((always_inline)) inline double RowSwitches::first_crossing(const Hermite& c) {
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
  return th;
}

int RowSwitches::find_event(const RowDynamics& dyn, const Eigen::VectorXd& y0,
                            const Eigen::VectorXd& y1, const Eigen::VectorXd& dy0,
                            const Eigen::VectorXd& dy1, double h, double& theta,
                            const std::vector<char>* ignore) const {
  const int n = row_.dofs();
  int best = -1;
  theta = 2.0;
  // The earliest crossing; among equal ones the lowest id (the switches in id order: the sites,
  // the storeys, the crushing faces).
  auto consider = [&](int k, const Hermite& c, bool renewed) {
    if (c.upper_bound() < 0.0) return;  // no crossing
    bool ev;
    if (renewed)                       // across within the location tolerance:
      ev = c.m0 > 0.0 || c.g1 > c.g0;  // only a renewed approach counts
    else
      ev = c.g1 > 0.0 || (c.m0 > 0.0 && c.max_over_step() > 0.0);
    if (!ev) return;
    const double th = first_crossing(c);  // first sign change of the cubic
    if (th < theta) {
      theta = th;
      best = k;
    }
  };
  if (dyn.pounding())
    for (int k = 0; k < ns_; ++k) {
      const double sign = dyn.active[k] ? -1.0 : 1.0;
      const Hermite c{sign * dyn.penetration(y0, k), sign * dyn.penetration(y1, k),
                      h * (sign * dyn.penetration_rate(y0, k)),
                      h * (sign * dyn.penetration_rate(y1, k))};
      consider(k, c, !dyn.active[k] && c.g0 > 0.0);
    }
  const int nsw = static_cast<int>(sw_.size());
  for (int j = 0; j < nsw; ++j) {
    const int dof = sw_[j].dof;
    if (has_safe_[dof]) {
      // Skip a storey whose drift stays inside its safe interval (shrunk by 1e-12 of its
      // ends, storey_changed): a bound of the drift's cubic over the step (its basis
      // functions of the end slopes are at most 4/27).
      const double d0 = dyn.drift(y0, 0, dof), d1 = dyn.drift(y1, 0, dof);
      const double m4 =
          4.0 / 27.0 * h * (std::fabs(dyn.drift(y0, n, dof)) + std::fabs(dyn.drift(y1, n, dof)));
      if (std::max(d0, d1) + m4 < safe_hi_[dof] && std::min(d0, d1) - m4 > safe_lo_[dof]) continue;
    }
    const int k = ns_ + j;
    const SwitchValue a = storey_value(dyn, k, y0, dy0), b = storey_value(dyn, k, y1, dy1);
    consider(k, {a.value, b.value, h * a.rate, h * b.rate}, false);
  }
  if (!dyn.capped()) return best;
  for (int i = 0; i < ns_; ++i) {  // the crushing switches (a capped pounding run)
    const int k = first_crush() + i;
    if (!dyn.active[i] || (ignore && (*ignore)[k])) continue;
    const SwitchValue a = crush_value(dyn, i, y0, dy0), b = crush_value(dyn, i, y1, dy1);
    consider(k, {a.value, b.value, h * a.rate, h * b.rate}, false);
  }
  return best;
}

void RowSwitches::throw_chatter(int k, double t, const std::string& what) const {
  const char* kind = k < ns_ ? "impacts" : (k < first_crush() ? "yield events" : "crushing phases");
  throw NumericalError(what + ": " + kind + " accumulate at t = " + std::to_string(t) +
                       " s (chatter)" +
                       (k < ns_ ? "; use a force-based contact model" : std::string()));
}

void RowSwitches::apply_storey(RowDynamics& dyn, int k, double t, const Eigen::VectorXd& y) {
  const StoreySwitch& w = sw_[k - ns_];
  const RowStorey& st = storeys_[w.dof];
  guard_chatter(k, t, [&] {
    return "building " + std::to_string(st.building + 1) + ", storey " +
           std::to_string(w.dof - row_.offset[st.building] + 1);
  });
  st.law->on_switch(w.local, st.p, dyn.storey[w.dof], dyn.drift(y, 0, w.dof),
                    dyn.continuous_states(y, w.dof));
  // The caller (RowRun::apply_event) updates the lines, safe intervals and exact steps once.
}

}  // namespace pound

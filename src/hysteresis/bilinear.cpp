#include "hysteresis/bilinear.hpp"

#include <cmath>

namespace pound {

double BilinearStorey::z_of(const StoreyParameters& p, const StoreyState& s, double d) {
  return s.branch == 0 ? s.z_anchor + (d - s.d_anchor) : s.branch * p.uy();
}

double BilinearStorey::shear(const StoreyParameters& p, const StoreyState& s, double d,
                             const double*) const {
  return p.k0 * (p.b * d + (1.0 - p.b) * z_of(p, s, d));
}

SwitchValue BilinearStorey::switch_value(int, const StoreyParameters& p, const StoreyState& s,
                                         double d, double dd, double ddd) const {
  if (s.branch == 0) {
    // |z| reaches uy: (z^2 - uy^2) / (2 uy) is smooth and ~ |z| - uy near the yield drift.
    const double uy = p.uy(), z = z_of(p, s, d);
    return {(z - uy) * (z + uy) / (2.0 * uy), z * dd / uy};
  }
  return {-s.branch * dd, -s.branch * ddd};  // the drift rate reverses: unloading
}

void BilinearStorey::on_switch(int, const StoreyParameters& p, StoreyState& s, double d,
                               const double*) const {
  const double uy = p.uy();
  if (s.branch == 0) {
    s.branch = z_of(p, s, d) > 0.0 ? 1 : -1;
  } else {
    s.dissipated += (1.0 - p.b) * p.Fy * std::fabs(d - s.d_anchor);
    s.branch = 0;
  }
  // Both branches start from z = +-uy: yielding at the yield drift, unloading from it.
  s.z_anchor = (s.branch != 0 ? s.branch : (s.z_anchor > 0.0 ? 1 : -1)) * uy;
  s.d_anchor = d;
}

bool BilinearStorey::branch_line(const StoreyParameters& p, const StoreyState& s, double& slope,
                                 double& offset) const {
  if (s.branch == 0) {  // V = k0 (b d + (1 - b)(z_a + d - d_a)) = k0 d + k0 (1 - b)(z_a - d_a)
    slope = p.k0;
    offset = p.k0 * (1.0 - p.b) * (s.z_anchor - s.d_anchor);
  } else {  // V = b k0 d + (1 - b) k0 (+-uy)
    slope = p.b * p.k0;
    offset = (1.0 - p.b) * p.k0 * s.branch * p.uy();
  }
  return true;
}

bool BilinearStorey::safe_drift(const StoreyParameters& p, const StoreyState& s, double& lo,
                                double& hi) const {
  if (s.branch != 0) return false;                // the unloading switch acts on the drift rate
  const double centre = s.d_anchor - s.z_anchor;  // the drift where z = 0
  lo = centre - p.uy();
  hi = centre + p.uy();
  return true;
}

double BilinearStorey::dissipated(const StoreyParameters& p, const StoreyState& s, double d,
                                  const double*) const {
  return s.branch == 0 ? s.dissipated
                       : s.dissipated + (1.0 - p.b) * p.Fy * std::fabs(d - s.d_anchor);
}

double BilinearStorey::stored(const StoreyParameters& p, const StoreyState& s, double d,
                              const double*) const {
  const double z = z_of(p, s, d);
  return 0.5 * p.k0 * (p.b * d * d + (1.0 - p.b) * z * z);
}

double BilinearStorey::advance(const StoreyParameters& p, const StoreyState& committed, double d0,
                               double d1, StoreyState& trial) const {
  // Return map of the elastic-perfectly-plastic part (Simo & Hughes, Computational
  // Inelasticity, sec. 1.4): elastic trial, then back onto |z| <= uy; its plastic work at the
  // constant force (1 - b) Fy is the step's hysteretic energy.
  const double uy = p.uy();
  const double z_trial = z_of(p, committed, d0) + (d1 - d0);
  trial = committed;
  // The energy dissipated up to d0 on the committed branch, which may have begun before d0 (a
  // state of the continuous form, anchored where its branch began: the damped Sears run's
  // stretches on the lumped solver, issue 30); nothing to add when it is anchored at d0.
  trial.dissipated = dissipated(p, committed, d0, nullptr);
  trial.d_anchor = d1;
  if (std::fabs(z_trial) <= uy) {
    trial.branch = 0;
    trial.z_anchor = z_trial;
  } else {
    const int sign = z_trial > 0.0 ? 1 : -1;
    trial.dissipated += (1.0 - p.b) * p.Fy * (std::fabs(z_trial) - uy);
    trial.branch = sign;
    trial.z_anchor = sign * uy;
  }
  return shear(p, trial, d1, nullptr);
}

}  // namespace pound

#pragma once
// The dense output of chosen points of one run (solver/row_apart.hpp, issue 38): per accepted
// step, each point's displacement and velocity at both ends, from which the step's cubic
// Hermite interpolant (the one the row solver locates contact events on) is rebuilt; and the
// peak |shear| of chosen storeys at the steps' ends. With it a row's free run is stepped
// building by building, and each contact site's approach is found across the two buildings'
// step grids. Internal to src/solver.
#include <Eigen/Dense>
#include <cmath>
#include <limits>
#include <vector>

#include "solver/hermite.hpp"
#include "structure/building_row.hpp"

namespace pound::detail {

struct StepWatch {
  /// Points in the run's own DOFs (SitePoint: weighted floors).
  std::vector<SitePoint> points;
  /// Per accepted step: its start and end time [s], then per point x0, x1 [m], v0, v1 [m/s].
  std::vector<double> steps;
  /// Storey DOFs (the run's own) whose peak |shear| over the steps' ends is kept [N].
  std::vector<int> shear_dofs;
  std::vector<double> peak_shear;

  int stride() const { return 2 + 4 * static_cast<int>(points.size()); }
  /// The step from t0 of length h [s] between states y0 and y1 (y = [u; v; ...], n DOFs).
  void add_step(double t0, double h, const Eigen::VectorXd& y0, const Eigen::VectorXd& y1, int n) {
    steps.push_back(t0);
    steps.push_back(t0 + h);
    for (const SitePoint& p : points) {
      steps.push_back(p.of(y0.data()));
      steps.push_back(p.of(y1.data()));
      steps.push_back(p.of(y0.data() + n));
      steps.push_back(p.of(y1.data() + n));
    }
  }
  /// A point's displacement x [m] and velocity v [m/s] at t [s] on a step record s (as in
  /// `steps`; off = 2 + 4 * point): the step's cubic Hermite and its derivative, the end values
  /// outside [t0, t1].
  static void point_at(const double* s, int off, double t, double& x, double& v) {
    const double t0 = s[0], t1 = s[1], x0 = s[off], x1 = s[off + 1], v0 = s[off + 2],
                 v1 = s[off + 3];
    if (t <= t0) {
      x = x0, v = v0;
      return;
    }
    if (t >= t1) {
      x = x1, v = v1;
      return;
    }
    const double h = t1 - t0, th = (t - t0) / h, t2 = th * th;
    const Hermite c{x0, x1, h * v0, h * v1};
    x = c.at(th);
    // d/dt of the cubic: its basis functions' derivatives over h.
    v = ((6 * t2 - 6 * th) * (x0 - x1) + (3 * t2 - 4 * th + 1) * c.m0 + (3 * t2 - 2 * th) * c.m1) /
        h;
  }
  /// A storey's shear v [N] at a step's end (k: its index in shear_dofs).
  void shear(int k, double v) {
    double& peak = peak_shear[static_cast<std::size_t>(k)];
    if (!(peak >= std::fabs(v))) peak = std::fabs(v);
  }
  void reset() {
    steps.clear();
    peak_shear.assign(shear_dofs.size(), std::numeric_limits<double>::quiet_NaN());
  }
};

}  // namespace pound::detail

#pragma once
// Exact steps between events (docs/integration.md, "Exact steps"): at a point of the grid
// t_k = k h with no contact active, a row whose storeys are linear or piecewise linear is
// linear in its state with the current branches' stiffness and offsets, and a piecewise-linear
// ag, so one step of linear_step() reaches t_k+1 exactly. This keeps the grid and the
// propagators (one per tangent stiffness met); the row solver takes the steps. Kernel only.
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "solver/linear_step.hpp"
#include "solver/row_dynamics.hpp"

namespace pound {

/// The exact steps' propagators of one row (docs/integration.md, "Exact steps"), one per
/// tangent stiffness met, kept between the runs that share the row, the motion's spacing and the
/// integrator settings (simulate_row: the free and the pounding run of a sample). A run uses a
/// stiffness' propagator from the kExactWarmup-th grid point at which it met that stiffness on
/// (briefer branches, a storey yielding for a few steps, cost less by Dormand-Prince than a
/// propagator); counted per run, so that a run takes the same steps with or without the cache.
struct ExactStepCache {
  static constexpr int kExactWarmup = 32;
  struct Entry {
    Eigen::MatrixXd K;      ///< tangent stiffness [N/m]
    std::uint64_t key = 0;  ///< hash of K's bits: most look-ups compare this alone (a
                            ///< deteriorating law meets a new stiffness at every excursion)
    bool ready = false;
    LinearStep step;
  };
  std::vector<Entry> entries;
  std::unordered_multimap<std::uint64_t, int> by_key;  ///< Entry::key -> its index in entries
  const AssembledRow* row = nullptr;  ///< the row and grid step [s] of the entries (a run of
  double h = 0.0;                     ///< another row or step clears them)
};

class ExactSteps {
 public:
  ExactSteps() = default;
  /// A copy uses its own copy of the source's own cache (or the same shared cache).
  ExactSteps(const ExactSteps& o);
  ExactSteps& operator=(const ExactSteps&) = delete;

  /// Enables exact steps on the grid of h_max [s] that holds every sample of a record of
  /// spacing rec_dt [s] (0: none); `shared` the propagators of other runs of the row (null:
  /// this run's own).
  void enable(const AssembledRow& row, double h_max, double rec_dt, ExactStepCache* shared);
  bool enabled() const { return enabled_; }
  void disable() { enabled_ = false; }
  double grid_step() const { return h_; }
  /// The last grid point at or before t [s] (advancing to it); whether t is on it.
  bool on_grid(double t) {
    while (double(point_ + 1) * h_ <= t * (1 + 1e-14) + 1e-15) ++point_;
    return std::fabs(t - double(point_) * h_) <= 1e-14 * std::max(1.0, t) + 1e-15;
  }
  /// The next grid point's time [s].
  double next_point() const { return double(point_ + 1) * h_; }
  /// After an exact step to the next point.
  void advanced() { ++point_; }

  /// Whether the exact step from the current grid point was declined (a switch fired in it:
  /// Dormand-Prince takes it instead), and marking it so.
  bool declined_here() const { return point_ == declined_; }
  void decline() { declined_ = point_; }
  /// At the top of each loop iteration of the solver: what the iteration may change and a fork
  /// must undo (undo_iteration).
  void begin_iteration() {
    declined_before_iteration_ = declined_;
    visited_ = -1;
  }
  void undo_iteration();

  /// After a switch: the stiffness is looked up again at the next exact step.
  void invalidate() {
    config_ = -1;
    offsets_ready_ = false;
  }
  /// The propagator of the current tangent stiffness of `dyn` (added when new, formed at its
  /// kExactWarmup-th grid point); null while not ready. offsets_response() then holds the
  /// response P1 [0; -M^-1] off of the branches' offsets [m, m/s].
  const LinearStep* propagator(const RowDynamics& dyn, const AssembledRow& row);
  const double* offsets_response() const { return offsets_response_.data(); }
  /// The ramped inputs of a step: one per ground channel (one, at zero, without ground).
  static int ground_inputs(const RowDynamics& dyn) {
    return dyn.ground() ? dyn.ground()->channels() : 1;
  }

 private:
  static void eliminate_massless(const RowDynamics& dyn, const Eigen::MatrixXd& K,
                                 const Eigen::MatrixXd& C, Eigen::MatrixXd& A, Eigen::MatrixXd& B);
  static const Eigen::VectorXd& dyn_inv_mass(const RowDynamics& dyn) { return dyn.inv_mass(); }

  bool enabled_ = false;
  double h_ = 0.0;      // grid step [s]
  long point_ = 0;      // index of the last grid point reached
  long declined_ = -1;  // the grid point whose exact step was declined
  ExactStepCache own_cache_;
  ExactStepCache* cache_ = &own_cache_;
  int config_ = -1;  // the current stiffness' entry (-1: look it up again, after a switch)
  bool offsets_ready_ = false;
  Eigen::VectorXd offsets_response_;
  Eigen::MatrixXd k_scratch_;  // the current stiffness, to look up its entry [N/m]
  Eigen::MatrixXd c_scratch_;  // the current damping matrix [N s/m]
  std::vector<int> visits_;    // per entry: grid points of this run met with its stiffness
  // The declined grid point as it was when the current loop iteration began, restored by
  // undo_iteration when a fork takes the iteration back.
  long declined_before_iteration_ = -1;
  int visited_ = -1;  // the cache entry whose visits this iteration counted (-1: none)
};

}  // namespace pound

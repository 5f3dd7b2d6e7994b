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
/// A row with a flexible foundation keeps them per building (ExactSteps' blocks).
struct ExactStepCache {
  static constexpr int kExactWarmup = 32;
  struct Entry {
    int block = 0;          ///< the block of DOFs it propagates (ExactSteps)
    Eigen::MatrixXd K;      ///< the block's tangent stiffness [N/m]
    std::uint64_t key = 0;  ///< hash of K's bits: most look-ups compare this alone (a
                            ///< deteriorating law meets a new stiffness at every excursion)
    bool ready = false;
    LinearStep step;
    // A building's block (ExactSteps::blocks_ of a row on flexible foundations): its step with
    // the rows padded to ld, a multiple of 4 (zeros below; stepped in place, step()), and the
    // accelerations' rows of its z' = A z + B w, padded to lda rows, for the derivative at the
    // step's end (rates()).
    int ld = 0, lda = 0;
    std::vector<double> phi, p1, p2;  ///< Phi (ld x ns), P1, P2 (ld x inputs), column-major
    std::vector<double> acc;          ///< A's rows n_d.. (lda x ns) [1/s^2, 1/s]
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
    visited_.clear();
  }
  void undo_iteration();

  /// After a switch: the stiffness is looked up again at the next exact step.
  void invalidate() {
    gate_ = -1;
    for (Block& b : blocks_) b.config = -1, b.offsets_ready = false;
  }
  /// Whether the propagators of the current tangent stiffness of `dyn` are ready (each added
  /// when new, formed at its kExactWarmup-th grid point), and with them the responses
  /// P1 [0; -M^-1] off to the branches' offsets.
  bool ready(const RowDynamics& dyn, const AssembledRow& row);
  /// The exact step of z = [u; v] from y0 into y1 (its other entries untouched) with the
  /// last r inputs (the ground channels' ag) ramping from a0 to a1 [m/s^2] (linear_step_apply).
  void step(int r, const double* a0, const double* a1, const Eigen::VectorXd& y0,
            Eigen::VectorXd& y1);
  /// The ramped inputs of a step: one per ground channel (one, at zero, without ground).
  static int ground_inputs(const RowDynamics& dyn) {
    return dyn.ground() ? dyn.ground()->channels() : 1;
  }
  /// Whether rates() gives the derivative at a step's end: a row on flexible foundations
  /// (per-building blocks) without massless DOFs. A row on fixed bases keeps RowDynamics::rhs.
  bool has_rates() const { return rates_; }
  /// The accelerations at the state y (after step(), with the same propagators) into
  /// dy(n + i) for every floor DOF i: z' = A z + B w of the blocks (row_system; docs/physics.md
  /// section 1 without contact forces), dv = A_v z - M^-1 off - ag, agc each ground channel's
  /// acceleration at y's time and agc[channel(i)] the one under DOF i [m/s^2]
  /// (FloorGround::channel_acc).
  void rates(const RowDynamics& dyn, const double* agc, const Eigen::VectorXd& y,
             Eigen::VectorXd& dy);

 private:
  // The DOFs a propagator steps: the whole row (a row on fixed bases: one propagator, its
  // numbers those of earlier versions), or one building of a row with a flexible foundation,
  // its floors then its base's sway and rotation. Between contacts the buildings do not
  // interact (K, C and M are block diagonal over them), so e^{A h} is block diagonal too and
  // each building's block is formed alone: when that building's tangent stiffness is new.
  struct Block {
    std::vector<int> state;  // its entries of z = [u; v]: its DOFs, then n + its DOFs
    int config = -1;         // its current stiffness' entry (-1: look it up again)
    bool offsets_ready = false;
    Eigen::VectorXd offsets_response;  // P1 of its offsets' columns times the offsets [m, m/s]
                                       // (padded to the entry's ld rows on flexible foundations)
    Eigen::VectorXd offsets_acc;       // -M^-1 off on its DOFs [m/s^2] (rates())
  };
  static void eliminate_massless(const RowDynamics& dyn, const Eigen::MatrixXd& K,
                                 const Eigen::MatrixXd& C, Eigen::MatrixXd& A, Eigen::MatrixXd& B);
  static const Eigen::VectorXd& dyn_inv_mass(const RowDynamics& dyn) { return dyn.inv_mass(); }
  // z' = A z + B w of the whole row at stiffness K (ready()).
  void row_system(const RowDynamics& dyn, const AssembledRow& row, const Eigen::MatrixXd& K,
                  Eigen::MatrixXd& A, Eigen::MatrixXd& B);
  static LinearStep block_step(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B, double h);
  static void pad_block(const Eigen::MatrixXd& Ab, int m, ExactStepCache::Entry& e);
  int find_entry(int block, const Eigen::MatrixXd& K);

  bool enabled_ = false;
  double h_ = 0.0;      // grid step [s]
  long point_ = 0;      // index of the last grid point reached
  long declined_ = -1;  // the grid point whose exact step was declined
  ExactStepCache own_cache_;
  ExactStepCache* cache_ = &own_cache_;
  std::vector<Block> blocks_;  // one (the whole row) or one per building
  bool whole_ = true;          // one block, the row in its own order
  bool rates_ = false;         // has_rates()
  int gate_ = -1;  // the entry of the row's stiffness, whose visits count the warm-up (-1: look
                   // it up again); whole_: the block's own
  Eigen::MatrixXd k_scratch_;   // the current stiffness, to look up its entry [N/m]
  Eigen::MatrixXd kb_scratch_;  // a block's part of it [N/m]
  Eigen::MatrixXd c_scratch_;   // the current damping matrix [N s/m]
  Eigen::VectorXd z1_, a1_;     // a block's state after its step, its accelerations
  std::vector<int> visits_;     // per entry: grid points of this run met with its stiffness
  // The declined grid point as it was when the current loop iteration began, restored by
  // undo_iteration when a fork takes the iteration back.
  long declined_before_iteration_ = -1;
  std::vector<int> visited_;  // the cache entries whose visits this iteration counted
};

}  // namespace pound

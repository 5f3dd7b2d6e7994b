#pragma once
// Newmark's average-acceleration method for the floors of a row (Chopra, Dynamics of
// Structures, sec. 5.4; the thesis' integrator for the buildings, Th. 8.8), solved for the
// end-of-step acceleration, which keeps m a = P exact for free bodies (momentum to round-off):
//   Mt a_{i+1} = p_{i+1} - C (v + h/2 a) - K (u + h v + h^2/4 a),  Mt = M + h/2 C + h^2/4 K
//   u_{i+1} = u + h v + h^2/4 (a + a_{i+1}),  v_{i+1} = v + h/2 (a + a_{i+1}).
// Mt^-1 is applied once, so that a step costs one matrix-vector product:
//   a_{i+1} = -sum_c (Mt^-1 M 1_c) ag_c - [Mt^-1 C, Mt^-1 K] [v + h/2 a; u + h v + h^2/4 a],
// 1_c the floors on ground channel c (issue 28: each building on its own ground; one column, at
// zero, for a row without ground). Kernel only: no files, no printing.
#include <Eigen/Dense>
#include <algorithm>

#include "ground/floor_ground.hpp"
#include "structure/building_row.hpp"

namespace pound::sears {

/// Mt = M + h/2 C + h^2/4 K for a step h [s].
Eigen::MatrixXd newmark_matrix(const AssembledRow& a, double h);

struct NewmarkOperator {
  Eigen::MatrixXd CK;  ///< [Mt^-1 C, Mt^-1 K], n x 2n (column-major) [1/s, 1/s^2]
  Eigen::MatrixXd g;   ///< Mt^-1 M 1_c, one column per ground channel c [-]

  NewmarkOperator(const AssembledRow& a, const Eigen::LLT<Eigen::MatrixXd>& mt,
                  const FloorGround& ground);
};

/// The ground inputs of a step: one per channel, or one (at zero) without ground.
inline int ground_inputs(const FloorGround& ground) {
  return std::max(ground.channels(), 1);
}

/// The floors' state u [m], v [m/s], acc [m/s^2] with Newmark's step.
struct NewmarkFloors {
  Eigen::VectorXd u, v, acc;
  Eigen::VectorXd work;  ///< scratch: [v + h/2 a; u + h v + h^2/4 a]

  /// a_next = Mt^-1 (p_{i+1} - C (v + h/2 a) - K (u + h v + h^2/4 a)) without contact forces,
  /// for a step h [s] whose end has ground accelerations ag_next [m/s^2], one per channel
  /// (FloorGround::channel_acc).
  void predict(double h, const NewmarkOperator& op, const double* ag_next, Eigen::VectorXd& a_next);
  /// The step's end from the end-of-step acceleration a_next.
  void update(double h, const Eigen::VectorXd& a_next);
};

}  // namespace pound::sears

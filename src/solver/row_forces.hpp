#pragma once
// The internal forces of the floors of a row (physics.md section 1; docs/hysteresis.md): the
// accelerations dv = -M^-1 (C v + f(u)) - ag of the row solver's right-hand side, with
//   - linear storeys: f = K u, from the bands of the tridiagonal K and Rayleigh C of shear
//     buildings (Th. 3.6; Chopra 11.4.1), or compressed rows when C is full (modal damping);
//   - piecewise-linear storeys (elastic, bilinear): f = K_t u + off, the bands of the current
//     tangent stiffness and the forces of the branches' offsets, rebuilt at every switch;
//   - other laws (Bouc-Wen): f_j = V_j - V_j+1 from the laws' shears, storey by storey.
// Each path costs O(nonzeros) and allocates nothing. Kernel only: no files, no printing.
#include <Eigen/Dense>
#include <vector>

#include "structure/building_row.hpp"

namespace pound {

class RowForces {
 public:
  /// `storeys` one per floor DOF of `row` (AssembledRow::storeys or elastic_storeys()).
  RowForces(const AssembledRow& row, const std::vector<RowStorey>& storeys);

  /// dv = -M^-1 (C v + K u) - ag [m/s^2] (linear storeys).
  void linear(const double* u, const double* v, double ag, double* dv) const;
  /// dv = -M^-1 (C v + K_t u + off) - ag with the lines of set_lines().
  void affine(const double* u, const double* v, double ag, double* dv) const;
  /// The tangent bands and offsets from every storey's current branch (branch_line()).
  void set_lines(const std::vector<StoreyState>& states);
  /// dv = -M^-1 (C v + f) - ag with f from the laws' shears at drifts d of u; the laws'
  /// continuous states are read at `x` + xoff[i] and their rates written at dy + xoff[i]
  /// (dy = the whole state derivative, dv = dy + n).
  void general(const Eigen::VectorXd& y, const std::vector<StoreyState>& states,
               const std::vector<int>& xoff, double ag, double* dy) const;
  /// C v [N].
  void damping(const double* v, double* cv) const;

 private:
  const AssembledRow& row_;
  const std::vector<RowStorey>& storeys_;
  const int n_;
  bool tridiagonal_ = false;                         // K and C tridiagonal
  std::vector<double> kl_, kd_, ku_, cl_, cd_, cu_;  // their bands [N/m], [N s/m]
  std::vector<int> row_start_, col_;                 // compressed rows of K and C
  std::vector<double> k_val_, c_val_;                // their entries [N/m], [N s/m]
  std::vector<double> tl_, td_, tu_, off_;           // K_t bands [N/m], offsets [N]
  mutable Eigen::VectorXd cv_;                       // scratch: C v [N]
};

}  // namespace pound

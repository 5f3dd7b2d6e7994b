#pragma once
// One building on its foundation (issue 29; docs/ssi.md, physics.md section 5a): the matrices of
// its floors and, on a flexible foundation, its base's sway u0 and rotation theta.
//
// Coordinates: U_j, floor j's horizontal displacement relative to the free-field ground under
// the building, U_j = u0 + H_j theta + (the storey deformations below floor j), H_j the floor's
// height above the base; then u0 and theta. So the mass matrix is diagonal (m_j; the base's m0;
// the rotary inertia I0 + trapped soil + sum of the floors' own J_j, every floor turning with
// the base), and the contact between neighbours acts on U (plus the ground's own displacement)
// as on a fixed base. Storey j's deformation, on which its law acts, is
//     d_j = U_j - U_j-1 - h_j theta    (U_0 = u0),
// and its P-Delta acts on its chord U_j - U_j-1 (the storey's tilt d_j / h_j + theta: gravity acts
// on the rotation too, the overturning moment of the floors' weights about the base). The
// foundation's springs and dashpots act on u0 and theta; the earthquake loads -m ag on every
// translating mass (the floors and m0), none on the rotation. The structure's own damping is the
// fixed-base building's (structure/building.hpp) acting on the deformations: C = T^T C_fixed T,
// T the map from (U, u0, theta) to the floors' displacements relative to the base,
// U_j - u0 - H_j theta. On a fixed base the matrices are the fixed-base ones.
// Kernel only: no files, no printing.
#include <Eigen/Dense>
#include <vector>

#include "structure/building.hpp"

namespace pound {

struct BaseMatrices {
  /// Degrees of freedom: the n floors, then (flexible foundation) sway and rotation.
  Eigen::MatrixXd M;          ///< diagonal: m_j [kg], m0 [kg], rotary inertia [kg m^2]
  Eigen::MatrixXd K0;         ///< the storeys' initial stiffnesses and the foundation springs
  Eigen::MatrixXd Kg;         ///< P-Delta on the storeys' chords (zero without): K0 - Kg acts
  Eigen::MatrixXd C;          ///< the structure's damping on the deformations, and the dashpots
  Eigen::VectorXd influence;  ///< per DOF: 1 where the earthquake loads -m ag, 0 (rotation)
  /// Undamped periods with the foundation, without P-Delta, longest first [s]; a massless sway
  /// or rotation is condensed out (it has no mode of its own).
  Eigen::VectorXd periods;
  /// Per period, its mode's damping ratio phi^T C phi / (2 omega phi^T M phi) [-] (exact for
  /// Rayleigh or modal damping; with a foundation's dashpots, which do not damp classically, the
  /// diagonal of the modal damping matrix). A raft on the cone's dashpots is overdamped (> 1).
  Eigen::VectorXd damping_ratios;
  std::vector<double> heights;  ///< H_j of floor j above the base [m]
  bool flexible = false;        ///< sway and rotation DOFs
  double rayleigh_a1 = 0.0;     ///< the fixed-base building's Rayleigh a1 [s] (tangent damping)
  /// The base DOFs (n: sway, n + 1: rotation) whose mass or rotary inertia was given but is
  /// taken as 0 (drop_light_base_masses): too light for their foundation's spring and dashpot.
  std::vector<int> light_base;
  int dofs() const { return static_cast<int>(M.rows()); }
};

/// The rates of a base DOF on its own, m s^2 + c s + k = 0 (its diagonal entries: m [kg or
/// kg m^2], c [N s/m or N m s], k [N/m or N m]): real roots -s, slow <= fast [1/s]
/// (2 k / (c + sqrt(c^2 - 4 m k)) and (c + sqrt(c^2 - 4 m k)) / (2 m) where it is overdamped;
/// k / c for both where m = 0), or, where it oscillates (real = false), |s| = sqrt(k / m) for both.
/// The one formula behind the stiff-root condensation (RowDynamics::condense_stiff_roots) and
/// the light-base rule (drop_light_base_masses).
struct BaseRoots {
  double slow = 0.0, fast = 0.0;  // [1/s]
  bool real = true;
};
BaseRoots base_roots(double m, double c, double k);

/// Issue 38: each of the base DOFs sway and rot of `out` whose own root (m s^2 + c s + k, the
/// diagonal entries) is faster than 1e4 / T_min, T_min the shortest of `fixed_periods` [s], is
/// taken as massless (its M entry set to 0, its index added to out.light_base): the quasi-static
/// limit of an inertial root no explicit step could follow.
void drop_light_base_masses(BaseMatrices& out, const Eigen::VectorXd& fixed_periods, int sway,
                            int rot);

/// The matrices of `b` on its foundation (b.foundation; fixed: the fixed-base building's).
BaseMatrices assemble_on_base(const Building& b);

/// The undamped modes of K x = w^2 M x (M diagonal; the DOFs whose mass is zero condensed
/// statically, K* = K_aa - K_ab K_bb^-1 K_ba on the others), longest period first: their
/// periods [s] and damping ratios phi^T C phi / (2 omega) for the mass-normalised shapes phi (a
/// massless DOF's entry from its equilibrium; 0 for omega = 0) [-].
struct ModalProperties {
  Eigen::VectorXd periods, damping_ratios;
};
ModalProperties modal_properties(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
                                 const Eigen::MatrixXd& C);

}  // namespace pound

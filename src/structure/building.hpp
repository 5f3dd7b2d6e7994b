#pragma once
// A lumped-mass shear building (physics.md section 1; Th. 3.6, 8.5): floors j = 1..n with
// masses m_j and storey stiffnesses k_j between floor j-1 and j (floor 0 is the ground).
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "hysteresis/storey_law.hpp"
#include "structure/foundation.hpp"

namespace pound {

enum class DampingKind {
  rayleigh,  ///< C = a0 M + a1 K with ratio xi on modes 1 and 2 (mass-proportional for 1 DOF)
  modal,     ///< classical modal damping, ratio xi on every mode
};

/// Which stiffness the stiffness-proportional part of Rayleigh damping uses (Charney 2008,
/// "Unintended consequences of modeling damping in structures", J. Struct. Eng. 134(4)).
enum class DampingStiffness {
  initial,  ///< C = a0 M + a1 K0, constant (the default)
  tangent,  ///< C = a0 M + a1 K_t: each storey's current tangent stiffness (at least 0)
};

struct Building {
  std::string name;                    ///< label for reports
  std::vector<double> masses;          ///< floor masses, floor 1 first [kg]
  std::vector<double> stiffnesses;     ///< storey stiffnesses, storey 1 first [N/m]
  std::vector<double> storey_heights;  ///< storey heights, for drift ratios [m]
  // Where its slabs stand (issue 36, structure/contact_geometry.hpp): floor j at base_elevation
  // plus the heights of storeys 1..j.
  double base_elevation = 0.0;  ///< the base's level against the row's datum [m] (a slope)
  double slab_thickness = 0.2;  ///< the slabs' thickness [m], > 0
  /// The share of a storey's stiffness in the columns of the face a neighbour's slab can
  /// strike [-], in (0, 1] (0.5: two of four corner columns).
  double face_column_share = 0.5;
  /// The shear strength of the struck face's columns together, per storey [N] (issue 36);
  /// empty: none (no column-shear ratio is reported).
  std::vector<double> column_shear_strength;
  double damping_ratio = 0.05;  ///< inherent damping ratio [-]
  DampingKind damping = DampingKind::rayleigh;
  /// Storey hysteresis (hysteresis/registry.hpp): "elastic", "bilinear", "bouc-wen" or "imk".
  /// The damping matrix stays the one built from the initial stiffnesses, constant through
  /// yielding.
  std::string hysteresis = "elastic";
  std::vector<double> yield_shears;  ///< storey yield shears Fy, storey 1 first [N]; may be
                                     ///< empty for "elastic" (no ductility is reported then)
  std::vector<double> hardening;     ///< post-yield stiffness ratio b per storey [-]; empty: 0.02
  std::vector<double> bw_n;          ///< Bouc-Wen sharpness n per storey [-]; empty: 2
  // The deteriorating law "imk" (hysteresis/imk.hpp), per storey; empty: the defaults of
  // StoreyParameters (docs/hysteresis.md). Drift ratios are of the storey heights.
  std::vector<double> cap_strength_ratio;       ///< Fc / Fy >= 1 [-]
  std::vector<double> plastic_drift_ratio;      ///< theta_p > 0, yield to cap [-]
  std::vector<double> post_cap_drift_ratio;     ///< theta_pc > 0, cap to zero strength [-]
  std::vector<double> ultimate_drift_ratio;     ///< theta_u, not below the cap [-]; empty: none
  std::vector<double> residual_strength_ratio;  ///< Fr / Fy in [0, 1) [-]
  std::vector<double> energy_capacity;          ///< lambda > 0, E_t = lambda Fy uy [-]
  std::vector<double> energy_exponent;          ///< c > 0 [-]
  /// P-Delta: the gravity load of the floors at and above storey j, P_j, acting on its drift
  /// d_j adds -P_j d_j / h_j to the storey shear (a geometric stiffness -P_j / h_j; e.g.
  /// Chopra, Dynamics of Structures, sec. 19.6 / FEMA P695 sec. 5.2.5).
  bool p_delta = false;
  std::vector<double> gravity_loads;  ///< gravity load per floor [N]; empty: m_j g
  DampingStiffness damping_stiffness = DampingStiffness::initial;
  /// The base on the soil (issue 29, structure/foundation.hpp): fixed (the default, the base
  /// moves with the ground), springs or a cone; a flexible one adds the base's sway and rotation
  /// to the row's DOFs (structure/building_on_base.hpp).
  Foundation foundation;

  int floors() const { return static_cast<int>(masses.size()); }
  bool inelastic() const { return hysteresis != "elastic"; }
  /// The parameters of storey j (0-based): k0, Fy (infinite when none), b, n, its height and
  /// the IMK parameters.
  StoreyParameters storey(int j) const;
  /// Gravity load of floor j (0-based) [N]: gravity_loads, or m_j g.
  double gravity_load(int j) const;
  /// P_j: the gravity load of floors j and above [N].
  double storey_gravity_load(int j) const;
  /// The geometric stiffness P_j / h_j of storey j with P-Delta [N/m]; 0 without.
  double geometric_stiffness(int j) const;
};

/// Mass, stiffness and damping matrices of one building (floor DOFs relative to the ground).
struct BuildingMatrices {
  Eigen::MatrixXd M, K, C;   ///< K from the initial storey stiffnesses, C from M and that K
  Eigen::MatrixXd Kg;        ///< geometric stiffness of P-Delta (zero without): K - Kg acts [N/m]
  Eigen::VectorXd periods;   ///< undamped periods of M and K (without P-Delta), longest first [s]
  double rayleigh_a0 = 0.0;  ///< Rayleigh C = a0 M + a1 K [1/s] (0 for modal damping)
  double rayleigh_a1 = 0.0;  ///< [s]
};

/// Assembles the matrices (Th. 3.6). Stiffness may be zero only for free bodies (no modes).
BuildingMatrices assemble(const Building& b);

/// Checks masses > 0, stiffnesses > 0, heights > 0, 0 <= xi < 1, matching lengths, a known
/// hysteresis law with its parameters (Fy > 0 for every storey of an inelastic law,
/// 0 <= b < 1, n > 0, Fc / Fy >= 1, theta_p, theta_pc, lambda, c > 0, 0 <= Fr / Fy < 1 and,
/// with "imk", theta_u not below the cap drift ratio uy / h + theta_p), gravity loads > 0 and
/// with P-Delta k0_j > P_j / h_j, tangent damping only with Rayleigh damping and a
/// piecewise-linear law, and the foundation (foundation_problem); throws InputError naming
/// `where` and the offending floor.
void validate(const Building& b, const std::string& where);
/// The part of validate() for gravity: loads > 0; with P-Delta every storey stiffer than its
/// geometric stiffness P / h (else it buckles under its own gravity load, the lateral stiffness
/// k0 - P / h being <= 0); tangent damping only with Rayleigh damping and piecewise-linear laws.
void validate_gravity(const Building& b, const std::string& where);

/// sum W_j H_j of the floors' gravity loads times their heights above the base [N m/rad]: the
/// rocking stiffness below which gravity overturns the building on its foundation.
double overturning_stiffness(const Building& b);

/// What is wrong with the IMK parameters of a storey ("" when nothing): each key with what is
/// valid (Fc / Fy >= 1; theta_p, theta_pc, lambda, c > 0; Fr / Fy in [0, 1); theta_u > 0 and,
/// when `imk` (the storey's law), not below the cap drift ratio uy / h + theta_p).
std::string imk_parameter_problem(const StoreyParameters& p, bool imk);

}  // namespace pound

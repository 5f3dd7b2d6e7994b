#pragma once
// Buildings standing in a row, left to right (physics.md section 1; thesis chapter 2: two
// buildings, a building between two others, a building at the end of a row). Floor j of
// building b and floor j of building b+1 can collide when both exist, so buildings of
// unequal height collide up to the lower roof.
#include <Eigen/Dense>
#include <vector>

#include "hysteresis/storey_law.hpp"
#include "structure/building.hpp"

namespace pound {

struct BuildingRow {
  std::vector<Building> buildings;
  /// gaps[p][j]: at-rest gap between building p and p+1 at floor level j+1 [m], one entry
  /// per colliding level (min of the two floor counts).
  std::vector<std::vector<double>> gaps;
};

/// One floor level of one adjacent pair where contact can happen.
struct ContactSite {
  int pair = 0;       ///< building pair index p (buildings p and p+1)
  int level = 0;      ///< floor level, 0-based (floor level+1)
  int dof_left = 0;   ///< global DOF of the left building's floor
  int dof_right = 0;  ///< global DOF of the right building's floor
  double gap = 0.0;   ///< at-rest gap [m]
};

/// The storey below one floor DOF (storey j joins floor j-1, or the ground, to floor j). A
/// building on a flexible foundation (structure/building_on_base.hpp) has two DOFs more, its
/// base's sway and rotation, each held by its foundation spring as by a linear "storey" on the
/// ground (`foundation`); its storeys' deformations are d = u_dof - u_below - h u_rot.
struct RowStorey {
  const StoreyLaw* law = nullptr;  ///< hysteresis/registry.hpp
  StoreyParameters p;              ///< k0 = the storey stiffness of K
  int below = -1;                  ///< global DOF of the floor below, -1 for the ground
  int above = -1;                  ///< global DOF of the floor above, -1 for the roof
  int building = 0;                ///< 0-based
  /// The building's base rotation DOF (-1: a fixed base): the deformation loses h theta, h the
  /// storey's height p.h [m] (issue 29).
  int rot = -1;
  /// The spring of a base DOF on the ground (sway or rotation), not a storey of floors: no
  /// drift ratio, collapse or ductility (issue 29).
  bool foundation = false;
  /// P-Delta: the geometric stiffness P / h of the storey [N/m] (0 without): the storey's shear
  /// is the law's V minus kg times its drift.
  double kg = 0.0;
  /// Tangent-stiffness damping (DampingStiffness::tangent): the building's Rayleigh a1 [s]; the
  /// storey's stiffness-proportional damping is then a1 max(k_t, 0) instead of a1 k0. 0: the
  /// initial stiffness' damping.
  double damping_a1 = 0.0;
};

/// The assembled row: block-diagonal matrices over all floors, building after building.
/// K is built from the initial storey stiffnesses (and C from it and M); a storey whose law is
/// not linear replaces its K contribution by its shear (see storeys).
struct AssembledRow {
  /// M, C from the initial storey stiffnesses, and K: the initial storey stiffnesses minus the
  /// geometric stiffness of P-Delta (K = K0 - Kg), the stiffness that acts.
  Eigen::MatrixXd M, C, K;
  Eigen::MatrixXd Kg;                    ///< geometric stiffness of P-Delta [N/m] (zero without)
  Eigen::VectorXd inv_mass;              ///< 1 / M_ii [1/kg]
  std::vector<int> offset;               ///< first global DOF of each building
  std::vector<Eigen::VectorXd> periods;  ///< per building [s]
  /// Per building, the damping ratio of each period's mode [-] (BaseMatrices::damping_ratios).
  std::vector<Eigen::VectorXd> damping_ratios;
  std::vector<ContactSite> sites;
  std::vector<RowStorey> storeys;  ///< one per floor DOF
  bool linear = true;              ///< every storey law linear (elastic)
  int dofs() const { return static_cast<int>(inv_mass.size()); }
  // Foundations (issue 29): the floors' DOFs come first, building after building (offset); the
  // bases' sway and rotation of the buildings on a flexible foundation follow them.
  int floors = 0;                ///< floor DOFs (the first `floors` DOFs)
  std::vector<int> sway, rot;    ///< per building its base DOFs, -1 on a fixed base
  std::vector<int> building_of;  ///< per DOF its building (0-based)
  /// Per DOF 1 where the earthquake loads -m ag (floors, base sway), 0 on a rotation.
  Eigen::VectorXd influence;
  /// Per DOF the foundation's dashpot on a base DOF, C_x on a sway [N s/m] and C_theta on a
  /// rotation [N m s/rad], 0 elsewhere: C = T^T C_fixed T + diag(base_damping)
  /// (structure/building_on_base.hpp). Empty for a row built by hand.
  std::vector<double> base_damping;
  /// Per DOF: no mass (a foundation whose mass or rotary inertia is 0): a first-order DOF held by
  /// its dashpot; inv_mass is 0 there.
  std::vector<char> massless;
  bool any_massless() const {
    for (char m : massless)
      if (m) return true;
    return false;
  }
};

/// The deformation of DOF i's storey at displacements u [m]: u_i - u_below - h u_rot (the ground
/// and a fixed base contribute nothing; a foundation spring's is its DOF's displacement).
inline double storey_drift(const RowStorey& s, int i, const double* u) {
  double d = u[i];
  if (s.below >= 0) d -= u[s.below];
  if (s.rot >= 0) d -= s.p.h * u[s.rot];
  return d;
}
/// Its chord u_i - u_below, on which P-Delta acts [m] (the deformation plus the base's tilt).
inline double storey_chord(const RowStorey& s, int i, const double* u) {
  return s.below >= 0 ? u[i] - u[s.below] : u[i];
}

/// Linear elastic storeys for an assembled row built by hand (free bodies, tests): the storey
/// stiffness k_i = K(i, i) + K(i, i+1) and the floors below from the building offsets.
std::vector<RowStorey> elastic_storeys(const AssembledRow& a);

/// The shortest positive finite undamped period of the row's buildings [s]; infinity when none
/// (free bodies).
double shortest_period(const AssembledRow& a);
/// The shortest period of a mode that oscillates [s]: of the periods whose mode's damping ratio
/// is below 1 (an overdamped mode, a raft on its radiation dashpots, does not oscillate: it
/// needs no steps of a twentieth of its undamped period). The solvers' automatic step
/// (T_min / 20) is taken from it. shortest_period(a) when the ratios are not known.
double step_period(const AssembledRow& a);

/// Number of colliding levels of pair p (min floor count).
int colliding_levels(const BuildingRow& row, int pair);
AssembledRow assemble(const BuildingRow& row);

}  // namespace pound

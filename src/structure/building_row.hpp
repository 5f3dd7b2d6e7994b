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

/// The storey below one floor DOF (storey j joins floor j-1, or the ground, to floor j).
struct RowStorey {
  const StoreyLaw* law = nullptr;  ///< hysteresis/registry.hpp
  StoreyParameters p;              ///< k0 = the storey stiffness of K
  int below = -1;                  ///< global DOF of the floor below, -1 for the ground
  int above = -1;                  ///< global DOF of the floor above, -1 for the roof
  int building = 0;                ///< 0-based
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
  std::vector<ContactSite> sites;
  std::vector<RowStorey> storeys;  ///< one per floor DOF
  bool linear = true;              ///< every storey law linear (elastic)
  int dofs() const { return static_cast<int>(inv_mass.size()); }
};

/// Linear elastic storeys for an assembled row built by hand (free bodies, tests): the storey
/// stiffness k_i = K(i, i) + K(i, i+1) and the floors below from the building offsets.
std::vector<RowStorey> elastic_storeys(const AssembledRow& a);

/// The shortest positive finite undamped period of the row's buildings [s]; infinity when none
/// (free bodies).
double shortest_period(const AssembledRow& a);

/// Number of colliding levels of pair p (min floor count).
int colliding_levels(const BuildingRow& row, int pair);
AssembledRow assemble(const BuildingRow& row);

}  // namespace pound

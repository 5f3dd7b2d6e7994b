#pragma once
// Buildings standing in a row, left to right (physics.md section 1; thesis chapter 2: two
// buildings, a building between two others, a building at the end of a row). The contact
// sites of each adjacent pair follow from the floors' elevations (issue 36,
// structure/contact_geometry.hpp): slab to slab where floors align, a slab against the
// neighbour's columns between its floors otherwise. A site is a pair of weighted lists of DOFs
// (SitePoint) with its series stiffness and apparent masses: the solvers, the event stepper and
// the recorder see sites, never their kind.
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "hysteresis/storey_law.hpp"
#include "structure/building.hpp"
#include "structure/contact_geometry.hpp"

namespace pound {

struct BuildingRow {
  std::vector<Building> buildings;
  /// gaps[p][k]: at-rest gap between building p and p+1 at the pair's site k [m], one entry
  /// per site of pair_sites() (with aligned floors: per colliding floor level).
  std::vector<std::vector<double>> gaps;
};

/// One side of a contact site: the point that strikes or is struck, u = sum w_k u_{dof_k} over
/// at most three DOFs (physics.md section 5b). A slab: its floor, weight 1. A point on a column
/// of storey j at xi (s = column_shape(xi)): floor j-1 (the base's sway where j-1 is the base;
/// nothing on a fixed base) with 1 - s, floor j with s, and on a rocking base its rotation with
/// h (xi - s) (the storey's chord turns with the base: u = u_{j-1} + xi h theta + s d_j, d_j =
/// u_j - u_{j-1} - h theta). A force F on the point loads each DOF with w_k F (virtual work).
struct SitePoint {
  int count = 0;
  std::array<int, 3> dof{{-1, -1, -1}};
  std::array<double, 3> weight{{0.0, 0.0, 0.0}};
  /// sum w_k x[dof_k] (x: displacements or velocities of the DOFs).
  double of(const double* x) const {
    double r = weight[0] * x[dof[0]];
    for (int k = 1; k < count; ++k) r += weight[k] * x[dof[k]];
    return r;
  }
  void add(int d, double w) {
    dof[count] = d;
    weight[count] = w;
    ++count;
  }
};

/// One contact site of one adjacent pair.
struct ContactSite {
  int pair = 0;   ///< building pair index p (buildings p and p+1)
  int level = 0;  ///< the site's index within its pair, 0-based (aligned floors: floor level)
  SitePoint left, right;  ///< the left and right building's points
  /// A DOF of each side's building: its slab's floor DOF (a slab side), or the struck storey's
  /// upper floor (a column side). The damped Sears path finds its bars' floors here (a column
  /// side has no bar; sears/sears_row_layout.hpp).
  int dof_left = 0, dof_right = 0;
  double gap = 0.0;       ///< at-rest gap [m]
  SiteGeometry geometry;  ///< kind, striking slab, struck floor or storey, xi
  /// The struck columns' stiffness at the point [N/m], in series with the contact law
  /// (column_point_stiffness); infinite at a slab site.
  double column_stiffness = std::numeric_limits<double>::infinity();
  /// Each side's apparent mass 1 / sum(w_k^2 / m_k) [kg] (a slab: its floor mass; a DOF
  /// without mass, a fixed base or a massless foundation, adds nothing).
  double mass_left = 0.0, mass_right = 0.0;
  // Column sites: the struck storey, for its columns' shear (column_shear_demand).
  int struck_dof = -1;      ///< the DOF of the struck storey's upper floor j (-1: a slab site)
  double face_share = 0.0;  ///< phi, the struck face's share of the storey's stiffness [-]
  double shape = 1.0;       ///< s = column_shape(xi) [-]
  /// The contact force F >= 0 loads the struck building toward +x (the right building: +1) or
  /// toward -x (the left one: -1).
  double struck_sign = 1.0;
  bool column() const { return geometry.kind == SiteKind::column; }
};

/// The shear demand on the struck face's columns at a column site [N] (issue 36; physics.md
/// section 5b): V_sway = phi V_j, the face's share of storey j's shear V_j (the storey law's
/// force, signed with the drift u_j - u_{j-1}), and the load P = struck_sign F on the struck
/// point (positive toward +x), which adds P (1 - s) below the point and -P s above it:
///   demand = max(|V_sway + P (1 - s)|, |V_sway - P s|)
/// (Karayannis & Favvata 2005: the struck column critical in shear). Without contact (F = 0)
/// it is |V_sway|.
inline double column_shear_demand(const ContactSite& s, double storey_shear, double force) {
  const double v = s.face_share * storey_shear, p = s.struck_sign * force;
  const double below = v + p * (1.0 - s.shape), above = v - p * s.shape;
  return std::max(std::fabs(below), std::fabs(above));
}

/// A slab site as before issue 36: each side one DOF of weight 1, its slab's floor (dof_left,
/// dof_right), so that sum w_k u_k is that floor's u (the per-step fast paths of RowDynamics and
/// the damped Sears path).
inline bool slab_site(const ContactSite& s) {
  return !s.column() && s.struck_dof < 0 && s.left.count == 1 && s.right.count == 1 &&
         s.left.weight[0] == 1.0 && s.right.weight[0] == 1.0 && s.left.dof[0] == s.dof_left &&
         s.right.dof[0] == s.dof_right;
}

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

/// A slab-to-slab site between floor DOFs dof_left and dof_right of a row built by hand (free
/// bodies, tests): weight 1 each, the masses from a.inv_mass (set before).
ContactSite floor_site(const AssembledRow& a, int pair, int level, int dof_left, int dof_right,
                       double gap);

/// The site in words for messages: "building A floor 3 against building B floor 3 (slab to
/// slab)" or "... against building B storey 2 at xi 0.40 (slab to column)", names from `row`.
std::string describe_site(const BuildingRow& row, const ContactSite& s);

/// The contact sites of every pair in words, one line each (no newline): a pair whose floors
/// all meet their namesakes slab to slab in one line ("pair 1 (A | B): floors 1-3 slab to
/// slab"), otherwise one line per site, "pair 1 site 2: " + describe_site().
std::vector<std::string> describe_sites(const BuildingRow& row);

/// Number of contact sites of pair p (pair_sites(); aligned floors: the lower floor count).
int colliding_levels(const BuildingRow& row, int pair);
AssembledRow assemble(const BuildingRow& row);

}  // namespace pound

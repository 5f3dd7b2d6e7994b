#pragma once
// The foundation under a building (issue 29, docs/ssi.md, physics.md section 5a): a rigid base
// that sways (horizontal displacement u0) and rocks (rotation theta) on the soil, held by
// springs and dashpots. Three kinds:
//   fixed    the base moves with the ground (no foundation degrees of freedom): today's model;
//   springs  the sway and rocking springs and dashpots given directly;
//   cone     a rigid circular surface footing of radius r on a homogeneous half-space (shear
//            wave velocity Vs, density rho, Poisson's ratio nu), with the frequency-independent
//            constants of Wolf's cone model (Wolf 1994, "Foundation Vibration Analysis Using
//            Simple Physical Models", Prentice Hall, ch. 2; Wolf & Deeks 2004, "Foundation
//            Vibration Analysis: A Strength-of-Materials Approach", Elsevier, ch. 3);
//   gazetas  a rigid rectangular surface footing (length along the row, width across it) on the
//            same half-space, with Gazetas' (1991) static stiffnesses and radiation dashpots
//            ("Foundation vibrations", ch. 15 of H.-Y. Fang (ed.), Foundation Engineering
//            Handbook, 2nd ed., Van Nostrand Reinhold, Table 15.1).
// The solvers take it through structure/building_on_base.hpp: the base's sway and rotation are
// degrees of freedom of the row (docs/ssi.md, "In the solvers").
#include <complex>
#include <string>
#include <vector>

namespace pound {

enum class FoundationKind {
  fixed,    ///< the base moves with the ground (the default)
  springs,  ///< sway and rocking springs and dashpots given directly
  cone,     ///< Wolf's cone: a rigid disk on a homogeneous half-space
  gazetas,  ///< Gazetas 1991: a rigid rectangle on a homogeneous half-space
};

/// Whether the kind stands on the soil's Vs, rho and nu (cone, gazetas).
inline bool on_soil(FoundationKind k) {
  return k == FoundationKind::cone || k == FoundationKind::gazetas;
}

/// The kind's name in study files: "fixed", "springs", "cone" or "gazetas".
const char* foundation_kind_name(FoundationKind k);
/// "fixed, springs, cone or gazetas", for messages.
std::string foundation_kind_names();
/// The kind named `name`; false (kind untouched) when there is none.
bool parse_foundation_kind(const std::string& name, FoundationKind& kind);

/// The foundation as given, SI. Each kind reads its own fields; the others are ignored.
struct Foundation {
  FoundationKind kind = FoundationKind::fixed;
  // springs: the sway spring between the base and the ground, the rocking spring about the
  // base, and their dashpots.
  double sway_stiffness = 0.0;     ///< K_x > 0 [N/m]
  double rocking_stiffness = 0.0;  ///< K_theta > 0 [N m/rad]
  double sway_damping = 0.0;       ///< C_x > 0 [N s/m]
  double rocking_damping = 0.0;    ///< C_theta > 0 [N m s/rad]
  // cone: the footing and the half-space under it (gazetas: the same soil).
  double radius = 0.0;  ///< r > 0, of the rigid circular footing [m]
  double length = 0.0;  ///< gazetas: the rectangle's side along the row (sway, rocking) [m]
  double width = 0.0;   ///< gazetas: its side across the row [m]
  double soil_shear_velocity = 0.0;  ///< Vs > 0 [m/s]
  double soil_density = 0.0;         ///< rho > 0 [kg/m^3]
  double soil_poisson = 0.0;         ///< nu in [0, 0.5) [-]
  // Every kind but fixed: the base's own mass and rotary inertia, and the floors' rotary
  // inertias (each floor turns with the base).
  double foundation_mass = 0.0;     ///< m_0 >= 0, the base slab's mass [kg]
  double foundation_inertia = 0.0;  ///< I_0 >= 0, the base's rotary inertia about the base [kg m^2]
  /// J_j >= 0, floor j's rotary inertia about its own centre [kg m^2], floor 1 first; empty: 0
  /// for every floor (else one per floor).
  std::vector<double> floor_inertias;

  bool flexible() const { return kind != FoundationKind::fixed; }
};

/// The constants a solver needs, SI, however the foundation was given. For `fixed` every one is
/// 0 (no foundation degrees of freedom).
struct FoundationConstants {
  FoundationKind kind = FoundationKind::fixed;
  double sway_stiffness = 0.0;     ///< K_x [N/m]
  double rocking_stiffness = 0.0;  ///< K_theta [N m/rad]
  double sway_damping = 0.0;       ///< C_x [N s/m]
  double rocking_damping = 0.0;    ///< C_theta [N m s/rad]
  /// Delta M_theta: the soil trapped under a cone footing for nu > 1/3 that rocks with it
  /// [kg m^2]; included in foundation_inertia. 0 for springs and for nu <= 1/3.
  double trapped_rocking_inertia = 0.0;
  double foundation_mass = 0.0;        ///< m_0 [kg]
  double foundation_inertia = 0.0;     ///< I_0 + Delta M_theta, about the base [kg m^2]
  std::vector<double> floor_inertias;  ///< J_j per floor [kg m^2]; empty: 0 for every floor
  // The cone's own parameters (cone only; 0 otherwise), for docs/ssi.md and for a solver that
  // models the rocking cone's frequency dependence.
  double sway_aspect_ratio = 0.0;      ///< z0 / r of the translational cone [-]
  double rocking_aspect_ratio = 0.0;   ///< z0 / r of the rocking cone [-]
  double rocking_wave_velocity = 0.0;  ///< c of the rocking cone: Vp, at most 2 Vs [m/s]
  /// M_theta = rho I0 z0: the rotary inertia of the rocking cone's internal degree of freedom,
  /// joined to the base by the dashpot C_theta (spring-dashpot-mass model; docs/ssi.md). Not
  /// part of the frequency-independent model [kg m^2].
  double rocking_internal_inertia = 0.0;

  /// J_j of floor j (0-based) [kg m^2]: floor_inertias[j], or 0 when none are given.
  double floor_inertia(std::size_t j) const {
    return j < floor_inertias.size() ? floor_inertias[j] : 0.0;
  }
};

/// The constants of `f` (the cone's formulas are in foundation.cpp with their sources).
FoundationConstants foundation_constants(const Foundation& f);

/// The dynamic stiffnesses S(omega) = K(omega) + i omega C(omega) of the foundation at circular
/// frequency omega [rad/s] (force per displacement [N/m], moment per rotation [N m/rad]).
struct DynamicStiffness {
  std::complex<double> sway;
  std::complex<double> rocking;
};
/// The frequency-independent model: K + i omega C (rocking: minus omega^2 Delta M_theta).
DynamicStiffness constant_dynamic_stiffness(const Foundation& f, double omega);
/// The cone itself, frequency dependent (cone only; springs: as constant_dynamic_stiffness):
/// sway K (1 + i b0), b0 = omega z0 / Vs, which is K + i omega C exactly; rocking
/// K [1 - b0^2 / (3 (1 + b0^2))] + i omega C b0^2 / (1 + b0^2) - omega^2 Delta M_theta,
/// b0 = omega z0 / c (docs/ssi.md derives both).
DynamicStiffness cone_dynamic_stiffness(const Foundation& f, double omega);

/// What is wrong with `f` for a building of `floors` floors ("" when nothing): the key of the
/// study file that holds the bad value and what is valid. Only the fields of f's kind are
/// checked, and the masses and inertias for every kind.
std::string foundation_problem(const Foundation& f, int floors);

}  // namespace pound

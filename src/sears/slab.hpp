#pragma once
// A floor slab (or pendulum mass) idealised as a free-free axial bar: the distributed-mass
// body of the damped Sears impact model (Khatiwada thesis, ch. 7 and 8; docs/sears.md).
//
// The bar keeps the body's length and mass; its effective cross-section follows from the mass,
// A = m / (rho l), so that rho A l = m (Th. 8.3 and physics.md section 3). Its free-free axial
// modes are cos(n pi x / l), n = 0 (rigid body), 1, 2, ..., with circular frequencies
// w_n = n pi c / l (Th. 7.6) and c = chi sqrt(E / rho) the effective wave speed; chi is the
// thesis' wave-speed reduction factor (1/8 for RC slabs and steel pendulums, ch. 7 and 8).
namespace pound::sears {

struct Slab {
  double length_m = 0.0;   ///< l: length along the line of impact [m]
  double E_Pa = 0.0;       ///< Young's modulus [Pa]
  double rho_kg_m3 = 0.0;  ///< density [kg/m^3]
  double poisson = 0.0;    ///< Poisson's ratio [-] (enters the Hertz stiffness only)
  double mass_kg = 0.0;    ///< m: mass of the body (floor mass in a building) [kg]
  double chi = 1.0 / 8.0;  ///< wave-speed factor, c = chi sqrt(E/rho) [-]

  /// Effective cross-section A = m / (rho l) [m^2].
  double area_m2() const { return mass_kg / (rho_kg_m3 * length_m); }
  /// Effective axial wave speed c = chi sqrt(E / rho) [m/s].
  double wave_speed() const;
  /// Circular frequency of free-free axial mode n >= 1, w_n = n pi c / l [rad/s] (Th. 7.14).
  double omega(int n) const;
  /// Period of the first axial mode, 2 l / c [s] (thesis Table 8.1).
  double first_mode_period() const;
  /// Generalised (modal) mass of every internal mode, int rho A cos^2 dx = m / 2 [kg].
  double modal_mass() const { return 0.5 * mass_kg; }
  /// Characteristic impedance rho A c = m c / l [N s/m] (wave limit of the contact).
  double impedance() const { return mass_kg * wave_speed() / length_m; }
};

/// Throws InputError naming `what` ("bar 1", "building 2 floor 3") unless every property is
/// finite and positive (Poisson in [0, 0.5), chi in (0, 1]).
void validate(const Slab& slab, const char* what);

}  // namespace pound::sears

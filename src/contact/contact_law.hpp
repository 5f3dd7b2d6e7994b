#pragma once
// The interface every lumped-mass contact force model implements (physics.md section 2).
// Sign conventions: delta [m] is the penetration (> 0 in contact), ddelta [m/s] its rate
// (> 0 while the bodies approach), v0 [m/s] the approach velocity when the contact began
// (> 0). The force [N] is compressive when positive.
#include <memory>
#include <string>

namespace pound {

/// Parameters shared by the lumped contact models. Each model documents which it uses.
struct ContactParameters {
  double k = 0.0;   ///< contact stiffness: [N/m] for linear laws, [N/m^1.5] for Hertz laws
  double e = 0.65;  ///< nominal coefficient of restitution [-], in (0, 1]
  double m1 = 0.0;  ///< mass of the left colliding body (floor) [kg]
  double m2 = 0.0;  ///< mass of the right colliding body (floor) [kg]
  /// Smallest approach velocity used where a model divides by v0 [m/s]. Grazing contacts in
  /// buildings can start with v0 near 0; the v0-scaled damping terms would then become
  /// arbitrarily stiff. Below v0_min the damping is that of a contact starting at v0_min.
  double v0_min = 1e-3;
  /// Variant of the damping-restitution relation where a model offers one ("exact" or
  /// "published"); see the model's documentation.
  std::string xi_relation = "exact";
};

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;
  /// Contact force [N] while the contact is active. delta may be slightly negative at the
  /// located instant of separation; laws return a finite value there.
  virtual double force(double delta, double ddelta, double v0) const = 0;
  /// True for instantaneous-impact models (no force history; velocity jump at impact).
  virtual bool impulsive() const { return false; }
  /// Coefficient of restitution applied by an impulsive model.
  virtual double restitution() const { return 1.0; }
};

/// Reduced mass m1 m2 / (m1 + m2) [kg].
inline double reduced_mass(double m1, double m2) {
  return m1 * m2 / (m1 + m2);
}

}  // namespace pound

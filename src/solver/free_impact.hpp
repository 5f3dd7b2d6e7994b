#pragma once
// Two free bodies colliding once through a lumped contact model (`pound impact`): masses m1
// (left, moving right at v0) and m2 (right, at rest), no springs, no ground motion.
#include "contact/contact_law.hpp"
#include "contact/impact_result.hpp"
#include "solver/integrator_settings.hpp"

namespace pound {

struct FreeImpactSpec {
  double m1 = 1.0;  ///< [kg]
  double m2 = 1.0;  ///< [kg]
  double v0 = 1.0;  ///< approach velocity, > 0 [m/s]
};

/// Simulates the impact until the bodies separate for good and reports e_eff, duration,
/// impulse, peak force, maximum penetration and the velocities after.
ImpactResult simulate_free_impact(const ContactLaw& law, const FreeImpactSpec& spec,
                                  const IntegratorSettings& integ);

}  // namespace pound

#pragma once
// What a single free two-body impact (`pound impact`) reports, for every contact model.
#include <limits>

namespace pound {

struct ImpactResult {
  double e_eff = 0.0;               ///< separation over approach velocity (rigid-body) [-]
  double contact_duration_s = 0.0;  ///< first contact to final separation [s]
  double impulse_Ns = 0.0;          ///< integral of the contact force [N s]
  double peak_force_N = 0.0;        ///< [N]
  double max_penetration_m = 0.0;   ///< [m]
  double v1_after = 0.0;            ///< body 1 (centre-of-mass) velocity after separation [m/s]
  double v2_after = 0.0;            ///< body 2 (centre-of-mass) velocity after separation [m/s]
  int contact_phases = 0;           ///< separate contact phases (1 unless bars chatter)
  /// Energy left in the internal vibration of each bar after separation [J] (damped Sears
  /// model only; NaN for lumped models).
  double internal_energy1_J = std::numeric_limits<double>::quiet_NaN();
  double internal_energy2_J = std::numeric_limits<double>::quiet_NaN();
};

}  // namespace pound

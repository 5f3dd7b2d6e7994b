#pragma once
// Bouc-Wen storey (Bouc 1967; Wen 1976, "Method for random vibration of hysteretic systems",
// J. Eng. Mech. Div. ASCE 102(2), 249-263), in the form of the issue:
//     V = b k0 d + (1 - b) k0 z,
//     dz/dt = dd [1 - |z|^n (gamma + beta sgn(dd z))],   beta = gamma = 1 / (2 uy^n),
// uy = Fy / k0, so that z saturates at the yield drift (loading: dz/dd = 1 - |z/uy|^n;
// unloading: dz/dd = 1). Smooth: no switching events; z is a continuous state (x[0]), and so
// is the hysteretic energy (x[1]),
//     dE_h/dt = (1 - b) k0 z (dd - dz/dt) = (1 - b) k0 |z|^n (gamma z dd + beta |z dd|) >= 0,
// with the recoverable energy U = k0 (b d^2 + (1 - b) z^2) / 2.
// Incremental form: dz/dd along the drift path, by classical Runge-Kutta in d with sub-steps
// of at most uy / (50 n) (the loading slope is -n / uy at saturation), energy alongside.
#include "hysteresis/storey_law.hpp"

namespace pound {

class BoucWenStorey final : public StoreyLaw {
 public:
  const char* name() const override { return "bouc-wen"; }
  int continuous_states() const override { return 2; }
  double shear(const StoreyParameters& p, const StoreyState& s, double d,
               const double* x) const override;
  void rates(const StoreyParameters& p, const StoreyState& s, double d, double dd, const double* x,
             double* dxdt) const override;
  double dissipated(const StoreyParameters& p, const StoreyState& s, double d,
                    const double* x) const override;
  double stored(const StoreyParameters& p, const StoreyState& s, double d,
                const double* x) const override;
  double advance(const StoreyParameters& p, const StoreyState& committed, double d0, double d1,
                 StoreyState& trial) const override;

  /// dz/dd for drift direction `sign` (+1 or -1) at z [-].
  static double slope(const StoreyParameters& p, double z, double sign);
};

}  // namespace pound

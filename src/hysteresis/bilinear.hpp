#pragma once
// Bilinear storey with kinematic hardening: the law of OpenSees' Steel01 without isotropic
// hardening (Filippou, Popov & Bertero 1983; Chopra, Dynamics of Structures, sec. 7.1 for the
// elastic-perfectly-plastic case b = 0). Initial stiffness k0, yield shear Fy, post-yield
// stiffness b k0; the two bounding lines V = b k0 d +- (1 - b) Fy translate with the plastic
// drift. Written as V = k0 (b d + (1 - b) z) with z an elastic-perfectly-plastic drift:
//   branch 0 (elastic):     z = z_a + (d - d_a),   |z| <= uy
//   branch +-1 (yielding):  z = +-uy, while the drift keeps growing in that direction
// Switches (kinks of V, located as events by the row solver):
//   elastic -> yielding where |z| reaches uy:   value (z^2 - uy^2) / (2 uy), rate z dd / uy
//   yielding -> elastic where the drift rate reverses:   value -branch dd, rate -branch ddd
// Hysteretic energy: (1 - b) Fy |d - d_a| per yielding branch (plastic work of the EPP part);
// recoverable energy U = k0 (b d^2 + (1 - b) z^2) / 2.
#include "hysteresis/storey_law.hpp"

namespace pound {

class BilinearStorey final : public StoreyLaw {
 public:
  const char* name() const override { return "bilinear"; }
  double shear(const StoreyParameters& p, const StoreyState& s, double d,
               const double* x) const override;
  int switches() const override { return 1; }
  SwitchValue switch_value(int i, const StoreyParameters& p, const StoreyState& s, double d,
                           double dd, double ddd) const override;
  void on_switch(int i, const StoreyParameters& p, StoreyState& s, double d,
                 const double* x) const override;
  bool branch_line(const StoreyParameters& p, const StoreyState& s, double& slope,
                   double& offset) const override;
  bool safe_drift(const StoreyParameters& p, const StoreyState& s, double& lo,
                  double& hi) const override;
  double dissipated(const StoreyParameters& p, const StoreyState& s, double d,
                    const double* x) const override;
  double stored(const StoreyParameters& p, const StoreyState& s, double d,
                const double* x) const override;
  double advance(const StoreyParameters& p, const StoreyState& committed, double d0, double d1,
                 StoreyState& trial) const override;

  /// The hysteretic drift z [m] at drift d in state s.
  static double z_of(const StoreyParameters& p, const StoreyState& s, double d);
};

}  // namespace pound

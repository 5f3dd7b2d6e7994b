#pragma once
// Peak-oriented modified Ibarra-Medina-Krawinkler storey (Ibarra, Medina & Krawinkler 2005,
// "Hysteretic models that incorporate strength and stiffness deterioration", Earthquake Eng.
// Struct. Dyn. 34(12), 1489-1511; Lignos & Krawinkler 2011, "Deterioration modeling of steel
// components in support of collapse prediction of steel moment frames under earthquake
// loading", J. Struct. Eng. 137(11), 1291-1302), with the rules of OpenSees' uniaxial material
// IMKPeakOriented (A. Elkady, H. Eljisr and K. Ichinohe; its branch form of October 2022 and the
// September 2023 revision, SRC/material/uniaxial/IMKPeakOriented.cpp), written here as exact
// piecewise-linear branches; docs/hysteresis.md lists where the two codes and this law differ.
// Issue 23 states the rules; docs/hysteresis.md explains them with the parameters' defaults.
//
// Parameters (StoreyParameters; drift ratios are of the storey height h [m]): k0 [N/m], Fy [N],
// Fc / Fy >= 1, theta_p > 0, theta_pc > 0, theta_u, Fr / Fy in [0, 1), lambda > 0, c > 0. With
// uy = Fy / k0 [m], one value lambda and c for all four deterioration modes:
//     E_t = lambda Fy uy [J]                                  (reference energy)
//     Kp  = (Fc - Fy) / (theta_p h),  Kpc = Fc / (theta_pc h)   [N/m]
// Backbone of each direction (written for the positive one, the negative one mirrored):
//     elastic      V = k0 d                        up to (uy, Fy)
//     post-yield   V = Fy + Kp (d - uy)            up to the cap (uy + theta_p h, Fc)
//     post-capping V = Fc - Kpc (d - d_cap)        down to Fr
//     residual     V = Fr                          up to theta_u h
// and no force from theta_u h on (reaching it fails the storey), for ever.
//
// Branches (StoreyState::branch = side x kind; side +1 or -1 is the sign of the shear on it,
// "toward" meaning the drift grows in that direction; 0 before the first yield):
//   0 elastic         V = k0 d until |d| reaches uy (then post-yield of that side)
//   1 unloading       V = V_L + Ku (d - d_L), the line of slope Ku through the last reversal
//                     point L = (d_L, V_L); the storey may move either way on it (OpenSees'
//                     branch 1: small vibrations on it are no events). Ends where the shear
//                     crosses zero, at u0 = d_L - V_L / Ku (a new excursion toward the other
//                     side), and back at d_L (on toward the global peak G)
//   3 to local        V = K3 (d - u0) from the zero crossing u0 to L,  K3 = V_L / (d_L - u0)
//   4 to global       the straight line from u0 (after an excursion) or from L to G
//   5 post-yield      on the backbone (from G, or from the elastic branch at first yield)
//   6 post-capping    on the backbone, to the residual drift d_res where V = Fr
//   7 residual        V = Fr up to theta_u h
//   failed            V = 0 for ever
// Peak-oriented reloading (Ibarra et al. 2005; OpenSees' branches 3 and 4): at a new excursion (the
// shear crossing zero at u0) toward a side, the target is the global peak G (the largest drift
// reached toward that side, on the current backbone; the yield point before the side yielded),
// or first the last reversal point L of that side when u0 < d_L, V_L < V_G and L lies above
// the line from u0 to G (V_L / (d_L - u0) > V_G / (d_G - u0)), then G; past G the backbone.
// (OpenSees' rule, posFlocal < posFglobal: a tie, L and G both on the residual plateau at Fr,
// aims at G, although L then lies above the line to G.)
// (Degenerate case, as OpenSees: when G is not ahead of u0, the shear goes straight onto the
// backbone at u0.)
// Unloading (a drift reversal on branches 3-7, i.e. the shear and the drift rate of opposite
// signs): L becomes the reversal point, and so does G when the reversal point lies beyond it;
// Ku is reduced (below).
//
// Cyclic deterioration (Ibarra et al. 2005; Lignos & Krawinkler 2011: the energy rule of Rahnama
// & Krawinkler 1993 for the four modes),
// with E_h the hysteretic energy dissipated so far and E_exc its value at the start of the
// current excursion:
//   - at each new excursion (shear crossing zero) toward side s:
//         beta = ((E_h - E_exc) / (E_t - E_h))^c,   E_exc <- E_h;
//     if side s has yielded before (OpenSees' posYield_Flag / negYield_Flag), its backbone
//     deteriorates: Fy and Kp times (1 - beta) (Fy not below Fr; Kp = 0 once Fy = Fr); the
//     post-capping line's zero-drift intercept Fc + Kpc d_cap times (1 - beta), the cap then
//     being where the post-yield and post-capping lines meet; the global peak drift d_G times
//     (1 + beta), V_G then on the updated backbone;
//   - at each unloading:  beta_K = ((E_h - E_exc) / (E_t - E_h))^c,  Ku <- Ku (1 - beta_K),
//     with E_h counted without the elastic energy V^2 / (2 Ku) still stored at the reversal
//     (Ku before the reduction). (The 2020 OpenSees code added that energy to E_h - E_exc
//     instead; its 2022 revision subtracts it, as the issue states.)
//   A beta below zero counts as zero (the clipping). OpenSees fails the storey at a beta
//   below -0.01, which a beta_K reaches once Ku has deteriorated below the slope K of the
//   reloading line the excursion began on (its energy up to the unloading is then
//   V^2 (1/K - 1/Ku) / 2 < 0).
// Failure (the storey carries no shear from then on): a beta above 1 or E_t - E_h <= 0 at an
// excursion or unloading; the drift reaching theta_u h (OpenSees: Ui >= Uu, so the shear at
// exactly theta_u h is zero); the backbone reaching zero shear (Fr = 0 at
// the end of the post-capping branch, or a global peak with no strength left).
//
// Energies (V dd = dU + dE_h on every branch): U = stored() = V^2 / (2 Ku), what unloading
// along Ku recovers; E_h = dissipated() = W - U with W the work of the shear, kept in closed form
// from the start of the current line (W = W_a + (V_a + V)(d - d_a) / 2). So V^2 <= 2 k0 U
// (Ku <= k0), and E_h stays constant on the unloading branch. A reduction of Ku
// at a reversal raises U by V^2 (1/Ku' - 1/Ku) / 2 with no work done: E_h steps down by as much
// at that instant. On a reloading branch steeper than Ku (K3 or K4 > Ku, possible once Ku has
// deteriorated) E_h decreases along the branch (dE_h = V dd (1 - K / Ku)). At failure the
// stored energy becomes dissipated (E_h = W, U = 0).
//
// Continuous form: every branch is a line (branch_line()); two switching functions per branch,
// each linear in the drift or its rate (so that the solver's interpolant of it is exact):
//   0: the end toward the branch's side s (+ for the elastic branch): s (d - d_end) [m];
//   1: on the elastic and unloading branches, which the storey may travel either way, the
//      other end: s (d_back - d) [m] (the interval between the ends is safe_drift()); on
//      branches 3-7 the drift rate reversing: -s dd [m/s] (unloading).
// Incremental form: advance() walks every corner between d0 and d1 of the monotone path (a
// reversal at d0 when the path turns back on a loading branch), exactly.
#include "hysteresis/storey_law.hpp"

namespace pound {

class ImkStorey final : public StoreyLaw {
 public:
  const char* name() const override { return "imk"; }
  double shear(const StoreyParameters& p, const StoreyState& s, double d,
               const double* x) const override;
  int switches() const override { return 2; }
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
  bool failed(const StoreyParameters& p, const StoreyState& s) const override;
  bool can_fail() const override { return true; }

  /// The unloading stiffness Ku of state s [N/m] (k0 before any unloading).
  static double unloading_stiffness(const StoreyParameters& p, const StoreyState& s);
};

}  // namespace pound

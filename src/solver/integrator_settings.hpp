#pragma once
// How the equations of motion are integrated in time (see docs/integration.md).
namespace pound {

enum class StepControl {
  adaptive,  ///< error-controlled Dormand-Prince 5(4) steps
  fixed,     ///< constant step dt (reference path; convergence studies)
};

struct IntegratorSettings {
  StepControl control = StepControl::adaptive;
  double rtol = 1e-8;  ///< relative local-error tolerance [-]
  double atol =
      1e-10;           ///< absolute local-error tolerance on displacements [m] and velocities [m/s]
  double dt = 0.0;     ///< fixed step [s] (StepControl::fixed)
  double h_max = 0.0;  ///< largest step [s]; 0 = automatic: min(record step, T_min / 20)
  long max_steps = 200000000;  ///< guard against runaway step counts
  /// Adaptive control: between contacts and yield events, a row whose storeys are linear or
  /// piecewise linear (and no energy balance is tracked) takes exact steps of the linear
  /// system on the grid of h_max (linear_step.hpp; docs/integration.md, "Exact steps");
  /// false: Dormand-Prince throughout.
  bool exact_free = true;
  /// A stiff first-order root (issue 38; docs/integration.md, "Stiff first-order roots"): a
  /// building's massless base DOFs are condensed to their quasi-static limit when every one's
  /// relaxation rate K_ii / C_ii [1/s] times the row's shortest oscillating period T_min [s]
  /// reaches this (the base's relative error at most about 2 pi / this, 6e-4, the floors' that
  /// times the base's share of their response); infinity: never [-].
  double stiff_root = 1e4;
  /// Adaptive control on a row whose massive flexible bases carry dashpots too stiff for an
  /// explicit step (issue 38; C_dd / M_d times h_max above Dormand-Prince's 3.3): the additive
  /// Runge-Kutta pair ARK5(4)8L[2]SA, implicit in those dashpots on the bases' own velocities
  /// (solver/ark_imex.hpp). Off by default: measured, it loses order where the dashpot's force
  /// balances the explicit forces (the soft-soil study took more steps, not fewer; docs/speed.md
  /// "IMEX steps on soil"; imex_from chooses it where the dashpots are far stiffer); false:
  /// Dormand-Prince throughout, but for imex_from.
  bool imex_bases = false;
  /// Adaptive control: the same IMEX pair chosen once per run, without imex_bases, where a
  /// massive base's own dashpot rate C_dd / M_d [1/s] times h_max [s] reaches this [-] (issue
  /// 38: a heavy raft on stiff soil, where Dormand-Prince is held at 3 / lambda; measured on the
  /// chapter 8 pair on Gazetas footings, docs/speed.md "IMEX steps on soil": the pair takes
  /// 0.55-0.91 of Dormand-Prince's CPU time from lambda h_max = 79 to 118, 1.08 (elastic
  /// storeys) and 0.84 (IMK) at 59, 1.8-4.4 at 6 and 20); infinity: never.
  double imex_from = 80.0;
  /// Adaptive control on a row with flexible bases (issue 38; docs/integration.md, "Step
  /// choice"): each base DOF's entries of the error test measured by what they do to its
  /// building's floors (the sway's and the rotation's lever to the roof, in the floors' scale; a
  /// velocity error by the displacement it makes within the DOF's own relaxation time) and the
  /// Dormand-Prince steps kept inside the stability bound of the bases' dashpots. false: every
  /// base entry against its own atol + rtol |y|, as the floors' (the norm before). Rows on fixed
  /// bases take the same norm either way.
  bool base_error_by_floors = true;
};

}  // namespace pound

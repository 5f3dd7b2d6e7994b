#pragma once
// The restoring force of one storey of a shear building (physics.md section 1 with columns that
// may yield; issue 16): the storey shear V as a function of the storey drift
// d = u_j - u_{j-1} [m] and of its history. Every law here is written as
//     V = k0 (b d + (1 - b) z),
// a linear spring b k0 in parallel with a hysteretic element of stiffness (1 - b) k0 whose
// "hysteretic drift" z [m] stays within the yield drift uy = Fy / k0 (bilinear: exactly;
// Bouc-Wen: asymptotically), so a law is its rule for z.
//
// A law serves two integrators:
//   - the continuous form, for the adaptive Dormand-Prince row solver (solver/row_solver.cpp):
//     V from the drift, the law's discrete state (the branch, which changes only at switching
//     events located like contacts) and its continuous states x (integrated with the floors);
//   - the incremental form, for the Newmark integrator of the damped Sears row solver:
//     advance() follows a monotone drift path from the committed state to a trial drift
//     (a return map), the continuous states then living in StoreyState::x.
// Laws hold no state: one object per law (hysteresis/registry.cpp) serves every storey.
//
// Energies (the energy balance of docs/hysteresis.md): stored() is the recoverable strain
// energy U and dissipated() the hysteretic energy E_h, with V dd = dU/dt + dE_h/dt. Two
// properties every law must keep, because the event stepping of the damped Sears model bounds
// the buildings' motion by their energy (sears/translation_bound.hpp):
//     V^2 <= 2 k0 U   and   dE_h/dt >= 0.
#include <limits>

namespace pound {

/// Parameters of one storey [SI]. A law reads the members it documents; the defaults of the
/// IMK members are those of docs/hysteresis.md (reinforced-concrete frames).
struct StoreyParameters {
  double k0 = 0.0;                                      ///< initial stiffness [N/m]
  double Fy = std::numeric_limits<double>::infinity();  ///< yield shear [N]
  double b = 0.02;                                      ///< hardening k_post / k0 [-]
  double bw_n = 2.0;                                    ///< Bouc-Wen sharpness n [-]
  double h = 3.0;  ///< storey height [m]; drift ratios are drifts / h
  // Deteriorating law (imk.hpp), drift ratios of h:
  double cap_strength_ratio = 1.2;     ///< Fc / Fy >= 1 [-]
  double plastic_drift_ratio = 0.06;   ///< theta_p: yield to cap [-]
  double post_cap_drift_ratio = 0.10;  ///< theta_pc: cap to zero strength [-]
  double ultimate_drift_ratio =        ///< theta_u: no strength beyond [-]
      std::numeric_limits<double>::infinity();
  double residual_strength_ratio = 0.0;  ///< Fr / Fy in [0, 1) [-]
  double energy_capacity = 100.0;        ///< lambda: E_t = lambda Fy uy [-]
  double energy_exponent = 1.0;          ///< c of beta = (E_i / (E_t - sum E_j))^c [-]
  double uy() const { return Fy / k0; }  ///< yield drift [m]
};

/// History variables of one storey; a law uses the members it documents.
struct StoreyState {
  int branch = 0;           ///< piecewise laws: the current branch (changes at switches only)
  double d_anchor = 0.0;    ///< drift where the branch began [m]
  double z_anchor = 0.0;    ///< hysteretic drift z at the branch start [m]
  double dissipated = 0.0;  ///< hysteretic energy dissipated before the branch began [J]
  /// Continuous states (incremental form; the continuous form keeps them in the ODE state).
  double x[2] = {0.0, 0.0};
  /// Room for a law's history variables (the IMK law's current line, unloading stiffness,
  /// energies, and per direction its backbone and peaks: imk.cpp names them). All zero is the
  /// state at rest that no law has touched yet.
  static constexpr int kHistory = 25;
  double history[kHistory] = {};
};

/// A switching function and its time derivative: a switch happens where `value` rises through
/// zero (its units are the law's: m for a drift, m/s for a drift rate).
struct SwitchValue {
  double value = -1.0;
  double rate = 0.0;
};

class StoreyLaw {
 public:
  static constexpr int kMaxContinuous = 2;
  virtual ~StoreyLaw() = default;
  virtual const char* name() const = 0;
  /// True for the linear law V = k0 d (the solvers keep their linear fast paths).
  virtual bool linear() const { return false; }

  // --- Continuous form -------------------------------------------------------------------
  /// Number of continuous states (at most kMaxContinuous) [-].
  virtual int continuous_states() const { return 0; }
  /// Storey shear [N] at drift d [m].
  virtual double shear(const StoreyParameters& p, const StoreyState& s, double d,
                       const double* x) const = 0;
  /// Time derivatives of the continuous states at drift d [m] and drift rate dd [m/s].
  virtual void rates(const StoreyParameters&, const StoreyState&, double, double, const double*,
                     double*) const {}
  /// Number of switching functions of the law (every branch has as many; unused ones return
  /// a constant negative value) [-].
  virtual int switches() const { return 0; }
  /// Switching function i at drift d, rate dd and drift acceleration ddd [m/s^2].
  virtual SwitchValue switch_value(int, const StoreyParameters&, const StoreyState&, double, double,
                                   double) const {
    return {};
  }
  /// Applies switch i at drift d (continuous states x): the new branch and anchors.
  virtual void on_switch(int, const StoreyParameters&, StoreyState&, double, const double*) const {}
  /// Piecewise-linear laws: the shear of the current branch as V = slope d + offset [N/m], [N]
  /// (it changes only at switches). Returns false for a law without such a form.
  virtual bool branch_line(const StoreyParameters&, const StoreyState&, double&, double&) const {
    return false;
  }
  /// A drift interval (lo, hi) [m] inside which no switching function of the current branch can
  /// rise through zero, whatever the drift rate; false when there is none (e.g. a switch on
  /// the drift rate). Lets the solver skip the switches of storeys far from a kink.
  virtual bool safe_drift(const StoreyParameters&, const StoreyState&, double&, double&) const {
    return false;
  }
  /// Hysteretic energy dissipated up to drift d [J].
  virtual double dissipated(const StoreyParameters&, const StoreyState&, double,
                            const double*) const {
    return 0.0;
  }
  /// Recoverable strain energy at drift d [J].
  virtual double stored(const StoreyParameters& p, const StoreyState& s, double d,
                        const double* x) const = 0;

  // --- Incremental form ------------------------------------------------------------------
  /// The state at drift d1 [m] after a monotone drift path from the committed state at d0 [m];
  /// returns the shear at d1 [N]. The trial's dissipated() and stored() at d1 hold the step's
  /// energies.
  virtual double advance(const StoreyParameters& p, const StoreyState& committed, double d0,
                         double d1, StoreyState& trial) const = 0;

  // --- Both forms --------------------------------------------------------------------------
  /// True once the storey has failed for good (a deteriorating law that lost all strength: it
  /// carries no shear from then on). The solvers use it to detect collapse.
  virtual bool failed(const StoreyParameters&, const StoreyState&) const { return false; }
  /// Whether failed() can ever be true (the solvers skip the test for laws that cannot fail).
  virtual bool can_fail() const { return false; }
};

}  // namespace pound

#pragma once
// The internal (n >= 1) axial modes of one free-free bar, stepped by the exact
// piecewise-linear-excitation recurrence (Chopra, Dynamics of Structures, sec. 5.2).
//
// Section x of the bar moves as u(x,t) = q0(t) + sum_{n=1..N} q_n(t) cos(n pi x / l)
// (Th. 7.5, 8.3); q0 (the rigid-body mode) belongs to the caller: a free body in
// `pound impact`, the floor DOF of the building in `pound simulate`. Each internal mode obeys
//     q_n'' + 2 xi_s w_n q_n' + w_n^2 q_n = (2 / m) Q_n(t),   Q_n = P_left + (-1)^n P_right
// (Th. 7.14, 8.7), where P_left and P_right are the axial forces applied at x = 0 and x = l,
// positive in +x (a compressive contact force F pushes the left end with +F and the right end
// with -F) and m = rho A l is the bar's mass.
//
// Over a step [t_i, t_i + dt] the end forces are taken linear in time between their values
// P_i and P_{i+1}; the recurrence is then exact (and exact for free vibration at any dt):
//     q_{i+1} = A q_i + B q'_i + C f_i + D f_{i+1}
//     q'_{i+1} = A' q_i + B' q'_i + C' f_i + D' f_{i+1}           f = (2/m) Q_n
// The coefficients are those of Chopra's Table 5.2.1 (for unit mass); they are computed here
// from the exponential of the augmented 4x4 system in step-scaled variables, which is exact
// and free of the cancellation the closed forms suffer when w dt << 1.
#include <vector>

#include "sears/slab.hpp"

namespace pound::sears {

/// Chopra's recurrence coefficients for a unit-mass oscillator (Table 5.2.1 names).
struct RecurrenceCoefficients {
  double A = 0, B = 0, C = 0, D = 0;      ///< displacement row [-, s, s^2, s^2]
  double Av = 0, Bv = 0, Cv = 0, Dv = 0;  ///< velocity row [1/s, -, s, s]
};

/// Coefficients for circular frequency w [rad/s], damping ratio xi in [0, 1) and step dt [s].
RecurrenceCoefficients recurrence_coefficients(double omega, double xi, double dt);

/// Axial end forces on a bar, positive in +x [N].
struct EndLoads {
  double left_N = 0.0;   ///< applied at x = 0
  double right_N = 0.0;  ///< applied at x = l
};

/// Internal-mode contribution at three sections: the two faces and the centre.
struct SectionValues {
  double left = 0.0;    ///< x = 0
  double right = 0.0;   ///< x = l
  double centre = 0.0;  ///< x = l/2
};

class ModalBank {
 public:
  /// N internal modes of `slab` with modal damping xi_s in [0, 1), recurrence for step dt [s].
  ModalBank(const Slab& slab, int modes, double xi_s, double dt);

  int modes() const { return modes_; }
  double dt() const { return dt_; }
  const Slab& slab() const { return slab_; }

  /// Internal face displacements now: sum q_n and sum (-1)^n q_n [m].
  SectionValues displacement() const;
  /// Internal face velocities now [m/s].
  SectionValues velocity() const;
  /// Internal accelerations sum q_n'' cos(n pi x / l) now, given the end loads acting now
  /// [m/s^2] (the rigid-body acceleration is the caller's).
  SectionValues acceleration(const EndLoads& now) const;

  /// Adds the loaded recurrence for a further step size h [s] (event stepping's longer steps
  /// through smooth contact forces, docs/speed.md) and returns its index; index 0 is dt().
  int add_step(double h);
  /// Step size of recurrence `level` [s].
  double step_size(int level) const { return rec_[level].h; }

  /// Face displacements at the end of the next step (of recurrence `level`) if the end loads
  /// went linearly from `begin` to zero [m]; the end-of-step loads add flexibility(level) times
  /// themselves.
  SectionValues predict(const EndLoads& begin, int level = 0) const;
  /// Step flexibility [m/N]: end-face displacement per unit end-of-step load at the same face
  /// (`same`) and at the opposite face (`cross`).
  struct Flexibility {
    double same = 0.0;
    double cross = 0.0;
  };
  Flexibility flexibility(int level = 0) const { return rec_[level].flex; }

  /// Advances one step with end loads linear from `begin` to `end`. No allocation.
  void step(const EndLoads& begin, const EndLoads& end);

  /// What the row solver needs after a step (one pass over the modes, docs/speed.md).
  struct StepResult {
    SectionValues disp;       ///< displacement() at the end of the step
    SectionValues accel;      ///< acceleration(end) at the end of the step
    SectionValues next_pred;  ///< predict(end) for the next step (faces only)
  };
  /// step(begin, end) fused with displacement(), acceleration(end) and predict(end), by
  /// recurrence `level`; next_pred is by recurrence `next_level` (-1: `level`). Sums are taken
  /// in four interleaved lanes (modes n mod 4), so they may differ from the separate calls in
  /// the last bits. No allocation.
  void step(const EndLoads& begin, const EndLoads& end, StepResult& out, int level = 0,
            int next_level = -1);

  /// Energy in the internal vibration, sum (m/4)(q_n'^2 + w_n^2 q_n^2) [J].
  double energy() const;
  /// Power dissipated by the modal damping now, sum xi_s w_n m q_n'^2 [W].
  double damping_power() const;
  /// Bound on |internal displacement| of either face for all later free (unloaded) motion,
  /// sum sqrt(q_n^2 + (q_n'/w_n)^2) [m]: each damped mode's energy cannot grow when free.
  double free_face_bound() const;
  /// Sets every mode to rest.
  void reset();

  /// Prepares free_step(): the free-vibration recurrence for a second (coarse) step h [s]
  /// (event-driven stepping, docs/speed.md). Exact for unloaded modes at any h.
  void set_free_step(double h);
  /// The free step set by set_free_step() [s]; 0 when none.
  double free_step() const { return h_free_; }
  /// Advances one free step (no end loads) of length free_step(). No allocation.
  void step_free();
  /// step_free() fused with displacement() and acceleration({}) after it (out.next_pred is
  /// left unset: the next fine step calls predict()). No allocation.
  void step_free(StepResult& out);
  /// Bound on how far either face can move, by internal vibration, within the next `h` seconds
  /// of free (unloaded) motion [m]:
  ///     |w(t + tau) - w(t)| <= sum_n R_n min(2, w_n h),  R_n = sqrt(q_n^2 + (q_n'/w_n)^2),
  /// since a free damped mode keeps |q_n| <= R_n and |q_n'| <= w_n R_n (its energy
  /// (q_n'^2 + w_n^2 q_n^2)/2 = w_n^2 R_n^2 / 2 cannot grow).
  double face_motion_bound(double h) const;
  /// Bound on |internal acceleration| of any section for all later free motion [m/s^2]:
  /// sum_n w_n^2 R_n (1 + 2 xi_s), since |q_n''| = |2 xi_s w_n q_n' + w_n^2 q_n|.
  double free_accel_bound() const;
  /// k free steps of free_step() at once (dormant slabs, docs/speed.md): the per-mode 2 x 2
  /// free recurrence raised to the power k by its binary powers (formed by squaring in
  /// set_free_step), so O(N log k). Equals k calls of step_free() up to round-off; fills `out`
  /// as step_free(out) does. No allocation.
  void advance_free(long k, StepResult& out);

 private:
  Slab slab_;
  int modes_ = 0;
  double dt_ = 0.0;
  double gain_ = 0.0;  // 2 / m [1/kg]
  double xi_ = 0.0;
  // Structure of arrays, padded with inert modes (zero coefficients and state, w = 1) to a
  // multiple of 4 for the fused step; every other loop runs over the modes_ real modes.
  std::vector<double> omega_, q_, v_;
  std::vector<double> c1_, k1_;  // 2 xi w_n, w_n^2
  // The loaded recurrence for one step size h [s] (padded like q_).
  struct Recurrence {
    double h = 0.0;
    std::vector<double> A, B, C, D, Av, Bv, Cv, Dv;
    Flexibility flex;
  };
  std::vector<Recurrence> rec_;  // rec_[0]: dt_
  double h_free_ = 0.0;
  std::vector<double> Af_, Bf_, Avf_, Bvf_;  // free recurrence for h_free_
  // Its binary powers: entry [j][4 i + (0..3)] = (A, B, Av, Bv) of mode i for 2^j free steps.
  std::vector<std::vector<double>> free_pow_;
};

}  // namespace pound::sears

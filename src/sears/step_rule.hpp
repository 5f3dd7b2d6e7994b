#pragma once
// Step size of the damped Sears model (docs/sears.md, "Step rule").
//
// Two time scales must be resolved: the shortest modal period retained, T_min = 2 l / (N c)
// over the colliding bars, and the contact time scale t_c, the duration of the elastic
// lumped-mass impact with the same contact law (SlabContactLaw::lumped_duration), which is never
// longer than the actual contact of the distributed bars.
//
//   automatic step:      dt = min(T_min / 10, t_c / 200)
//   largest user step:   dt <= min(T_min / 2, t_c / 20)
//
// The modal recurrence is exact for any step if the force is linear over it, so the upper
// limit is not a stability bound but a resolution bound: a force sampled every dt cannot drive
// a mode of period below 2 dt (Nyquist) and a contact shorter than 20 steps has its impulse
// and duration wrong by more than a few per cent. A larger user step is an InputError that
// names the largest allowed value. The automatic step was T_min / 20 until a convergence study
// against the thesis' 10 us (docs/speed.md, "Fine step") showed T_min / 10 changes floor
// displacements, drifts, floor accelerations and contact forces by under 1e-4 and the slab-centre
// accelerations by under 0.1 %; the contact-face acceleration, a peak sampled at step ends from a
// sum dominated by the highest modes, reads up to 1.2 % low (0.3 % at T_min / 20).
namespace pound::sears {

inline constexpr double kStepsPerShortestPeriod = 10.0;    ///< automatic step
inline constexpr double kStepsPerContact = 200.0;          ///< automatic step
inline constexpr double kMinStepsPerShortestPeriod = 2.0;  ///< largest allowed step (Nyquist)
inline constexpr double kMinStepsPerContact = 20.0;        ///< largest allowed step

struct StepLimits {
  double auto_dt_s = 0.0;  ///< the step used when none is given [s]
  double max_dt_s = 0.0;   ///< the largest step a user may give [s]
};

/// Limits from the shortest modal period T_min [s] and the contact time scale t_c [s].
StepLimits step_limits(double shortest_modal_period_s, double contact_time_s);

/// Returns dt_user when given (> 0) and allowed, else the automatic step; throws InputError
/// saying the largest allowed value when dt_user is too large.
double choose_step(const StepLimits& limits, double dt_user_s);

}  // namespace pound::sears

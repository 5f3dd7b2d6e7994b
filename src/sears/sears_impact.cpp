#include "sears/sears_impact.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "sears/modal_bank.hpp"

namespace pound::sears {
namespace {

// Mode 0 of a free bar: a rigid body under the axial end force P (sum of both ends), which is
// linear over the step like the modal forces, so this update is exact too.
struct RigidBody {
  double mass = 0.0;  // [kg]
  double x = 0.0;     // centre-of-mass displacement [m]
  double v = 0.0;     // [m/s]
  double predict(double P0, double dt) const { return x + v * dt + dt * dt / mass * P0 / 3.0; }
  double flexibility(double dt) const { return dt * dt / (6.0 * mass); }
  void step(double P0, double P1, double dt) {
    x += v * dt + dt * dt / mass * (P0 / 3.0 + P1 / 6.0);
    v += 0.5 * dt / mass * (P0 + P1);
  }
};

double shortest_modal_period(const SearsImpactSpec& s) {
  const double w = std::max(s.bar1.omega(s.modes), s.bar2.omega(s.modes));
  return 2.0 * M_PI / w;
}

double reduced_mass(const SearsImpactSpec& s) {
  return s.bar1.mass_kg * s.bar2.mass_kg / (s.bar1.mass_kg + s.bar2.mass_kg);
}

void validate_spec(const SearsImpactSpec& s) {
  validate(s.bar1, "bar 1");
  validate(s.bar2, "bar 2");
  validate(s.contact);
  if (!(s.v0_m_s > 0.0 && std::isfinite(s.v0_m_s)))
    throw InputError("damped Sears impact: approach velocity v0 must be > 0 [m/s]");
  if (s.modes < 1) throw InputError("damped Sears impact: number of modes must be >= 1");
  if (!(s.xi_s >= 0.0 && s.xi_s < 1.0))
    throw InputError("damped Sears impact: slab damping xi_s must be in [0, 1)");
}

}  // namespace

StepLimits sears_impact_step_limits(const SearsImpactSpec& spec) {
  validate_spec(spec);
  return step_limits(shortest_modal_period(spec),
                     spec.contact.lumped_duration(reduced_mass(spec), spec.v0_m_s));
}

namespace {
// The peak accelerations of the contact faces and centres (rigid + internal, Th. 7.5) under the
// contact force F [N] on bar 1's right end (-F) and bar 2's left end (+F).
void record_accelerations(SearsImpactOutcome& out, double F, double m1, double m2,
                          const ModalBank& bank1, const ModalBank& bank2) {
  const SectionValues a1 = bank1.acceleration(EndLoads{0.0, -F});
  const SectionValues a2 = bank2.acceleration(EndLoads{F, 0.0});
  out.peak_face_accel1 = std::max(out.peak_face_accel1, std::fabs(-F / m1 + a1.right));
  out.peak_face_accel2 = std::max(out.peak_face_accel2, std::fabs(F / m2 + a2.left));
  out.peak_centre_accel1 = std::max(out.peak_centre_accel1, std::fabs(-F / m1 + a1.centre));
  out.peak_centre_accel2 = std::max(out.peak_centre_accel2, std::fabs(F / m2 + a2.centre));
}
}  // namespace

SearsImpactOutcome run_sears_impact(const SearsImpactSpec& spec) {
  const StepLimits limits = sears_impact_step_limits(spec);
  const double dt = choose_step(limits, spec.dt_s);
  const SlabContactLaw& law = spec.contact;
  const bool implicit = spec.coupling == Coupling::implicit_linear_force;

  ModalBank bank1(spec.bar1, spec.modes, spec.xi_s, dt);
  ModalBank bank2(spec.bar2, spec.modes, spec.xi_s, dt);
  RigidBody body1{spec.bar1.mass_kg, 0.0, spec.v0_m_s};
  RigidBody body2{spec.bar2.mass_kg, 0.0, 0.0};
  const double compliance =
      body1.flexibility(dt) + body2.flexibility(dt) + bank1.flexibility().same +
      bank2.flexibility().same;  // S: overlap change per unit end-of-step force [m/N]

  const double t_c = law.lumped_duration(reduced_mass(spec), spec.v0_m_s);
  const double t_max =
      spec.max_time_s > 0.0
          ? spec.max_time_s
          : 1000.0 * (t_c + std::max(spec.bar1.first_mode_period(), spec.bar2.first_mode_period()));

  SearsImpactOutcome out;
  out.dt_s = dt;
  out.initial_energy_J = 0.5 * body1.mass * spec.v0_m_s * spec.v0_m_s;
  ImpactResult& r = out.impact;
  r.contact_phases = 1;  // the faces touch at t = 0, approaching at v0
  bool in_contact = true;
  double F = 0.0, delta = 0.0, t = 0.0, last_separation = 0.0;
  double power = 0.0;  // damping power at the start of the step [W]
  if (spec.record_history) out.history.push_back(SearsImpactSample{0.0, 0.0, 0.0});

  for (long i = 0;; ++i) {
    if (t > t_max)
      throw NumericalError(
          "damped Sears impact: no final separation by t = " + std::to_string(t_max) + " s (" +
          std::to_string(r.contact_phases) + " contact phases)");
    // Loads at the start of the step: -F on bar 1's right end, +F on bar 2's left end.
    const EndLoads begin1{0.0, -F}, begin2{F, 0.0};
    double F_next;
    if (implicit) {
      // End-of-step overlap with zero end-of-step force, then solve F = law(pred - S F).
      const double pred = body1.predict(-F, dt) + bank1.predict(begin1).right -
                          body2.predict(F, dt) - bank2.predict(begin2).left - out.crush_m;
      F_next = law.solve_implicit(pred, compliance);
      bank1.step(begin1, EndLoads{0.0, -F_next});
      bank2.step(begin2, EndLoads{F_next, 0.0});
      body1.step(-F, -F_next, dt);
      body2.step(F, F_next, dt);
      r.impulse_Ns += 0.5 * (F + F_next) * dt;
    } else {
      bank1.step(begin1, begin1);
      bank2.step(begin2, begin2);
      body1.step(-F, -F, dt);
      body2.step(F, F, dt);
      r.impulse_Ns += F * dt;
      F_next = 0.0;  // computed from the new overlap below
    }
    t += dt;
    // The overlap from the gap widened by the faces' indentation (crushing at the cap).
    double delta_next =
        body1.x + bank1.displacement().right - body2.x - bank2.displacement().left - out.crush_m;
    if (!implicit) F_next = law.force(delta_next);
    const double dc = law.crush_increment(delta_next, F_next);  // 0 without a cap
    if (dc > 0.0) {
      out.crush_m += dc;
      delta_next -= dc;
      out.crushing_J += law.force_cap_N * dc;
    }

    // Contact phases; separation time by linear interpolation of the overlap.
    if (in_contact && !(delta_next > 0.0)) {
      in_contact = false;
      last_separation = delta > 0.0 ? t - dt + dt * delta / (delta - delta_next) : t - dt;
      if (r.contact_phases == 1) {
        out.first_phase_impulse_Ns = r.impulse_Ns;
        out.first_phase_duration_s = last_separation;
      }
    } else if (!in_contact && delta_next > 0.0) {
      in_contact = true;
      ++r.contact_phases;
    }
    F = F_next;
    delta = delta_next;
    r.peak_force_N = std::max(r.peak_force_N, F);
    r.max_penetration_m = std::max(r.max_penetration_m, delta + out.crush_m);
    if (spec.record_history) out.history.push_back(SearsImpactSample{t, F, delta});

    record_accelerations(out, F, body1.mass, body2.mass, bank1, bank2);

    // Energy balance: kinetic + modal + contact + dissipated (trapezoidal rule) = initial.
    const double power_next = bank1.damping_power() + bank2.damping_power();
    out.dissipated_J += 0.5 * (power + power_next) * dt;
    power = power_next;
    const double energy = 0.5 * body1.mass * body1.v * body1.v +
                          0.5 * body2.mass * body2.v * body2.v + bank1.energy() + bank2.energy() +
                          law.potential(delta);
    out.max_energy_error_J =
        std::max(out.max_energy_error_J,
                 std::fabs(energy + out.dissipated_J + out.crushing_J - out.initial_energy_J));

    // Final separation: the rigid bodies do not approach and even the largest internal face
    // displacements that free vibration can reach leave a gap.
    if (!in_contact && body1.v <= body2.v &&
        body1.x - body2.x - out.crush_m + bank1.free_face_bound() + bank2.free_face_bound() < 0.0) {
      out.steps = i + 1;
      break;
    }
  }
  out.end_time_s = t;
  r.contact_duration_s = last_separation;
  r.v1_after = body1.v;
  r.v2_after = body2.v;
  r.e_eff = (body2.v - body1.v) / spec.v0_m_s;
  r.internal_energy1_J = bank1.energy();
  r.internal_energy2_J = bank2.energy();
  return out;
}

ImpactResult simulate_sears_impact(const SearsImpactSpec& spec) {
  return run_sears_impact(spec).impact;
}

}  // namespace pound::sears

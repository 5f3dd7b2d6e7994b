#include "sears/modal_bank.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/error.hpp"

namespace pound::sears {
namespace {
// (-1)^n and cos(n pi / 2), the mode shapes at x = l and x = l/2.
inline double sign_at_right(int n) {
  return (n % 2) ? -1.0 : 1.0;
}
inline double shape_at_centre(int n) {
  return (n % 2) ? 0.0 : ((n / 2) % 2 ? -1.0 : 1.0);
}
}  // namespace

RecurrenceCoefficients recurrence_coefficients(double omega, double xi, double dt) {
  // Step-scaled variables s = t/dt, w = dt q', phi = dt^2 f make every entry O(1):
  //   d/ds [q, w, phi, dphi] = H [q, w, phi, dphi],  phi linear in s over the step.
  const double a = omega * dt;
  Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
  H(0, 1) = 1.0;
  H(1, 0) = -a * a;
  H(1, 1) = -2.0 * xi * a;
  H(1, 2) = 1.0;
  H(2, 3) = 1.0;
  const Eigen::Matrix4d E = H.exp();
  // q_{i+1} = E00 q + E01 w + E02 phi_i + E03 (phi_{i+1} - phi_i), same for w with row 1.
  RecurrenceCoefficients c;
  c.A = E(0, 0);
  c.B = E(0, 1) * dt;
  c.C = (E(0, 2) - E(0, 3)) * dt * dt;
  c.D = E(0, 3) * dt * dt;
  c.Av = E(1, 0) / dt;
  c.Bv = E(1, 1);
  c.Cv = (E(1, 2) - E(1, 3)) * dt;
  c.Dv = E(1, 3) * dt;
  return c;
}

ModalBank::ModalBank(const Slab& slab, int modes, double xi_s, double dt)
    : slab_(slab), dt_(dt), gain_(2.0 / slab.mass_kg), xi_(xi_s) {
  if (modes < 1) throw InputError("damped Sears model: number of modes must be >= 1");
  if (!(xi_s >= 0.0 && xi_s < 1.0))
    throw InputError("damped Sears model: slab damping xi_s must be in [0, 1)");
  if (!(dt > 0.0 && std::isfinite(dt))) throw InputError("damped Sears model: dt must be > 0");
  omega_.resize(modes);
  coef_.resize(modes);
  q_.assign(modes, 0.0);
  v_.assign(modes, 0.0);
  for (int i = 0; i < modes; ++i) {
    const int n = i + 1;
    omega_[i] = slab.omega(n);
    coef_[i] = recurrence_coefficients(omega_[i], xi_s, dt);
    flex_.same += gain_ * coef_[i].D;
    flex_.cross += gain_ * sign_at_right(n) * coef_[i].D;
  }
}

SectionValues ModalBank::displacement() const {
  SectionValues s;
  for (int i = 0; i < modes(); ++i) {
    const int n = i + 1;
    s.left += q_[i];
    s.right += sign_at_right(n) * q_[i];
    s.centre += shape_at_centre(n) * q_[i];
  }
  return s;
}

SectionValues ModalBank::velocity() const {
  SectionValues s;
  for (int i = 0; i < modes(); ++i) {
    const int n = i + 1;
    s.left += v_[i];
    s.right += sign_at_right(n) * v_[i];
    s.centre += shape_at_centre(n) * v_[i];
  }
  return s;
}

SectionValues ModalBank::acceleration(const EndLoads& now) const {
  SectionValues s;
  for (int i = 0; i < modes(); ++i) {
    const int n = i + 1;
    const double f = gain_ * (now.left_N + sign_at_right(n) * now.right_N);
    const double acc = f - 2.0 * xi_ * omega_[i] * v_[i] - omega_[i] * omega_[i] * q_[i];
    s.left += acc;
    s.right += sign_at_right(n) * acc;
    s.centre += shape_at_centre(n) * acc;
  }
  return s;
}

SectionValues ModalBank::predict(const EndLoads& begin) const {
  SectionValues s;
  for (int i = 0; i < modes(); ++i) {
    const int n = i + 1;
    const auto& c = coef_[i];
    const double f = gain_ * (begin.left_N + sign_at_right(n) * begin.right_N);
    const double q = c.A * q_[i] + c.B * v_[i] + c.C * f;
    s.left += q;
    s.right += sign_at_right(n) * q;
  }
  return s;
}

void ModalBank::step(const EndLoads& begin, const EndLoads& end) {
  for (int i = 0; i < modes(); ++i) {
    const double sgn = sign_at_right(i + 1);
    const auto& c = coef_[i];
    const double f0 = gain_ * (begin.left_N + sgn * begin.right_N);
    const double f1 = gain_ * (end.left_N + sgn * end.right_N);
    const double q = q_[i], v = v_[i];
    q_[i] = c.A * q + c.B * v + c.C * f0 + c.D * f1;
    v_[i] = c.Av * q + c.Bv * v + c.Cv * f0 + c.Dv * f1;
  }
}

double ModalBank::energy() const {
  double e = 0.0;
  for (int i = 0; i < modes(); ++i) e += v_[i] * v_[i] + omega_[i] * omega_[i] * q_[i] * q_[i];
  return 0.5 * slab_.modal_mass() * e;
}

double ModalBank::damping_power() const {
  double p = 0.0;
  for (int i = 0; i < modes(); ++i) p += omega_[i] * v_[i] * v_[i];
  return xi_ * slab_.mass_kg * p;
}

double ModalBank::free_face_bound() const {
  double b = 0.0;
  for (int i = 0; i < modes(); ++i) {
    const double r = v_[i] / omega_[i];
    b += std::sqrt(q_[i] * q_[i] + r * r);
  }
  return b;
}

void ModalBank::set_free_step(double h) {
  if (!(h > 0.0 && std::isfinite(h))) throw InputError("damped Sears model: free step must be > 0");
  h_free_ = h;
  coef_free_.resize(omega_.size());
  for (std::size_t i = 0; i < omega_.size(); ++i)
    coef_free_[i] = recurrence_coefficients(omega_[i], xi_, h);
}

void ModalBank::step_free() {
  for (int i = 0; i < modes(); ++i) {
    const auto& c = coef_free_[i];
    const double q = q_[i], v = v_[i];
    q_[i] = c.A * q + c.B * v;
    v_[i] = c.Av * q + c.Bv * v;
  }
}

double ModalBank::face_motion_bound(double h) const {
  double b = 0.0;
  for (int i = 0; i < modes(); ++i) {
    const double r = v_[i] / omega_[i];
    b += std::sqrt(q_[i] * q_[i] + r * r) * std::min(2.0, omega_[i] * h);
  }
  return b;
}

void ModalBank::reset() {
  std::fill(q_.begin(), q_.end(), 0.0);
  std::fill(v_.begin(), v_.end(), 0.0);
}

}  // namespace pound::sears

#include "sears/modal_bank.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <unsupported/Eigen/MatrixFunctions>

#include "core/error.hpp"
#include "core/vec4.hpp"

namespace pound::sears {
namespace {
// (-1)^n and cos(n pi / 2), the mode shapes at x = l and x = l/2.
inline double sign_at_right(int n) {
  return (n % 2) ? -1.0 : 1.0;
}
inline double shape_at_centre(int n) {
  return (n % 2) ? 0.0 : ((n / 2) % 2 ? -1.0 : 1.0);
}
// The arrays of a ModalBank's fused step (padded to a multiple of 4 modes).
struct FusedArrays {
  double *q, *v;
  const double *A, *B, *C, *D, *Av, *Bv, *Cv, *Dv, *c1, *k1;
  const double *pA, *pB, *pC;  // the next step's recurrence, for its prediction
  int padded;
};
// One block of four modes is one simd::V4 (core/vec4.hpp).
using simd::load;
using simd::store;
using simd::V4;

// One step of every mode with loads linear from f0 to f1 (per lane), and the lane sums of the
// new q (s[0..3]), of -(2 xi w q' + w^2 q) (s[4..7]) and of the next step's prediction
// A q + B q' + C f1 (s[8..11]), by the next step's coefficients pA, pB, pC when kOtherNext (a
// step of another length follows) and by this step's otherwise. Each lane sums its modes in
// order, as a scalar loop would; no FMA is enabled, so the AVX2 clone and the default (SSE2)
// clone give the same bits.
template <bool kOtherNext>
__attribute__((always_inline)) inline void fused_step_body(const FusedArrays& a, const double* f0,
                                                           const double* f1, double* s) {
  const V4 F0 = load(f0), F1 = load(f1);
  V4 sq = {0, 0, 0, 0}, sa = {0, 0, 0, 0}, sp = {0, 0, 0, 0};
  for (int i = 0; i < a.padded; i += 4) {
    const V4 q = load(a.q + i), v = load(a.v + i);
    const V4 A = load(a.A + i), B = load(a.B + i), C = load(a.C + i);
    const V4 qn = A * q + B * v + C * F0 + load(a.D + i) * F1;
    const V4 vn =
        load(a.Av + i) * q + load(a.Bv + i) * v + load(a.Cv + i) * F0 + load(a.Dv + i) * F1;
    store(a.q + i, qn);
    store(a.v + i, vn);
    sq += qn;
    sa -= load(a.c1 + i) * vn + load(a.k1 + i) * qn;
    if constexpr (kOtherNext)
      sp += load(a.pA + i) * qn + load(a.pB + i) * vn + load(a.pC + i) * F1;
    else
      sp += A * qn + B * vn + C * F1;
  }
  store(s, sq);
  store(s + 4, sa);
  store(s + 8, sp);
}
__attribute__((target_clones("avx2", "default"))) void fused_step_kernel(const FusedArrays& a,
                                                                         const double* f0,
                                                                         const double* f1,
                                                                         double* s) {
  fused_step_body<false>(a, f0, f1, s);
}
__attribute__((target_clones("avx2", "default"))) void fused_step_kernel_other_next(
    const FusedArrays& a, const double* f0, const double* f1, double* s) {
  fused_step_body<true>(a, f0, f1, s);
}

// One free step (no loads) of every mode by the coefficients Af..Bvf, and the lane sums of the new
// q (s[0..3]) and of -(2 xi w q' + w^2 q) (s[4..7]); same rules as fused_step_kernel.
struct FreeArrays {
  double *q, *v;
  const double *A, *B, *Av, *Bv, *c1, *k1;
  int padded;
};
__attribute__((target_clones("avx2", "default"))) void free_step_kernel(const FreeArrays& a,
                                                                        double* s) {
  V4 sq = {0, 0, 0, 0}, sa = {0, 0, 0, 0};
  for (int i = 0; i < a.padded; i += 4) {
    const V4 q = load(a.q + i), v = load(a.v + i);
    const V4 qn = load(a.A + i) * q + load(a.B + i) * v;
    const V4 vn = load(a.Av + i) * q + load(a.Bv + i) * v;
    store(a.q + i, qn);
    store(a.v + i, vn);
    sq += qn;
    sa -= load(a.c1 + i) * vn + load(a.k1 + i) * qn;
  }
  store(s, sq);
  store(s + 4, sa);
}

// sum_n R_n min(2, w_n h), R_n = sqrt(q_n^2 + (q_n'/w_n)^2), over padded modes (the padding has
// q = q' = 0); summed in four lanes (modes n mod 4), the same bits in both clones.
__attribute__((target_clones("avx2", "default"))) double face_motion_kernel(const double* q,
                                                                            const double* v,
                                                                            const double* omega,
                                                                            int padded, double h) {
  const V4 H = {h, h, h, h}, two = {2.0, 2.0, 2.0, 2.0};
  V4 b = {0, 0, 0, 0};
  for (int i = 0; i < padded; i += 4) {
    const V4 w = load(omega + i), x = load(q + i), r = load(v + i) / w, wh = w * H;
    b += simd::vsqrt(x * x + r * r) * (wh < two ? wh : two);
  }
  return (b[0] + b[1]) + (b[2] + b[3]);
}

// Face and centre sums from the lane sums s[k], n % 4 = k + 1 (mod 4).
inline void lane_faces(const double* s, SectionValues& o) {
  o.left = (s[0] + s[1]) + (s[2] + s[3]);
  o.right = (s[1] + s[3]) - (s[0] + s[2]);
  o.centre = s[3] - s[1];
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
    : slab_(slab), modes_(modes), dt_(dt), gain_(2.0 / slab.mass_kg), xi_(xi_s) {
  if (modes < 1) throw InputError("damped Sears model: number of modes must be >= 1");
  if (!(xi_s >= 0.0 && xi_s < 1.0))
    throw InputError("damped Sears model: slab damping xi_s must be in [0, 1)");
  if (!(dt > 0.0 && std::isfinite(dt))) throw InputError("damped Sears model: dt must be > 0");
  const int padded = (modes + 3) / 4 * 4;
  for (auto* a : {&q_, &v_, &c1_, &k1_}) a->assign(padded, 0.0);
  omega_.assign(padded, 1.0);
  for (int i = 0; i < modes; ++i) {
    omega_[i] = slab.omega(i + 1);
    c1_[i] = 2.0 * xi_s * omega_[i];
    k1_[i] = omega_[i] * omega_[i];
  }
  add_step(dt);
}

int ModalBank::add_step(double h) {
  if (!(h > 0.0 && std::isfinite(h))) throw InputError("damped Sears model: dt must be > 0");
  Recurrence r;
  r.h = h;
  for (auto* a : {&r.A, &r.B, &r.C, &r.D, &r.Av, &r.Bv, &r.Cv, &r.Dv}) a->assign(q_.size(), 0.0);
  for (int i = 0; i < modes_; ++i) {
    const RecurrenceCoefficients c = recurrence_coefficients(omega_[i], xi_, h);
    r.A[i] = c.A, r.B[i] = c.B, r.C[i] = c.C, r.D[i] = c.D;
    r.Av[i] = c.Av, r.Bv[i] = c.Bv, r.Cv[i] = c.Cv, r.Dv[i] = c.Dv;
    r.flex.same += gain_ * c.D;
    r.flex.cross += gain_ * sign_at_right(i + 1) * c.D;
  }
  rec_.push_back(std::move(r));
  return static_cast<int>(rec_.size()) - 1;
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

SectionValues ModalBank::predict(const EndLoads& begin, int level) const {
  const Recurrence& r = rec_[level];
  SectionValues s;
  for (int i = 0; i < modes(); ++i) {
    const int n = i + 1;
    const double f = gain_ * (begin.left_N + sign_at_right(n) * begin.right_N);
    const double q = r.A[i] * q_[i] + r.B[i] * v_[i] + r.C[i] * f;
    s.left += q;
    s.right += sign_at_right(n) * q;
  }
  return s;
}

void ModalBank::step(const EndLoads& begin, const EndLoads& end) {
  const Recurrence& r = rec_[0];
  for (int i = 0; i < modes(); ++i) {
    const double sgn = sign_at_right(i + 1);
    const double f0 = gain_ * (begin.left_N + sgn * begin.right_N);
    const double f1 = gain_ * (end.left_N + sgn * end.right_N);
    const double q = q_[i], v = v_[i];
    q_[i] = r.A[i] * q + r.B[i] * v + r.C[i] * f0 + r.D[i] * f1;
    v_[i] = r.Av[i] * q + r.Bv[i] * v + r.Cv[i] * f0 + r.Dv[i] * f1;
  }
}

void ModalBank::step(const EndLoads& begin, const EndLoads& end, StepResult& out, int level,
                     int next_level) {
  const Recurrence& r = rec_[level];
  const Recurrence& rn = rec_[next_level < 0 ? level : next_level];
  // Lane k of a block of four modes holds n = 4j + k + 1: n odd for k = 0, 2 ((-1)^n = -1,
  // cos(n pi / 2) = 0), n = 4j + 2 for k = 1 (cos = -1), n = 4j + 4 for k = 3 (cos = +1).
  const double f0o = gain_ * (begin.left_N - begin.right_N),
               f0e = gain_ * (begin.left_N + begin.right_N);
  const double f1o = gain_ * (end.left_N - end.right_N), f1e = gain_ * (end.left_N + end.right_N);
  const double f0[4] = {f0o, f0e, f0o, f0e}, f1[4] = {f1o, f1e, f1o, f1e};
  FusedArrays arr{q_.data(),   v_.data(),   r.A.data(),  r.B.data(),
                  r.C.data(),  r.D.data(),  r.Av.data(), r.Bv.data(),
                  r.Cv.data(), r.Dv.data(), c1_.data(),  k1_.data(),
                  rn.A.data(), rn.B.data(), rn.C.data(), static_cast<int>(q_.size())};
  double s[12];
  if (&rn == &r)
    fused_step_kernel(arr, f0, f1, s);
  else
    fused_step_kernel_other_next(arr, f0, f1, s);
  // Forcing term of the accelerations, f1 once per real mode of each lane.
  for (int k = 0; k < 4; ++k) s[4 + k] += f1[k] * ((modes_ - k + 3) / 4);
  lane_faces(s, out.disp);
  lane_faces(s + 4, out.accel);
  lane_faces(s + 8, out.next_pred);
}

void ModalBank::step_free(StepResult& out) {
  FreeArrays arr{q_.data(),  v_.data(),   Af_.data(),
                 Bf_.data(), Avf_.data(), Bvf_.data(),
                 c1_.data(), k1_.data(),  static_cast<int>(q_.size())};
  double s[8];
  free_step_kernel(arr, s);
  lane_faces(s, out.disp);
  lane_faces(s + 4, out.accel);
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
  for (auto* a : {&Af_, &Bf_, &Avf_, &Bvf_}) a->assign(q_.size(), 0.0);
  for (int i = 0; i < modes_; ++i) {
    const RecurrenceCoefficients c = recurrence_coefficients(omega_[i], xi_, h);
    Af_[i] = c.A, Bf_[i] = c.B, Avf_[i] = c.Av, Bvf_[i] = c.Bv;
  }
  // Binary powers of the free recurrence [[A, B], [Av, Bv]] by repeated squaring, up to 2^40
  // steps. A damped mode's powers decay (to zero for the high modes), so no entry overflows.
  constexpr int kLevels = 41;
  free_pow_.assign(kLevels, std::vector<double>(4 * static_cast<std::size_t>(modes_), 0.0));
  for (int i = 0; i < modes_; ++i) {
    double* m = &free_pow_[0][4 * i];
    m[0] = Af_[i], m[1] = Bf_[i], m[2] = Avf_[i], m[3] = Bvf_[i];
  }
  for (int j = 1; j < kLevels; ++j)
    for (int i = 0; i < modes_; ++i) {
      const double* a = &free_pow_[j - 1][4 * i];
      double* m = &free_pow_[j][4 * i];
      m[0] = a[0] * a[0] + a[1] * a[2];
      m[1] = a[0] * a[1] + a[1] * a[3];
      m[2] = a[2] * a[0] + a[3] * a[2];
      m[3] = a[2] * a[1] + a[3] * a[3];
    }
}

void ModalBank::advance_free(long k, StepResult& out) {
  if (k < 0 || h_free_ <= 0.0 || (k >> (free_pow_.size() - 1)) > 1)
    throw std::logic_error("ModalBank::advance_free: no free step set, or k out of range");
  for (std::size_t j = 0; k != 0; ++j, k >>= 1) {
    if (!(k & 1)) continue;
    const double* m = free_pow_[j].data();
    for (int i = 0; i < modes_; ++i) {
      const double q = q_[i], v = v_[i];
      q_[i] = m[4 * i] * q + m[4 * i + 1] * v;
      v_[i] = m[4 * i + 2] * q + m[4 * i + 3] * v;
    }
  }
  double sq[4] = {0, 0, 0, 0}, sa[4] = {0, 0, 0, 0};
  for (int i = 0; i < modes_; ++i) {
    sq[i % 4] += q_[i];
    sa[i % 4] -= c1_[i] * v_[i] + k1_[i] * q_[i];
  }
  lane_faces(sq, out.disp);
  lane_faces(sa, out.accel);
}

double ModalBank::free_accel_bound() const {
  double b = 0.0;
  for (int i = 0; i < modes(); ++i) {
    const double r = v_[i] / omega_[i];
    b += omega_[i] * omega_[i] * std::sqrt(q_[i] * q_[i] + r * r);
  }
  return b * (1.0 + 2.0 * xi_);
}

void ModalBank::step_free() {
  for (int i = 0; i < modes(); ++i) {
    const double q = q_[i], v = v_[i];
    q_[i] = Af_[i] * q + Bf_[i] * v;
    v_[i] = Avf_[i] * q + Bvf_[i] * v;
  }
}

double ModalBank::face_motion_bound(double h) const {
  return face_motion_kernel(q_.data(), v_.data(), omega_.data(), static_cast<int>(q_.size()), h);
}

void ModalBank::reset() {
  std::fill(q_.begin(), q_.end(), 0.0);
  std::fill(v_.begin(), v_.end(), 0.0);
}

}  // namespace pound::sears

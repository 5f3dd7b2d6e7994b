#pragma once
// Operations on a ground-acceleration record: integration, baseline correction, truncation
// and scaling. Pure functions: a new GroundMotion in, a new GroundMotion out.
#include <cstddef>
#include <memory>
#include <vector>

#include "motion/ground_motion.hpp"

namespace pound {

/// Ground velocity [m/s] and displacement [m] at the samples, starting from rest, for the
/// piecewise-linear acceleration between samples (exact integration of that interpolant):
///   v_{i+1} = v_i + dt (a_i + a_{i+1}) / 2
///   d_{i+1} = d_i + dt v_i + dt^2 (2 a_i + a_{i+1}) / 6
struct GroundKinematics {
  std::vector<double> velocity;      ///< [m/s]
  std::vector<double> displacement;  ///< [m]
  double final_velocity() const { return velocity.empty() ? 0.0 : velocity.back(); }
  double final_displacement() const { return displacement.empty() ? 0.0 : displacement.back(); }
};
GroundKinematics integrate(const GroundMotion& motion);

/// Baseline correction. A correction acceleration a_c(t) = (1 - s) sum_{k=1}^{4} c_k s^k,
/// s = t / T (T the duration), is subtracted; it vanishes at both ends, so the record's
/// first and last values are kept, and its displacement is a polynomial of degree 7. The
/// coefficients
/// minimise the squared difference between the record's displacement and the correction's
/// displacement over all samples (the classic least-squares polynomial fit to the
/// displacement drift), subject to the two equality constraints that the corrected final
/// velocity and final displacement are zero (to round-off; both use the same exact
/// integration as integrate()). Solved as a 6x6 KKT system. Records shorter than 8 samples
/// are returned unchanged.
GroundMotion baseline_correct(const GroundMotion& motion);

/// baseline_correct for many records of one length and spacing (the motion generator corrects
/// every iteration): the basis functions' integrals and the KKT matrix's factors are computed
/// once, so a correction is one integration of the record, four dot products and the solve.
/// Gives baseline_correct's numbers bit for bit.
class BaselineCorrector {
 public:
  /// samples n >= 8, spacing dt > 0 [s]
  BaselineCorrector(std::size_t samples, double dt);
  ~BaselineCorrector();
  BaselineCorrector(const BaselineCorrector&) = delete;
  BaselineCorrector& operator=(const BaselineCorrector&) = delete;
  /// Corrects accel [m/s^2] (samples values) in place. Not const: uses scratch buffers (one
  /// corrector per thread).
  void apply(std::vector<double>& accel);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The first `seconds` [s] of a record (samples with t <= seconds, to 1e-9 dt). Throws
/// InputError when seconds <= 0.
GroundMotion truncate(const GroundMotion& motion, double seconds);

/// The record multiplied by `factor` [-].
GroundMotion scale(const GroundMotion& motion, double factor);

}  // namespace pound

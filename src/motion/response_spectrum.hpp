#pragma once
// Elastic single-degree-of-freedom response spectra by the exact piecewise-linear recurrence
// of Nigam & Jennings (1969), "Calculation of response spectra from strong-motion
// earthquake records", BSSA 59(2):909-922.
//
// The oscillator  x'' + 2 zeta omega x' + omega^2 x = -a_g(t)  (x relative displacement [m])
// is advanced exactly for the ground acceleration interpolated linearly between samples. The
// response is exact at every step for that interpolant; sub-stepping only adds points at
// which the peak is looked for (steps of at most max_step_fraction * T), which matters at
// short periods (El Centro NS, 5 %, T = 0.2 s: PSA 0.793 g without, 0.820 g with T/20).
// Peaks are taken over the record's duration (no free-vibration tail). SpectrumCalculator
// takes one exact step of the record spacing per sample and computes the points inside it
// directly from the state at the step's start (issue 13; the same numbers to round-off as the
// sub-steps taken one after another, tests/motion/response_spectrum_test.cpp).
#include <vector>

#include "motion/design_spectrum.hpp"
#include "motion/ground_motion.hpp"

namespace pound {

/// Instruction set of the oscillator kernel; every one gives the same bits (automatic: the
/// widest the CPU has; the others are for tests and benchmarks).
enum class SimdPath { automatic, avx512, avx2, baseline };
/// Whether the CPU running this has the instruction set of `path`.
bool simd_path_available(SimdPath path);

struct ResponseSpectrumOptions {
  /// Largest step used to look for peaks, as a fraction of the period [-]: the peak is looked
  /// for at the ends of ceil(dt / (fraction T)) equal sub-steps of each record step dt.
  /// 0 = at the samples only.
  double max_step_fraction = 0.05;
  SimdPath simd = SimdPath::automatic;
};

/// Peaks at the given periods for one damping ratio.
struct ResponseSpectrum {
  double damping = 0.05;       ///< fraction of critical [-]
  std::vector<double> period;  ///< T [s]
  std::vector<double> sd;      ///< peak relative displacement [m]
  std::vector<double> psv;     ///< pseudo-velocity omega * sd [m/s]
  std::vector<double> psa;     ///< pseudo-acceleration omega^2 * sd [m/s^2]
  std::vector<double> sa_abs;  ///< peak absolute acceleration |x'' + a_g| [m/s^2]
};

/// Exact one-step propagator of the oscillator over a step h for a linearly varying ground
/// acceleration (Nigam & Jennings 1969, eq. 6-7 form):
///   x1 = a11 x0 + a12 v0 + b11 ag0 + b12 ag1,   v1 = a21 x0 + a22 v0 + b21 ag0 + b22 ag1.
struct SdofStep {
  double a11, a12, a21, a22, b11, b12, b21, b22;
  /// period T > 0 [s], damping 0 <= zeta < 1 [-], step h > 0 [s]
  static SdofStep make(double period, double damping, double h);
};

/// Relative displacement [m] and velocity [m/s] at the record's samples, from rest.
struct SdofHistory {
  std::vector<double> x, v;
};
SdofHistory sdof_history(const GroundMotion& motion, double period, double damping);

/// Evaluates spectra of many records of one sample spacing at fixed periods and damping;
/// the step coefficients are computed once (the generator calls this in its iterations).
class SpectrumCalculator {
 public:
  /// periods >= 0 [s] (T = 0 gives the peak ground acceleration), damping in [0, 1) [-],
  /// dt > 0 [s]. Throws InputError on invalid values.
  SpectrumCalculator(std::vector<double> periods, double damping, double dt,
                     ResponseSpectrumOptions options = {});
  /// Spectrum of accel [m/s^2] sampled at dt.
  ResponseSpectrum compute(const std::vector<double>& accel) const;
  /// Only the pseudo-acceleration [m/s^2] (the generator's inner loop), into psa.
  void compute_psa(const std::vector<double>& accel, std::vector<double>& psa) const;
  const std::vector<double>& periods() const { return periods_; }

 private:
  struct PerPeriod {
    double omega = 0.0;  // 0 for T = 0
    int substeps = 1;
  };
  // The oscillators (periods > 0) sit side by side in flat arrays (structure of arrays),
  // ordered by sub-step count, most first, and padded with inert lanes (all coefficients 0)
  // to a multiple of kLanes, so that one SIMD kernel advances eight independent recurrences
  // at once. Every lane takes one exact step of the record spacing dt per sample, on the
  // shifted state y = x - b12 a_i, u = v - b22 a_i (g1, g2: the coefficients of a_i there);
  // the points inside a step at which the peak is also looked for (t_i + j dt / m, j < m) are
  // computed directly from the state at t_i and the two samples (Points), not by stepping.
  struct Lanes {
    std::vector<double> a11, a12, a21, a22, g1, b12, g2, b22, c, w2;
  };
  // Inner points of block b (lanes [kLanes b, kLanes (b + 1))): count[b] points, the first
  // one's coefficients at offset[b] (in units of kLanes values); a lane with fewer points than
  // its block has zero coefficients for the extra ones (x = 0 there, which never raises a peak).
  struct Points {
    std::vector<int> count;
    std::vector<std::size_t> offset;
    // x(t_i + s dt) = xx y_i + xv u_i + xa0 a_i + xa1 a_{i+1}; v likewise.
    std::vector<double> xx, xv, xa0, xa1, vx, vv, va0, va1;
  };
  // Peak |x| and peak |x'' + a_g| (when sa is not null) of every period.
  void peaks(const std::vector<double>& accel, std::vector<double>& sd,
             std::vector<double>* sa) const;
  std::vector<double> periods_;
  double damping_, dt_;
  SimdPath path_;
  std::vector<PerPeriod> per_;
  bool rigid_ = false;  // some period is 0: its peak is the record's PGA (computed only then)
  std::vector<std::size_t> lane_of_;  // lane of period i (periods > 0)
  Lanes lanes_;
  Points points_;
};

/// Response spectrum of a record at the given periods [s] and damping [-].
ResponseSpectrum response_spectrum(const GroundMotion& motion, const std::vector<double>& periods,
                                   double damping, ResponseSpectrumOptions options = {});

/// A design spectrum at the given periods [s] as a response spectrum: psa = sa_abs = its
/// pseudo-acceleration Sa(T) [m/s^2], sd = Sa / w^2 [m], psv = Sa / w [m/s] (w = 2 pi / T; 0 at
/// T = 0), at its damping (`pound motion target`).
ResponseSpectrum design_response_spectrum(const DesignSpectrum& target,
                                          const std::vector<double>& periods);

/// n periods spaced evenly in log T from t_min to t_max [s] (both included), n >= 2.
std::vector<double> log_spaced_periods(double t_min, double t_max, int n);

}  // namespace pound

#pragma once
// Spectrum-compatible artificial ground motions after SIMQKE (Gasparini & Vanmarcke 1976,
// "Simulated earthquake motions compatible with prescribed response spectra", MIT R76-4).
//
//   a(t) = I(t) sum_k A_k cos(w_k t + phi_k),  then baseline correction,
//
// with w_k the bins of a real FFT of length nfft >= 2 n (n samples of the motion; the
// stationary part is synthesised by one FFTW complex-to-real transform and its first n
// samples kept), phi_k uniform on [0, 2 pi) from Philox4x32-10 keyed by (seed, index), and
// I(t) an intensity envelope (envelope.hpp).
//
// First guess of the one-sided power spectral density from the target pseudo-acceleration
// (Vanmarcke's narrow-band approximation without the integral correction):
//   G(w) = 4 zeta (Sa(w) / r)^2 / (pi w),   A_k = sqrt(2 G(w_k) dw),
//   r = sqrt(2 ln(2 N)),  N = max(1.5, w Ts / (2 pi ln 2))  (median peak factor, Ts the
//   strong-phase duration of the envelope).
// Iteration (SIMQKE's correction): compute the pseudo-acceleration spectrum of the
// baseline-corrected motion at the matching periods, and multiply A_k by the ratio target /
// computed, interpolated in log period at T = 2 pi / w_k (end ratios held outside the
// matching range). Stop when every ratio is within 1 +- tolerance or after max_iterations;
// the motion with the smallest largest deviation is returned.
//
// Deterministic: the same (target, duration, settings, seed, index) give the same motion on
// any machine to round-off (own uniform -> phase transform, FFTW_ESTIMATE plans whose choice
// does not depend on timing; no std:: distributions).
#include <cstdint>
#include <memory>
#include <vector>

#include "motion/design_spectrum.hpp"
#include "motion/envelope.hpp"
#include "motion/ground_motion.hpp"

namespace pound {

struct SimqkeSettings {
  double dt = 0.01;             ///< sample spacing [s]
  EnvelopeSettings envelope;    ///< intensity envelope
  double match_t_min = 0.04;    ///< shortest matching period [s]
  double match_t_max = 5.0;     ///< longest matching period [s]
  int match_periods = 120;      ///< log-spaced matching periods [-]
  int max_iterations = 25;      ///< correction iterations at most [-]
  double tolerance = 0.04;      ///< stop when |computed / target - 1| <= tolerance everywhere
  double max_frequency = 0.0;   ///< highest frequency with energy [Hz]; 0: 0.8 Nyquist
  int padding = 2;              ///< FFT length >= padding * samples [-]
  double relaxation = 1.0;      ///< amplitudes scale by ratio^relaxation per iteration [-]
};

/// Ratio of a computed to a target spectrum over a set of periods.
struct SpectrumMatch {
  double min_ratio = 0.0, max_ratio = 0.0, mean_ratio = 0.0;  ///< [-]
};
SpectrumMatch compare_spectra(const std::vector<double>& computed,
                              const std::vector<double>& target);

struct GeneratedMotion {
  GroundMotion motion;            ///< baseline-corrected acceleration [m/s^2]
  int iterations = 0;             ///< correction iterations used
  SpectrumMatch match;            ///< at the matching periods
  double final_velocity = 0.0;    ///< [m/s]
  double final_displacement = 0.0;///< [m]
};

/// A generator for one target, duration and settings. FFTW plans and buffers are made once
/// and reused by every generate() call; one object per thread (generate() mutates buffers).
class SimqkeGenerator {
 public:
  /// target: the design spectrum (matched at its own damping); duration [s] > 10 dt.
  SimqkeGenerator(const DesignSpectrum& target, double duration, SimqkeSettings settings = {});
  ~SimqkeGenerator();
  SimqkeGenerator(const SimqkeGenerator&) = delete;
  SimqkeGenerator& operator=(const SimqkeGenerator&) = delete;

  /// Motion number `index` of the sequence keyed by `seed`.
  GeneratedMotion generate(std::uint64_t seed, std::uint64_t index = 0);

  const std::vector<double>& match_periods() const;
  /// Target pseudo-acceleration at the matching periods [m/s^2].
  const std::vector<double>& match_target() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One spectrum-compatible motion: (spectrum, duration [s], seed) -> motion; the call the
/// Monte Carlo campaign makes per sample (a generator per call; keep a SimqkeGenerator to
/// reuse the FFT plans across samples).
GroundMotion generate_spectrum_compatible(const DesignSpectrum& target, double duration,
                                          std::uint64_t seed, const SimqkeSettings& settings = {});

/// Uniform number in [0, 1) with 53 random bits from Philox4x32-10, key (seed), counter
/// (i, 0, index low, index high); the generator's phases are 2 pi u. Exposed for tests.
double philox_uniform(std::uint64_t seed, std::uint64_t index, std::uint32_t i);

}  // namespace pound

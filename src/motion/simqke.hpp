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
// matching range), raised to the power `relaxation`; the correction filters the Fourier
// transform of the current motion (FFTW real-to-complex, zero-padded to nfft; phases kept;
// complex-to-real back, first n samples), then the motion is baseline-corrected again.
// Stop when every ratio is within the tolerance band or after max_iterations; the motion
// with the smallest score max_j |q_j - 1| (q = computed / target) is
// kept. A few phase sets do not converge at the longest periods (the correction of a
// narrow band cannot move a late peak); when the best score exceeds accept_score the
// phases are drawn again from the next Philox stream (deterministically) and the best
// motion over the attempts is returned.
//
// Record-to-record variability (issue 12): generate(seed, index, ln_factor) matches the motion
// to a random target design(T) exp(sigma(T) eps(T)) drawn by TargetVariability
// (spectral_variability.hpp) instead of the design spectrum itself; the phases and the
// correction are the same, the score of an iteration is the RMS of ln(computed / target) and
// one phase set is used (see generate).
//
// Deterministic: the same (target, duration, settings, seed, index) give the same motion on
// any machine to round-off (own uniform -> phase transform, FFTW_ESTIMATE plans whose choice
// does not depend on timing; no std:: distributions).
#include <complex>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "motion/design_spectrum.hpp"
#include "motion/envelope.hpp"
#include "motion/ground_motion.hpp"

namespace pound {

struct SimqkeSettings {
  double dt = 0.01;           ///< sample spacing [s]
  EnvelopeSettings envelope;  ///< intensity envelope
  /// Matching periods: match_periods log-spaced from match_t_min to match_t_max [s], plus
  /// match_extend more at the same spacing beyond each end (default 100 periods 0.05-4 s,
  /// extended to 0.040-4.99 s, so that the check grid of the acceptance is matched exactly).
  double match_t_min = 0.05;
  double match_t_max = 4.0;
  int match_periods = 100;
  int match_extend = 5;
  int max_iterations = 35;  ///< correction iterations at most [-]
  /// Stop when every q = computed / target satisfies |q - 1| <= tol [-].
  double tolerance = 0.04;
  double max_frequency = 0.0;  ///< highest frequency with energy [Hz]; 0: 0.8 Nyquist
  int padding = 2;             ///< FFT length >= padding * samples [-]
  /// Fourier amplitudes are multiplied by ratio^relaxation per iteration [-]; > 1 because a
  /// peak response grows less than proportionally with the amplitudes of its band.
  double relaxation = 1.6;
  /// A motion whose best score exceeds accept_score after the iterations is drawn again
  /// with the next phase set (stream 1, 2, ...), at most max_attempts sets in all; the best
  /// motion over all attempts is returned. Score: max_j |q_j - 1|.
  double accept_score = 0.095;
  int max_attempts = 4;
  /// Phase sets at most for a random target (generate with ln factors) [-]. One: a random
  /// target is rough at every period scale and partly out of reach of any motion of this
  /// kind (docs/motions.md, "Record-to-record variability"), so its score stays above
  /// accept_score whatever the phases, and new phase sets would only multiply the cost.
  int max_attempts_random_target = 1;
  /// An attempt ends early when its score has not improved for `stall` iterations and
  /// the best motion is acceptable, or for 2 stall iterations otherwise [-].
  int stall = 8;
};

/// The matching periods of the settings [s] (see SimqkeSettings).
std::vector<double> simqke_match_periods(const SimqkeSettings& settings);

/// Ratio of a computed to a target spectrum over a set of periods.
struct SpectrumMatch {
  double min_ratio = 0.0, max_ratio = 0.0, mean_ratio = 0.0;  ///< [-]
};
SpectrumMatch compare_spectra(const std::vector<double>& computed,
                              const std::vector<double>& target);

struct GeneratedMotion {
  GroundMotion motion;  ///< baseline-corrected acceleration [m/s^2]
  /// The spectrum the motion was matched to, at the matching periods [m/s^2]: the design
  /// spectrum, or its random target (generate with ln factors).
  std::vector<double> target_psa;
  int iterations = 0;   ///< correction iterations of the returned motion
  int attempt = 0;      ///< phase set of the returned motion (0 = first)
  int spectra = 0;      ///< spectrum evaluations, every phase set counted
  SpectrumMatch match;  ///< at the matching periods
  /// The motion's pseudo-acceleration spectrum at the matching periods [m/s^2] (the one its
  /// score was taken on).
  std::vector<double> psa;
  double final_velocity = 0.0;      ///< [m/s]
  double final_displacement = 0.0;  ///< [m]
};

/// What the matching iteration of one phase set starts from (SimqkeGenerator::start).
struct SimqkeStart {
  std::vector<double> amplitude;  ///< first-guess A_k of FFT bin k [m/s^2] (0 outside the band)
  std::vector<double> target;     ///< the spectrum matched to, at the matching periods [m/s^2]
  int max_attempts = 1;           ///< phase sets at most [-]
  bool rms_score = false;         ///< score RMS of ln q (random target) instead of max |q - 1|
  double stop_score = 0.0;        ///< > 0: the iteration also ends once a score is <= this [-]
  /// For the stall rules an iteration improves only when its score is below (1 - stall_gain)
  /// times the score of the last iteration that did [-] (0: any improvement; the best motion
  /// is kept either way).
  double stall_gain = 0.0;
  /// > 1: coarse iterations. Iterations 0, full_every, 2 full_every, ... take the spectrum at
  /// every matching period (the reference R); the others at every coarse_stride-th one only (and
  /// the last), and between those ln(PSA / R) linearly in ln T (R's period-to-period structure
  /// kept), for the correction. Every iteration is scored over the coarse periods alone. The
  /// returned attempt is then unscored: its psa is empty and its score the coarse one;
  /// SimqkeGenerator::score gives it its full spectrum and score. 1: every matching period at
  /// every iteration [-].
  int coarse_stride = 1;
  int full_every = 4;  ///< see coarse_stride, >= 1 [-]
};

/// The best iteration of one phase set (SimqkeGenerator::match).
struct SimqkeAttempt {
  GroundMotion motion;      ///< baseline-corrected acceleration [m/s^2]
  double score = 1e300;     ///< max |q - 1| or RMS ln q of the motion [-]
  int iterations = 0;       ///< correction iterations of the motion
  int spectra = 0;          ///< spectrum evaluations of the phase set
  SpectrumMatch match;      ///< at the matching periods
  std::vector<double> psa;  ///< the motion's spectrum at the matching periods [m/s^2]
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

  /// Motion number `index` of the sequence keyed by `seed`, matched to the design spectrum.
  GeneratedMotion generate(std::uint64_t seed, std::uint64_t index = 0);
  /// The same phases, matched to the random target design(T_j) exp(ln_factor_j) at the
  /// matching periods T_j (one factor per period, spectral_variability.hpp): the first-guess
  /// amplitudes are multiplied by exp(ln_factor) interpolated linearly in ln T at each FFT bin
  /// (end values held), as the correction ratio is. The iteration is the same except that the
  /// kept iteration is the one with the smallest RMS of ln(computed / target) over the
  /// matching periods (instead of the smallest max |computed / target - 1|; acceptance and
  /// stall use that score too) and at most max_attempts_random_target phase sets are tried:
  /// a random target has ordinates that no motion of this kind reaches (docs/motions.md), which
  /// would dominate the maximum and make every phase set fail the acceptance.
  GeneratedMotion generate(std::uint64_t seed, std::uint64_t index,
                           const std::vector<double>& ln_factor);

  const std::vector<double>& match_periods() const;
  /// Target pseudo-acceleration at the matching periods [m/s^2].
  const std::vector<double>& match_target() const;

  // The lower level that generate() is made of, for generators of several motions at once
  // (ground/station_generator.hpp): generate(seed, index) is start(), then for each phase set
  // a = 0, 1, ... match() from the phasors simqke_phasors(seed, index, a) until an attempt's
  // score is within accept_score, the attempt of the smallest score kept, then finish().

  /// FFT bins of the stationary part, nfft / 2 + 1 [-].
  std::size_t fft_bins() const;
  /// Frequency of bin k [Hz] (k / (nfft dt)).
  double bin_frequency(std::size_t k) const;
  /// The start for the design spectrum (generate(seed, index)).
  SimqkeStart start() const;
  /// The start for the random target design(T_j) exp(ln_factor_j) (generate with ln factors).
  SimqkeStart start(const std::vector<double>& ln_factor) const;
  /// One phase set's iteration from the stationary part's Fourier coefficients A_k (re_k + i
  /// im_k), A_k = s.amplitude[k]: synthesis a(t) = I(t) sum_k A_k |z_k| cos(w_k t + arg z_k),
  /// baseline correction, the correction loop with its tolerance and stall rules; returns the
  /// best iteration. For one motion z_k = exp(i phi_k) (simqke_phasors).
  SimqkeAttempt match(const SimqkeStart& s, const std::vector<double>& re,
                      const std::vector<double>& im);
  /// The same iteration from a given motion (iteration 0 is `m` itself).
  SimqkeAttempt match(const SimqkeStart& s, GroundMotion m);
  /// How an iteration's correction is applied: `m` is the current motion, `ratio` target /
  /// computed at the matching periods; the corrector replaces `m` by the corrected motion.
  using Corrector = std::function<void(GroundMotion& m, const std::vector<double>& ratio)>;
  /// The same iteration with another correction step than correct() (the loop, score,
  /// tolerance and stall rules unchanged; ground/station_generator.hpp).
  SimqkeAttempt match(const SimqkeStart& s, GroundMotion m, const Corrector& corrector);
  /// The phase sets of generate(): start `s`, phases simqke_phasors(seed, index, a).
  GeneratedMotion generate(const SimqkeStart& s, std::uint64_t seed, std::uint64_t index);
  /// The stationary part of coefficients A_k (re_k + i im_k), enveloped and baseline-corrected.
  GroundMotion synthesise(const SimqkeStart& s, const std::vector<double>& re,
                          const std::vector<double>& im);
  /// One correction step: the Fourier amplitudes of `m` times ratio^relaxation, `ratio` (target
  /// / computed at the matching periods, [-]) interpolated in ln T at each bin; baseline-corrected.
  void correct(GroundMotion& m, const std::vector<double>& ratio);
  /// The pseudo-acceleration of `m` at the matching periods [m/s^2].
  void spectrum(const GroundMotion& m, std::vector<double>& psa) const;
  /// The spectrum of a.motion at every matching period into a.psa, its score against s.target
  /// (max |q - 1|, or the RMS of ln q with s.rms_score, as match() scores) and a.match; one
  /// more evaluation in a.spectra.
  void score(const SimqkeStart& s, SimqkeAttempt& a) const;
  /// The Fourier transform of a record of the generator's length zero-padded to the FFT length
  /// (unnormalised, fft_bins() values) [m/s^2 x samples].
  void transform(const std::vector<double>& accel, std::vector<std::complex<double>>& x);
  /// The inverse of transform(): the first samples of the real sequence of x / nfft, the DC bin
  /// dropped, baseline-corrected, as correct() ends.
  void inverse(const std::vector<std::complex<double>>& x, GroundMotion& m);
  /// ratio^power at every bin k >= 1, ratio interpolated in ln T as correct() does (end values
  /// held); out[0] = 1.
  void bin_power(const std::vector<double>& ratio, double power, std::vector<double>& out) const;
  const SimqkeSettings& settings() const;
  /// The returned motion of the kept attempt: its name, target, phase set, kinematics.
  GeneratedMotion finish(SimqkeAttempt best, const SimqkeStart& s, std::uint64_t seed,
                         std::uint64_t index, int attempt, int spectra) const;

 private:
  GeneratedMotion run(const SimqkeStart& s, std::uint64_t seed, std::uint64_t index);
  template <class Correct>
  SimqkeAttempt iterate(const SimqkeStart& s, GroundMotion m, const Correct& correct);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One spectrum-compatible motion: (spectrum, duration [s], seed) -> motion; the call the
/// Monte Carlo campaign makes per sample (a generator per call; keep a SimqkeGenerator to
/// reuse the FFT plans across samples).
GroundMotion generate_spectrum_compatible(const DesignSpectrum& target, double duration,
                                          std::uint64_t seed, const SimqkeSettings& settings = {});

/// Uniform number in [0, 1) with 53 random bits from Philox4x32-10, key (seed), counter
/// (i, stream, index low, index high); the generator's phase of bin i in attempt `stream`
/// is 2 pi u. Exposed for tests.
double philox_uniform(std::uint64_t seed, std::uint64_t index, std::uint32_t i,
                      std::uint32_t stream = 0);

/// The phasors exp(i phi_k), phi_k = 2 pi philox_uniform(seed, index, k, stream), of the bins
/// with amplitude (re = 1, im = 0 where amplitude[k] == 0: no phase is drawn there), resized to
/// amplitude.size(). Stream a is the generator's phase set a.
void simqke_phasors(std::uint64_t seed, std::uint64_t index, std::uint32_t stream,
                    const std::vector<double>& amplitude, std::vector<double>& re,
                    std::vector<double>& im);

}  // namespace pound

#pragma once
// Spatially varying spectrum-compatible motions at S stations of a row (issue 28,
// docs/ground.md, "Generation"): conditional simulation in the frequency domain (Vanmarcke &
// Fenton 1991; Konakli & Der Kiureghian 2012, EESD 41:495-513, who condition on recorded
// motions) on the stations already generated, each station then matched to the target by a
// SIMQKE iteration that changes it only where it misses the target.
//
// 1. Station 1 is SimqkeGenerator::generate(seed, index[, ln_factor]) itself (phase sets,
//    matching, acceptance: one motion).
// 2. Station j = 2..S, at every FFT bin f_k (X_m the Fourier transform, zero-padded to the
//    generator's FFT length, of the MATCHED station m < j):
//
//      X_j = sum_{m<j} b_jm X_m + L_jj E_j W_j,
//      (G_<j + delta I) b_j = g_j + delta g_jn e_n,   L_jj^2 = 1 - b_j^T G_<j b_j,
//
//    the regression (kriging) of station j on the stations before it under the coherency
//    matrix G_jm = gamma_in(|x_j - x_m|, f_k) (the lagged coherency; the wave passage is a pure
//    delay of each station, applied by the caller with delayed(), Deodatis 1996, Prob. Eng.
//    Mech. 11:149-167), n the most coherent (nearest) earlier station. The nugget delta = 0.01
//    is there because the earlier stations are matched motions, not samples of the model:
//    without it the regression on close stations extrapolates (Luco-Wong at 100 m lost 0.2 of
//    coherency); it pulls b_j towards the regression on station n alone, not towards 0 (so
//    that a pair of stations keeps its coherency, 0.991 at 12 m below 1 Hz, not 0.991 / 1.01).
//    W_j is SIMQKE's first guess with station j's phases (Philox stream a + 65536 (j - 1) in
//    phase set a: simqke_phasors, synthesis, envelope, baseline correction) and E_j =
//    sqrt(<sum_m |X_m|^2 / j> / <|W_j|^2>) equalises its power (<> a moving sum over
//    +-max(1, k/10) bins) to the earlier stations'. Before the matching, with one earlier
//    station, E[X_j X_1^*] = gamma_in S(f) exactly.
// 3. gamma_in = gamma + kappa(f) (c^-1(gamma) - gamma): the model's coherency, raised towards
//    c^-1(gamma), c(g) = [E(g) - (1 - g^2) K(g)] / g the coherency of the unit phasors of two
//    circular Gaussians of correlation g (K, E complete elliptic integrals of modulus g), with
//    kappa 0 up to 2 Hz, 0.5 (0.25 with a random target) from 6 Hz, linear in ln f between.
//    Why: per-station matching equalises the stations' spectral amplitudes, which takes a set
//    of Gaussian correlation g towards the phase coherency c(g) < g; the matching of step 4
//    loses nothing measurable up to 2 Hz and about half of g - c(g) at 4-10 Hz (a quarter with
//    a random target). An empirical calibration (docs/ground.md), measured for the default
//    settings (10 s at 0.01 s), checked at 20 s, for NZS 1170.5 and the three models.
// 4. Each station j >= 2 is matched by SIMQKE's iteration (SimqkeGenerator::match: its loop,
//    best-iteration and stall rules, envelope, baseline correction and relaxation) with its
//    own correction step: at the matching periods T_i,
//      l_i = ln(target_i / computed_i), soft-thresholded by the dead band 0.07 (l_i - 0.07
//      above it, l_i + 0.07 below -0.07, 0 between), smoothed (1/4, 1/2, 1/4) over the
//      neighbouring periods, exp(relaxation l) interpolated in ln T at the bins as SIMQKE's
//      ratio and, below the lowest matching frequency f_lo, faded out over one octave (its
//      logarithm times ln(2 f / f_lo) / ln 2; SIMQKE holds the end ratio there);
//    the iteration ends once max |q - 1| <= 0.085 (below accept_score = 0.095). A station is
//    changed only where it is out of the band, so the set keeps the start's cross spectra:
//    SIMQKE's own iteration keeps correcting periods already within tolerance, a random walk
//    of each station's Fourier amplitudes that cost the former generator 0.03-0.16 of
//    coherency at 1-6 Hz and decorrelated close stations below 1 Hz. The band is widened to the
//    earlier stations' mean ln(target / computed) +- 0.02 where they miss it by more (a station
//    does not chase an ordinate its neighbours miss as much, or no motion reaches): with the
//    design spectrum up to ln(1 +- 0.085) (issue 37), with a random target (RMS score) without
//    a limit; the latter's iteration has no stop score; for its stall rules an iteration improves
//    only when it lowers the score 5 % below the last one that did (SimqkeStart::stall_gain). Phase
//    sets: station j alone, W_j drawn again from the next stream, at most 2 max_attempts (2
//    max_attempts_random_target) draws, the one of the smallest score kept.
// 5. Below the lowest matching frequency f_lo nothing is matched, but each station's own
//    processing (its corrections cut to the record, its baseline corrections) leaves there a
//    low-frequency content of its own that would be the largest part of the relative
//    displacement of close stations under a model near 1 (issue 37). So the kept motion of
//    station j gets the least-norm correction on its record (a combination of the rows below,
//    restricted to the record) that sets its Fourier bins 1..K below f_lo to
//      Z_k = X_k + w_k (z_k - X_k),   z_k = C_jk + L_jj E_j W_jk (the conditional start),
//    and keeps its final velocity and displacement at 0; w_k = 1 where the innovation's share
//    L_jj <= 0.05 (1 - gamma_in <~ 1.3e-3), 0 from 0.1, linear between, so that only nearly
//    coherent bins, where the start is as coherent as the model, are pinned. Its score is then
//    evaluated again.
//
// With coherency none (or S = 1) every station is bit for bit SimqkeGenerator::generate's
// motion, which is computed once and copied.
#include <complex>
#include <cstdint>
#include <memory>
#include <vector>

#include "ground/coherency.hpp"
#include "motion/design_spectrum.hpp"
#include "motion/simqke.hpp"

namespace pound {

struct StationSettings {
  std::vector<double>
      positions;        ///< station coordinates along the row [m], strictly increasing, S >= 1
  Coherency coherency;  ///< lagged coherency (none: fully coherent)
  /// Stations 2.. with a random target iterate on coarse spectra (SimqkeStart::coarse_stride;
  /// station_generator.cpp, kCoarseStride); false: on full ones at every iteration (the
  /// generation before issue 38's coarse iterations, for tests and benchmarks).
  bool coarse_iterations = true;
};

class StationGenerator {
 public:
  /// target, duration [s], settings as SimqkeGenerator's. Throws InputError on positions that
  /// are empty, not finite or not strictly increasing.
  StationGenerator(const DesignSpectrum& target, double duration, SimqkeSettings settings,
                   StationSettings stations);
  ~StationGenerator();
  StationGenerator(const StationGenerator&) = delete;
  StationGenerator& operator=(const StationGenerator&) = delete;

  int stations() const;
  /// The S matched stations for (seed, index), not delayed. Station 1 is always, and with
  /// coherency none (or S = 1) EVERY station is, bit for bit SimqkeGenerator(target, duration,
  /// settings).generate(seed, index) (resp. with ln_factor). GeneratedMotion::attempt is the
  /// station's kept phase set and spectra its own evaluations.
  std::vector<GeneratedMotion> generate(std::uint64_t seed, std::uint64_t index);
  std::vector<GeneratedMotion> generate(std::uint64_t seed, std::uint64_t index,
                                        const std::vector<double>& ln_factor);
  const std::vector<double>& match_periods() const;
  const StationSettings& settings() const { return stations_; }
  /// The coherency the stations are generated with at separation d [m] and frequency f [Hz],
  /// gamma_in (step 3 above) [-], for the design spectrum or a random target.
  double input_coherency(double d, double f, bool random_target = false) const;

 private:
  using Complex = std::complex<double>;
  std::vector<GeneratedMotion> run(const SimqkeStart& s, std::uint64_t seed, std::uint64_t index);
  void factor_coherency(bool random_target, std::vector<double>& cond) const;
  GeneratedMotion station(const SimqkeStart& start, std::uint64_t seed, std::uint64_t index,
                          std::size_t j, std::vector<std::vector<Complex>>& x,
                          const std::vector<double>& misfit_sum);
  SimqkeAttempt match_station(const SimqkeStart& start, GroundMotion m0,
                              const std::vector<double>& misfit);
  void pin_low_frequencies(const SimqkeStart& start, const std::vector<Complex>& z,
                           const double* cond_j, std::size_t tri, SimqkeAttempt& a);

  SimqkeGenerator gen_;
  StationSettings stations_;
  double accept_score_ = 0.0;
  bool coherent_ = true;  // every station is station 1
  // per bin k: packed (j, m < j) -> b_jm, (j, j) -> L_jj (design spectrum, random target)
  std::vector<double> cond_, cond_random_;
  struct LowFrequencyPin;
  std::unique_ptr<LowFrequencyPin> pin_;  // step 5
};

/// The moving sum of p over bins k - h .. k + h (cut at the ends), h = max(1, k / 10), at every
/// bin k [p's unit]: the smoothing <> of step 2 above, each sum in the order of its bins. Exposed
/// for tests.
std::vector<double> moving_power_sum(const std::vector<double>& p);

/// Philox stream of station `station`'s phases (0-based) in phase set `attempt`: attempt +
/// 65536 station (station 0's is SimqkeGenerator's).
std::uint32_t station_phase_stream(int station, int attempt);

}  // namespace pound

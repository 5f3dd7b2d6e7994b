#pragma once
// Spatially varying spectrum-compatible motions at S stations of a row (issue 28,
// docs/ground.md): the spectral representation of a vector process (Deodatis 1996, "Simulation
// of ergodic multivariate stochastic processes", Prob. Eng. Mech. 11:149-167), with SIMQKE's
// unit-modulus Fourier coefficients. At every FFT frequency f_k of the generator, station j's
// coefficient is A(f_k) exp(i theta_j(f_k)),
//
//   exp(i theta_j) = z_j / |z_j|,  z_j = sum_{m <= j} L_jm(f_k) rho_m exp(i phi_m),
//
// with rho_m exp(i phi_m) independent standard circular complex Gaussians per station m (phi_m
// uniform, rho_m Rayleigh) and L the Cholesky factor of the S x S matrix
// G_jm = g(|gamma(|x_j - x_m|, f_k)|), g the inverse of the phase coherency
// c(g) = E exp(i (arg z_j - arg z_m)) = [E(g) - (1 - g^2) K(g)] / g of two circular Gaussians
// of correlation g (K, E complete elliptic integrals of modulus g): so the unit phasors of
// stations j and m have the coherency |gamma| of the model, and every station has SIMQKE's
// amplitude A(f_k) of one motion. Station 1's phases are exactly SimqkeGenerator's
// (z_1 / |z_1| = exp(i phi_1); Philox key seed, counter (k, a, index low, index high) in phase
// set a); station m's phases (m = 2, 3, ...) come from the stream a + 65536 (m - 1) and every
// station's Rayleigh moduli from the stream 2^31 + a + 65536 (m - 1) of the same key and
// counter layout.
//
// Each station is then matched to the target (the design spectrum, or the ONE random target of
// ln_factor shared by all stations of the set) by SIMQKE's iteration run on that station
// (SimqkeGenerator::match): the correction scales station j's amplitudes by a real positive
// ratio (Bi & Hao 2012, Prob. Eng. Mech. 29:92-104), with the same envelope and baseline
// correction as one motion. The set's lagged coherency after the matching is lower than the
// model's (docs/ground.md, "What the matching does to the coherency": by 0.03-0.16 at 1-6 Hz
// for 40-100 m under Harichandran-Vanmarcke), because the corrections of different stations
// differ. Phase-set retries (accept_score, max_attempts): all stations together, the attempt
// scored by its worst station (so that identical stations decide as one motion does); the
// attempt with the smallest such score is kept (the first of equal ones), and an attempt whose
// stations already score worse than the best attempt so far is abandoned (it cannot win).
//
// A semi-definite G (stations so close that they are fully coherent at f_k) is factored with
// the pivots that vanish set to 0. With coherency none (or S = 1) every station is bit for bit
// SimqkeGenerator::generate's motion, which is computed once and copied.
//
// The wave-passage phase exp(-i omega (x_k - x_j) / v) of the full coherency matrix is NOT
// applied here: it factors as D L with D = diag(exp(-i omega delay_j)), a pure delay of each
// station, which the caller applies with delayed() (ground/wave_passage.hpp) after matching.
#include <cstdint>
#include <vector>

#include "ground/coherency.hpp"
#include "motion/design_spectrum.hpp"
#include "motion/simqke.hpp"

namespace pound {

struct StationSettings {
  std::vector<double>
      positions;        ///< station coordinates along the row [m], strictly increasing, S >= 1
  Coherency coherency;  ///< lagged coherency (none: fully coherent)
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
  /// The S matched stations for (seed, index), not delayed. With coherency none (or S = 1)
  /// EVERY station is bit for bit SimqkeGenerator(target, duration, settings).generate(seed,
  /// index) (resp. with ln_factor). GeneratedMotion::attempt is the set's kept phase set and
  /// spectra each station's own evaluations.
  std::vector<GeneratedMotion> generate(std::uint64_t seed, std::uint64_t index);
  std::vector<GeneratedMotion> generate(std::uint64_t seed, std::uint64_t index,
                                        const std::vector<double>& ln_factor);
  const std::vector<double>& match_periods() const;
  const StationSettings& settings() const { return stations_; }

 private:
  std::vector<GeneratedMotion> run(const SimqkeStart& s, std::uint64_t seed, std::uint64_t index);
  void factor_coherency();
  void coefficients(std::size_t j, const std::vector<std::vector<double>>& re,
                    const std::vector<std::vector<double>>& im,
                    const std::vector<std::vector<double>>& rho, std::vector<double>& zr,
                    std::vector<double>& zi) const;

  SimqkeGenerator gen_;
  StationSettings stations_;
  double accept_score_ = 0.0;
  bool coherent_ = true;       // every station is station 1
  std::vector<double> lower_;  // per bin k: the packed lower factor, rows j, m <= j
};

/// Philox streams of station `station` (0-based) in phase set `attempt`: its phases
/// (attempt + 65536 station; station 0 is SimqkeGenerator's) and its Rayleigh moduli (2^31 +
/// the phase stream).
std::uint32_t station_phase_stream(int station, int attempt);
std::uint32_t station_modulus_stream(int station, int attempt);
void rayleigh_moduli(std::uint64_t seed, std::uint64_t index, int attempt, int station,
                     const std::vector<double>& amplitude, std::vector<double>& rho);

}  // namespace pound

#pragma once
// What a generated set of station motions achieves (issue 28, docs/ground.md): for every pair
// of stations (j, k), j < k, the lag and the lagged coherency estimated over the set.
//
//  * Ensemble cross-spectrum C_jk(f) = sum_i X_ik(f) X_ij(f)^* over the set's motions i (X the
//    FFT of a record zero-padded to at least twice the longest record, so that the circular
//    correlation does not wrap).
//  * Lag: the peak of the ensemble cross-correlation r_jk(t) = IFFT(C_jk) (positive: station k
//    moves later), refined by the parabola through the peak sample and its neighbours.
//  * Lagged coherency at f: C_jk(f_b) exp(+i 2 pi f_b lag) (the lag removed) summed over the
//    bins f_b within f +- half_band, |sum| / sqrt(sum C_jj sum C_kk).
// No files, no printing.
#include <vector>

#include "ground/coherency.hpp"
#include "motion/ground_motion.hpp"

namespace pound {

struct PairCoherency {
  int j = 0, k = 0;                     ///< stations, 0-based, j < k
  double separation = 0.0;              ///< |x_k - x_j| [m]
  double model_lag = 0.0;               ///< delay_k - delay_j [s]
  double lag = 0.0;                     ///< achieved lag [s]
  std::vector<double> model, achieved;  ///< |gamma| at the frequencies [-]
};

struct AchievedCoherency {
  std::vector<double> frequencies;  ///< [Hz]
  double half_band = 0.0;           ///< [Hz]
  std::vector<PairCoherency> pairs;
};

/// motions[i][j]: motion i at station j (one dt; records of any length, zero-padded to the
/// longest); positions [m] and delays [s] of the stations, the model for the comparison.
AchievedCoherency achieved_coherency(const std::vector<std::vector<GroundMotion>>& motions,
                                     const std::vector<double>& positions,
                                     const std::vector<double>& delays, const Coherency& model,
                                     const std::vector<double>& frequencies, double half_band);

/// The ensemble relative-displacement energy of stations j and k of a set without wave passage
/// between them (zero lag), over the bins f_min <= f_b <= f_max [Hz] (f_min > 0): achieved,
/// sum_i sum_b |D_ik(f_b) - D_ij(f_b)|^2, and the model's expectation for the set's own
/// spectra, sum_b [C_jj + C_kk - 2 |gamma(separation, f_b)| sqrt(C_jj C_kk)], D = X / (2 pi
/// f)^2 the Fourier transform of the displacement (X of the acceleration, zero-padded as in
/// achieved_coherency) and C_jj = sum_i |D_ij|^2 [m^2 s^2 x samples^2; compare the two].
struct RelativeEnergy {
  double achieved = 0.0, model = 0.0;
};
RelativeEnergy relative_displacement_energy(const std::vector<std::vector<GroundMotion>>& motions,
                                            int j, int k, double separation, const Coherency& model,
                                            double f_min, double f_max);

}  // namespace pound

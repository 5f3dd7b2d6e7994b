#pragma once
// Wave passage along a row of buildings (issue 28, docs/ground.md): the same ground motion
// reaches station j later by its distance along the row over the apparent velocity v [m/s]
// (physics.md 5a; typically 200-2000 m/s at building scale). The coherency matrix's phase
// exp(-i omega (x_k - x_j) / v) factors as D L with D = diag(exp(-i omega delay_j)), so wave
// passage is a pure delay of each station's motion, applied after the spectrum matching.
#include <vector>

#include "motion/ground_motion.hpp"

namespace pound {

/// Arrival delays [s] of stations at `positions` [m] (strictly increasing) for apparent velocity
/// v [m/s]: v infinite: all 0; v > 0: the wave travels from station 1 towards the last,
/// delay_j = (x_j - x_1) / v; v < 0: from the last towards station 1, delay_j = (x_last - x_j) /
/// |v|. (v = 0 or NaN: std::invalid_argument; the study reader validates before.)
std::vector<double> arrival_delays(const std::vector<double>& positions, double v);

/// `m` delayed by `delay` >= 0 [s] on its own sample grid: a whole number of samples by leading
/// zeros (exact, no arithmetic on the values), the remaining fraction of a sample (when more
/// than 1e-9 of a sample) by a band-limited shift (FFTW r2c/c2r on the record zero-padded so
/// that nothing wraps around; the phase exp(-i omega tau); the Nyquist bin, if any, times
/// cos(omega tau)). The result is longer by ceil(delay / dt) samples (by round(delay / dt) when
/// delay / dt is within 1e-9 of a whole number), keeps dt and name (+ ", delayed by X s").
/// delay = 0 returns `m` unchanged, bit for bit. Negative or non-finite delay:
/// std::invalid_argument.
GroundMotion delayed(const GroundMotion& m, double delay);

}  // namespace pound

#include "ground/achieved_coherency.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

#include "motion/fftw_support.hpp"

namespace pound {
namespace {

using Complex = std::complex<double>;

// The peak of the circular correlation r (index t: lag t dt, t > n/2: lag (t - n) dt) within
// +- max_lag samples, refined by a parabola [s].
double peak_lag(const std::vector<double>& r, double dt, std::size_t max_lag) {
  const std::size_t n = r.size();
  const auto at = [&](long t) { return r[std::size_t((t % long(n) + long(n)) % long(n))]; };
  long best = 0;
  for (long t = -long(max_lag); t <= long(max_lag); ++t)
    if (at(t) > at(best)) best = t;
  const double y0 = at(best - 1), y1 = at(best), y2 = at(best + 1);
  const double den = y0 - 2.0 * y1 + y2;
  const double shift = den < 0.0 ? 0.5 * (y0 - y2) / den : 0.0;
  return (double(best) + shift) * dt;
}

}  // namespace

AchievedCoherency achieved_coherency(const std::vector<std::vector<GroundMotion>>& motions,
                                     const std::vector<double>& positions,
                                     const std::vector<double>& delays, const Coherency& model,
                                     const std::vector<double>& frequencies, double half_band) {
  AchievedCoherency out;
  out.frequencies = frequencies;
  out.half_band = half_band;
  const std::size_t s = positions.size();
  if (motions.empty() || s < 2) return out;
  const double dt = motions.front().front().dt;
  std::size_t n = 0;
  for (const auto& row : motions)
    for (const GroundMotion& m : row) n = std::max(n, m.accel.size());
  RealFft fft(good_fft_size(2 * n));
  const std::size_t nb = fft.bins();
  // Ensemble cross-spectra C_jk = sum_i X_k X_j^*, j <= k, packed by pair.
  const auto pair = [&](std::size_t j, std::size_t k) { return k * (k + 1) / 2 + j; };
  std::vector<std::vector<Complex>> c(s * (s + 1) / 2, std::vector<Complex>(nb));
  std::vector<std::vector<Complex>> x(s);
  for (const auto& row : motions) {
    for (std::size_t j = 0; j < s; ++j) fft.forward(row[j].accel, x[j]);
    for (std::size_t k = 0; k < s; ++k)
      for (std::size_t j = 0; j <= k; ++j)
        for (std::size_t b = 0; b < nb; ++b) c[pair(j, k)][b] += x[k][b] * std::conj(x[j][b]);
  }
  const double df = 1.0 / (double(2 * (nb - 1)) * dt);
  for (std::size_t k = 1; k < s; ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      PairCoherency p;
      p.j = int(j);
      p.k = int(k);
      p.separation = std::fabs(positions[k] - positions[j]);
      p.model_lag = delays[k] - delays[j];
      const std::vector<Complex>& cjk = c[pair(j, k)];
      p.lag = peak_lag(fft.inverse(cjk), dt, n - 1);
      for (double f : frequencies) {
        Complex sum = 0.0;
        double sjj = 0.0, skk = 0.0;
        for (std::size_t b = 0; b < nb; ++b) {
          const double fb = df * double(b);
          if (std::fabs(fb - f) > half_band) continue;
          sum += cjk[b] * std::polar(1.0, 2.0 * M_PI * fb * p.lag);
          sjj += c[pair(j, j)][b].real();
          skk += c[pair(k, k)][b].real();
        }
        p.model.push_back(model(p.separation, f));
        p.achieved.push_back(sjj > 0.0 && skk > 0.0 ? std::abs(sum) / std::sqrt(sjj * skk) : 0.0);
      }
      out.pairs.push_back(std::move(p));
    }
  }
  return out;
}

RelativeEnergy relative_displacement_energy(const std::vector<std::vector<GroundMotion>>& motions,
                                            int j, int k, double separation, const Coherency& model,
                                            double f_min, double f_max) {
  RelativeEnergy out;
  if (motions.empty()) return out;
  const double dt = motions.front().front().dt;
  std::size_t n = 0;
  for (const auto& row : motions)
    n = std::max({n, row[std::size_t(j)].accel.size(), row[std::size_t(k)].accel.size()});
  RealFft fft(good_fft_size(2 * n));
  const std::size_t nb = fft.bins();
  const double df = 1.0 / (double(2 * (nb - 1)) * dt);
  std::vector<double> cjj(nb, 0.0), ckk(nb, 0.0);
  std::vector<Complex> xj, xk;
  for (const auto& row : motions) {
    fft.forward(row[std::size_t(j)].accel, xj);
    fft.forward(row[std::size_t(k)].accel, xk);
    for (std::size_t b = 1; b < nb; ++b) {
      const double f = df * double(b);
      if (f < f_min || f > f_max) continue;
      const double w2 = std::pow(2.0 * M_PI * f, 2);
      const Complex dj = xj[b] / w2, dk = xk[b] / w2;
      cjj[b] += std::norm(dj);
      ckk[b] += std::norm(dk);
      out.achieved += std::norm(dk - dj);
    }
  }
  for (std::size_t b = 1; b < nb; ++b) {
    const double f = df * double(b);
    if (f < f_min || f > f_max) continue;
    out.model += cjj[b] + ckk[b] - 2.0 * model(separation, f) * std::sqrt(cjj[b] * ckk[b]);
  }
  return out;
}

}  // namespace pound

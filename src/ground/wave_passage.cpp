#include "ground/wave_passage.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>

#include "motion/fftw_support.hpp"

namespace pound {
namespace {

// The record shifted later by `fraction` of a sample (0 < fraction < 1), band-limited:
// X(w) exp(-i w fraction dt) on a transform of at least 2 (n + 1) points, n + 1 samples kept
// (the shifted record ends between samples n - 1 and n).
std::vector<double> fractional_shift(const std::vector<double>& a, double fraction) {
  const std::size_t n = a.size(), out_n = n + 1;
  RealFft f(good_fft_size(2 * out_n));
  std::copy(a.begin(), a.end(), f.real);
  std::fill(f.real + n, f.real + f.n, 0.0);
  fftw_execute(f.r2c);
  const std::size_t bins = f.n / 2 + 1;
  for (std::size_t k = 0; k < bins; ++k) {
    // Phase of bin k: omega tau = 2 pi k fraction / nfft (tau = fraction dt, omega = 2 pi k /
    // (nfft dt)); the Nyquist bin of an even length stays real: times cos(omega tau).
    const double phi = 2.0 * M_PI * double(k) * fraction / double(f.n);
    const double c = std::cos(phi) / double(f.n), s = -std::sin(phi) / double(f.n);
    if (k == bins - 1 && f.n % 2 == 0) {
      f.spec[k][0] *= c;
      f.spec[k][1] = 0.0;
      continue;
    }
    const double re = f.spec[k][0], im = f.spec[k][1];
    f.spec[k][0] = re * c - im * s;
    f.spec[k][1] = re * s + im * c;
  }
  fftw_execute(f.c2r);
  return std::vector<double>(f.real, f.real + out_n);
}

}  // namespace

std::vector<double> arrival_delays(const std::vector<double>& positions, double v) {
  if (v == 0.0 || std::isnan(v))
    throw std::invalid_argument("arrival_delays: apparent velocity must be non-zero");
  std::vector<double> d(positions.size(), 0.0);
  if (std::isinf(v) || positions.empty()) return d;
  for (std::size_t j = 0; j < positions.size(); ++j)
    d[j] =
        v > 0.0 ? (positions[j] - positions.front()) / v : (positions.back() - positions[j]) / -v;
  return d;
}

GroundMotion delayed(const GroundMotion& m, double delay) {
  if (!(delay >= 0.0) || !std::isfinite(delay))
    throw std::invalid_argument("delayed: the delay must be finite and >= 0 s");
  if (delay == 0.0) return m;
  const double samples = delay / m.dt;
  const double whole_rounded = std::round(samples);
  std::size_t whole = 0;
  double fraction = 0.0;
  if (std::fabs(samples - whole_rounded) <= 1e-9) {
    whole = std::size_t(whole_rounded);
  } else {
    whole = std::size_t(std::floor(samples));
    fraction = samples - double(whole);
  }
  GroundMotion out;
  out.dt = m.dt;
  char note[64];
  std::snprintf(note, sizeof note, ", delayed by %.6g s", delay);
  out.name = m.name + note;
  out.accel.assign(whole, 0.0);
  if (fraction == 0.0 || m.accel.empty()) {
    out.accel.insert(out.accel.end(), m.accel.begin(), m.accel.end());
  } else {
    const std::vector<double> s = fractional_shift(m.accel, fraction);
    out.accel.insert(out.accel.end(), s.begin(), s.end());
  }
  return out;
}

}  // namespace pound

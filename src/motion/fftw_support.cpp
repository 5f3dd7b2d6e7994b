#include "motion/fftw_support.hpp"

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>

namespace pound {

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

std::size_t good_fft_size(std::size_t n) {
  for (std::size_t m = std::max<std::size_t>(n, 2);; ++m) {
    if (m % 2) continue;
    std::size_t r = m;
    for (std::size_t p : {2u, 3u, 5u})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

RealFft::RealFft(std::size_t length) : n(length) {
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  real = fftw_alloc_real(n);
  spec = fftw_alloc_complex(n / 2 + 1);
  if (!real || !spec) {
    if (real) fftw_free(real);
    if (spec) fftw_free(spec);
    throw std::bad_alloc();
  }
  r2c = fftw_plan_dft_r2c_1d(int(n), real, spec, FFTW_ESTIMATE);
  c2r = fftw_plan_dft_c2r_1d(int(n), spec, real, FFTW_ESTIMATE);
  if (!r2c || !c2r) {
    if (r2c) fftw_destroy_plan(r2c);
    if (c2r) fftw_destroy_plan(c2r);
    fftw_free(real);
    fftw_free(spec);
    throw std::runtime_error("no FFTW plan of length " + std::to_string(n));
  }
}

RealFft::~RealFft() {
  std::lock_guard<std::mutex> lock(fftw_planner_mutex());
  fftw_destroy_plan(r2c);
  fftw_destroy_plan(c2r);
  fftw_free(real);
  fftw_free(spec);
}

void RealFft::forward(const std::vector<double>& a, std::vector<std::complex<double>>& x) {
  std::fill(real, real + n, 0.0);
  std::copy(a.begin(), a.begin() + long(std::min(a.size(), n)), real);
  fftw_execute(r2c);
  x.resize(bins());
  for (std::size_t b = 0; b < bins(); ++b) x[b] = std::complex<double>(spec[b][0], spec[b][1]);
}

std::vector<double> RealFft::inverse(const std::vector<std::complex<double>>& c) {
  for (std::size_t b = 0; b < bins(); ++b) {
    spec[b][0] = c[b].real();
    spec[b][1] = c[b].imag();
  }
  fftw_execute(c2r);
  return std::vector<double>(real, real + n);
}

}  // namespace pound

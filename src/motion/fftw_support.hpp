#pragma once
// What every FFTW user of the engine shares: the planner lock (FFTW's planner is not
// thread-safe, so plans are made and destroyed under one process-wide mutex), the choice of
// fast transform sizes, and a real transform pair of one size with its buffers.
#include <fftw3.h>

#include <complex>
#include <cstddef>
#include <mutex>
#include <vector>

namespace pound {

/// The lock held while an FFTW plan is made or destroyed (by SimqkeGenerator, delayed(), ...).
std::mutex& fftw_planner_mutex();

/// Smallest size >= n of the form 2^a 3^b 5^c that is even (a fast FFTW size) [-].
std::size_t good_fft_size(std::size_t n);

/// The forward (r2c) and backward (c2r, unnormalised) transforms of length n with their
/// buffers, planned (FFTW_ESTIMATE) and destroyed under fftw_planner_mutex(). The buffers are
/// public for in-place work on the half-spectrum: `real` n values, `spec` n / 2 + 1 bins.
struct RealFft {
  explicit RealFft(std::size_t length);
  ~RealFft();
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;
  std::size_t bins() const { return n / 2 + 1; }
  /// The half-spectrum of `a` zero-padded (or cut) to n.
  void forward(const std::vector<double>& a, std::vector<std::complex<double>>& x);
  /// The real sequence (n values, unnormalised) of the Hermitian half-spectrum c.
  std::vector<double> inverse(const std::vector<std::complex<double>>& c);

  std::size_t n = 0;
  double* real = nullptr;
  fftw_complex* spec = nullptr;
  fftw_plan r2c = nullptr, c2r = nullptr;
};

}  // namespace pound

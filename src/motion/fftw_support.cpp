#include "motion/fftw_support.hpp"

#include <algorithm>

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

}  // namespace pound

#pragma once
// What every FFTW user of the engine shares: the planner lock (FFTW's planner is not
// thread-safe, so plans are made and destroyed under one process-wide mutex) and the choice of
// fast transform sizes.
#include <cstddef>
#include <mutex>

namespace pound {

/// The lock held while an FFTW plan is made or destroyed (by SimqkeGenerator, delayed(), ...).
std::mutex& fftw_planner_mutex();

/// Smallest size >= n of the form 2^a 3^b 5^c that is even (a fast FFTW size) [-].
std::size_t good_fft_size(std::size_t n);

}  // namespace pound

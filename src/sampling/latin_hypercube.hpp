#pragma once
// Latin hypercube sampling (McKay, Beckman & Conover 1979) that every rank can evaluate for
// any sample alone: for dimension d the N samples take the strata of a random permutation
// pi_d of 0..N-1 (Fisher-Yates driven by the counter-based generator of stream d), and
// sample i gets u = (pi_d(i) + v) / N with v uniform in (0, 1).
#include <cstdint>
#include <vector>

#include "sampling/counter_rng.hpp"

namespace pound {

class LatinHypercube {
 public:
  /// n samples; the permutation of each stream is built on first use and cached.
  LatinHypercube(std::uint64_t seed, std::uint64_t n) : seed_(seed), n_(n) {}
  /// The stratified uniform of sample i (0 <= i < n) in stream s.
  double uniform(std::uint64_t stream, std::uint64_t i);

 private:
  const std::vector<std::uint32_t>& permutation(std::uint64_t stream);
  std::uint64_t seed_, n_;
  std::vector<std::pair<std::uint64_t, std::vector<std::uint32_t>>> cache_;
};

}  // namespace pound

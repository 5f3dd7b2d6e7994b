#pragma once
// Latin hypercube sampling (McKay, Beckman & Conover 1979) that every rank can evaluate for
// any sample alone: for dimension d the N samples take the strata of a keyed pseudo-random
// permutation pi_d of 0..N-1 (sampling/keyed_permutation.hpp, keyed by the study seed and the
// dimension's stream), and sample i gets u = (pi_d(i) + v) / N with v uniform in (0, 1). The
// permutation is computed on demand, so memory does not depend on N (issue 13).
#include <cstdint>
#include <utility>
#include <vector>

#include "sampling/counter_rng.hpp"
#include "sampling/keyed_permutation.hpp"

namespace pound {

class LatinHypercube {
 public:
  /// n samples (n >= 1).
  LatinHypercube(std::uint64_t seed, std::uint64_t n) : seed_(seed), n_(n) {}
  /// The stratified uniform of sample i (0 <= i < n) in stream s.
  double uniform(std::uint64_t stream, std::uint64_t i);
  /// The stratum of sample i in stream s, pi_s(i) in [0, n).
  std::uint64_t stratum(std::uint64_t stream, std::uint64_t i) { return permutation(stream)(i); }

 private:
  const KeyedPermutation& permutation(std::uint64_t stream);
  std::uint64_t seed_, n_;
  std::vector<std::pair<std::uint64_t, KeyedPermutation>> cache_;  // one per stream used
};

}  // namespace pound

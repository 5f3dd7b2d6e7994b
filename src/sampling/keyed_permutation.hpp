#pragma once
// A keyed pseudo-random permutation of [0, n), evaluated on demand in O(1) memory: a balanced
// Feistel network on the 2w bits with 2^(2w) >= n (Luby & Rackoff 1988: four rounds of a
// pseudo-random function give a pseudo-random permutation; six are used), its round function
// the counter-based generator (Philox4x64-10, sampling/counter_rng.hpp) keyed by the study seed
// and a stream, and cycle walking onto [0, n) (Black & Rogaway 2002, "Ciphers with arbitrary
// finite domains": re-encrypt until the value falls below n; since 2^(2w) < 4 n, at most four
// walks are expected). It replaces a stored permutation of all n indices (Fisher-Yates), whose
// memory grows with the sample count (issue 13).
#include <cstdint>

#include "sampling/counter_rng.hpp"

namespace pound {

class KeyedPermutation {
 public:
  /// The permutation of [0, n) keyed by (seed, stream); n >= 1.
  KeyedPermutation(std::uint64_t seed, std::uint64_t stream, std::uint64_t n);
  /// pi(i) for 0 <= i < n; std::out_of_range otherwise.
  std::uint64_t operator()(std::uint64_t i) const;
  std::uint64_t size() const { return n_; }

 private:
  std::uint64_t encrypt(std::uint64_t x) const;
  static constexpr int kRounds = 6;
  CounterRng rng_;
  std::uint64_t n_;
  int w_ = 0;               // bits per half
  std::uint64_t mask_ = 0;  // 2^w - 1
};

}  // namespace pound

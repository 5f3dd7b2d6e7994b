#include "sampling/keyed_permutation.hpp"

#include <stdexcept>
#include <string>

namespace pound {

KeyedPermutation::KeyedPermutation(std::uint64_t seed, std::uint64_t stream, std::uint64_t n)
    : rng_(seed, stream), n_(n) {
  if (n == 0) throw std::invalid_argument("KeyedPermutation: empty domain");
  // The smallest b with 2^b >= n, split into two halves of w = ceil(b / 2) bits.
  int b = 0;
  while (b < 64 && (std::uint64_t{1} << b) < n) ++b;
  w_ = (b + 1) / 2;
  if (w_ == 0) w_ = 1;  // n = 1: a two-bit domain, walked back to 0
  if (w_ > 31) throw std::invalid_argument("KeyedPermutation: domain above 2^62");
  mask_ = (std::uint64_t{1} << w_) - 1;
}

// One pass of the Feistel network: (L, R) -> (R, L xor F_r(R)) for r = 0..kRounds-1, with
// F_r(R) the low w bits of Philox at counter (R, r). A bijection of [0, 2^(2w)) for any F.
std::uint64_t KeyedPermutation::encrypt(std::uint64_t x) const {
  std::uint64_t left = x >> w_, right = x & mask_;
  for (int r = 0; r < kRounds; ++r) {
    const std::uint64_t f = rng_.bits(right, static_cast<std::uint64_t>(r)) & mask_;
    const std::uint64_t next = left ^ f;
    left = right;
    right = next;
  }
  return (left << w_) | right;
}

std::uint64_t KeyedPermutation::operator()(std::uint64_t i) const {
  // Outside [0, n) the walk need not come back below n (it would not return).
  if (i >= n_)
    throw std::out_of_range("KeyedPermutation: index " + std::to_string(i) + " outside [0, " +
                            std::to_string(n_) + ")");
  // Cycle walking: the orbit of i under the bijection on [0, 2^(2w)) returns to [0, n), and
  // walking from distinct i < n gives distinct results (Black & Rogaway 2002, sec. 5).
  std::uint64_t x = encrypt(i);
  while (x >= n_) x = encrypt(x);
  return x;
}

}  // namespace pound

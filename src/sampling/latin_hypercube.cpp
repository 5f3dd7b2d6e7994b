#include "sampling/latin_hypercube.hpp"

namespace pound {

const KeyedPermutation& LatinHypercube::permutation(std::uint64_t stream) {
  for (const auto& c : cache_)
    if (c.first == stream) return c.second;
  // The permutation's own stream (stream ^ a constant), apart from the within-stratum draws.
  cache_.emplace_back(stream, KeyedPermutation(seed_, stream ^ 0x9e3779b97f4a7c15ull, n_));
  return cache_.back().second;
}

double LatinHypercube::uniform(std::uint64_t stream, std::uint64_t i) {
  const KeyedPermutation& p = permutation(stream);
  const CounterRng rng(seed_, stream);
  return (static_cast<double>(p(i)) + rng.uniform(i)) / static_cast<double>(n_);
}

}  // namespace pound

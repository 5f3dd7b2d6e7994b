#include "sampling/latin_hypercube.hpp"

#include <numeric>
#include <utility>

namespace pound {

const std::vector<std::uint32_t>& LatinHypercube::permutation(std::uint64_t stream) {
  for (const auto& c : cache_)
    if (c.first == stream) return c.second;
  std::vector<std::uint32_t> p(n_);
  std::iota(p.begin(), p.end(), 0u);
  // Fisher-Yates with the permutation's own stream (stream ^ a constant, draw j).
  const CounterRng rng(seed_, stream ^ 0x9e3779b97f4a7c15ull);
  for (std::uint64_t j = n_; j > 1; --j) {
    const std::uint64_t k = static_cast<std::uint64_t>(rng.uniform(j) * static_cast<double>(j));
    std::swap(p[j - 1], p[k < j ? k : j - 1]);
  }
  cache_.emplace_back(stream, std::move(p));
  return cache_.back().second;
}

double LatinHypercube::uniform(std::uint64_t stream, std::uint64_t i) {
  const auto& p = permutation(stream);
  const CounterRng rng(seed_, stream);
  return (static_cast<double>(p[i]) + rng.uniform(i)) / static_cast<double>(n_);
}

}  // namespace pound

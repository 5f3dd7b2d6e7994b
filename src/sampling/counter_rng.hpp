#pragma once
// Counter-based random numbers (Salmon et al. 2011, Philox4x64-10 from Random123): every draw
// is a pure function of (study seed, stream, sample id, draw index), so a Monte Carlo sample
// gets the same numbers on 1 or 64 ranks and in any order of completion. Streams separate the
// uses (one per sampled parameter, one for the ground motion), so adding a parameter to a
// study does not change the draws of the others.
#include <cstdint>
#include <string>

namespace pound {

/// 64-bit FNV-1a hash of a name, used to derive a stream id from a parameter key.
std::uint64_t stream_id(const std::string& name);

class CounterRng {
 public:
  CounterRng(std::uint64_t seed, std::uint64_t stream) : seed_(seed), stream_(stream) {}
  /// 64 random bits for (index, draw).
  std::uint64_t bits(std::uint64_t index, std::uint64_t draw = 0) const;
  /// Uniform in the open interval (0, 1): (top 53 bits + 0.5) * 2^-53.
  double uniform(std::uint64_t index, std::uint64_t draw = 0) const;

 private:
  std::uint64_t seed_, stream_;
};

}  // namespace pound

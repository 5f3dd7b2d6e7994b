#include "sampling/counter_rng.hpp"

#include <Random123/philox.h>

namespace pound {

std::uint64_t stream_id(const std::string& name) {
  std::uint64_t h = 14695981039346656037ull;  // FNV-1a offset basis
  for (unsigned char c : name) {
    h ^= c;
    h *= 1099511628211ull;  // FNV prime
  }
  return h;
}

std::uint64_t CounterRng::bits(std::uint64_t index, std::uint64_t draw) const {
  r123::Philox4x64 rng;
  r123::Philox4x64::ctr_type ctr = {{index, draw, 0, 0}};
  r123::Philox4x64::key_type key = {{seed_, stream_}};
  return rng(ctr, key)[0];
}

double CounterRng::uniform(std::uint64_t index, std::uint64_t draw) const {
  return (static_cast<double>(bits(index, draw) >> 11) + 0.5) * 0x1.0p-53;
}

}  // namespace pound

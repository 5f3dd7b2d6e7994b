#pragma once
// The rule of a pounding run that stops at the row's first collapse (docs/fragility.md,
// "Collapse"), on one sample's flags /response/collapsed_pounding[s, 0..buildings): 1 the
// building collapsed, 0 it stood, NaN the sample failed.
#include <cstddef>

namespace pound {

/// Whether building b's pounding run was stopped by another building's collapse while b stood:
/// b's response after the stop is unknown, so its pounding peaks cover only part of the record
/// (right-censored). False for a building that collapsed itself and where none collapsed.
inline bool stopped_by_another(const double* collapsed_pounding, std::size_t buildings,
                               std::size_t b) {
  if (collapsed_pounding[b] == 1.0) return false;
  for (std::size_t o = 0; o < buildings; ++o)
    if (o != b && collapsed_pounding[o] == 1.0) return true;
  return false;
}

}  // namespace pound

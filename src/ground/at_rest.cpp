#include "ground/at_rest.hpp"

#include <cstddef>

#include "motion/motion_processing.hpp"

namespace pound {

GroundMotion ending_at_rest(const GroundMotion& m) {
  // The first sample the motion moves at; the rest it starts from is the sample before (a
  // leading zero, or the trace's rest at -dt: a zero put in front).
  std::size_t k = 0;
  while (k < m.accel.size() && m.accel[k] == 0.0) ++k;
  if (k == m.accel.size()) return m;  // no motion
  const bool prepend = k == 0;
  GroundMotion part;
  part.name = m.name;
  part.dt = m.dt;
  part.accel.reserve(m.accel.size() - k + 2);
  if (prepend) part.accel.push_back(0.0);
  part.accel.insert(part.accel.end(), m.accel.begin() + static_cast<long>(prepend ? 0 : k - 1),
                    m.accel.end());
  // baseline_correct integrates from rest at the first sample (here 0), as the trace does.
  const GroundMotion fixed = baseline_correct(part);
  GroundMotion out = m;
  const std::size_t from = prepend ? 1 : 0, to = prepend ? 0 : k - 1;
  for (std::size_t i = from; i < fixed.accel.size(); ++i) out.accel[to + i - from] = fixed.accel[i];
  return out;
}

void end_at_rest_where_they_differ(std::vector<GroundMotion>& motions) {
  bool differ = false;
  for (std::size_t b = 1; b < motions.size() && !differ; ++b)
    differ = motions[b].dt != motions[0].dt || motions[b].accel != motions[0].accel;
  if (!differ) return;
  for (GroundMotion& m : motions) m = ending_at_rest(m);
}

}  // namespace pound

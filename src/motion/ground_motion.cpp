#include "motion/ground_motion.hpp"

#include <cmath>

namespace pound {

double GroundMotion::at(double t) const {
  if (accel.empty() || t < 0.0) return 0.0;
  const double s = t / dt;
  const auto i = static_cast<std::size_t>(s);
  if (i + 1 >= accel.size()) return i + 1 == accel.size() && s == double(i) ? accel[i] : 0.0;
  const double f = s - double(i);
  return accel[i] + f * (accel[i + 1] - accel[i]);
}

double GroundMotion::pga() const {
  double p = 0.0;
  for (double a : accel) p = std::fmax(p, std::fabs(a));
  return p;
}

}  // namespace pound

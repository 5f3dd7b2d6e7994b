#include "motion/ground_motion.hpp"

#include <cmath>

namespace pound {

double GroundMotion::pga() const {
  double p = 0.0;
  for (double a : accel) p = std::fmax(p, std::fabs(a));
  return p;
}

}  // namespace pound

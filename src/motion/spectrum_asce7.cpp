#include "motion/spectrum_asce7.hpp"

#include <sstream>

#include "core/error.hpp"
#include "motion/ground_motion.hpp"

namespace pound {

Asce7Spectrum::Asce7Spectrum(double sds, double sd1, double tl) : sds_(sds), sd1_(sd1), tl_(tl) {
  if (!(sds > 0.0 && sd1 > 0.0 && tl > 0.0))
    throw InputError("ASCE 7 spectrum: SDS, SD1 and TL must be > 0");
  if (!(tl > sd1 / sds)) throw InputError("ASCE 7 spectrum: TL must exceed TS = SD1/SDS");
}

double Asce7Spectrum::sa(double T) const {
  // ASCE/SEI 7-16 clause 11.4.6.
  if (T < t0()) return sds_ * (0.4 + 0.6 * T / t0());  // eq. (11.4-5)
  if (T <= ts()) return sds_;                          // plateau
  if (T <= tl_) return sd1_ / T;                       // eq. (11.4-6)
  return sd1_ * tl_ / (T * T);                         // eq. (11.4-7)
}

std::string Asce7Spectrum::describe() const {
  std::ostringstream s;
  s << "ASCE 7 design spectrum, SDS = " << sds_ / kGravity << " g, SD1 = " << sd1_ / kGravity
    << " g, TL = " << tl_ << " s (T0 = " << t0() << " s, TS = " << ts()
    << " s), 5 % damping; ASCE/SEI 7-16 11.4.6";
  return s.str();
}

}  // namespace pound

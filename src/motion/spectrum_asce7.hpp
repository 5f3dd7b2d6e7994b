#pragma once
// ASCE/SEI 7-16 design response spectrum, clause 11.4.6 (two parameters SDS, SD1 and the
// long-period transition TL), 5 % damping.
#include "motion/design_spectrum.hpp"

namespace pound {

class Asce7Spectrum : public DesignSpectrum {
 public:
  /// sds, sd1: design spectral accelerations at short periods and at 1 s [m/s^2];
  /// tl: long-period transition period [s].
  Asce7Spectrum(double sds, double sd1, double tl);
  double sa(double period) const override;
  double damping() const override { return 0.05; }
  std::string describe() const override;
  double t0() const { return 0.2 * sd1_ / sds_; }  ///< T0 = 0.2 SD1/SDS [s]
  double ts() const { return sd1_ / sds_; }        ///< TS = SD1/SDS [s]

 private:
  double sds_, sd1_, tl_;
};

}  // namespace pound

#pragma once
// NZS 1170.5:2004 elastic site hazard spectrum, clause 3.1.1:
//   C(T) = Ch(T) Z R N(T, D)        [g], eq. 3.1(1)
// with the spectral shape factor Ch(T) of clause 3.1.2 / Table 3.1 in its form for modal
// response spectrum and numerical integration time-history analysis (the bracketed values:
// Ch rises linearly from Ch(0) to the plateau over 0 < T < 0.1 s). 5 % damping.
#include "motion/design_spectrum.hpp"

namespace pound {

enum class NzsSiteClass { A, B, C, D, E };  ///< site subsoil classes of clause 3.1.3

/// Spectral shape factor Ch(T) [-] (NZS 1170.5 Table 3.1, time-history form).
double nzs_spectral_shape(NzsSiteClass site, double period);

/// Return period factor R [-] for a return period in years (NZS 1170.5 Table 3.5: 20, 25,
/// 50, 100, 250, 500, 1000, 2000, 2500). Throws InputError for other values.
double nzs_return_period_factor(int years);

/// Near-fault factor N(T, D) [-] (clause 3.1.6): Nmax(T) of Table 3.7 for D <= 2 km,
/// 1 + (Nmax(T) - 1)(20 - D)/18 for 2 < D <= 20 km, 1 beyond. D in km.
double nzs_near_fault_factor(double period, double distance_km);

class Nzs1170Spectrum : public DesignSpectrum {
 public:
  /// z: hazard factor Z [-] (Table 3.3); r: return period factor [-]; ZR <= 0.7 (cl. 3.1.1).
  /// n: a constant near-fault factor N [-] (>= 1), used when fault_distance_km < 0;
  /// otherwise N(T, D) from the distance to the nearest major fault [km].
  Nzs1170Spectrum(NzsSiteClass site, double z, double r, double n = 1.0,
                  double fault_distance_km = -1.0);
  double sa(double period) const override;
  double damping() const override { return 0.05; }
  std::string describe() const override;

 private:
  NzsSiteClass site_;
  double z_, r_, n_, distance_km_;
};

}  // namespace pound

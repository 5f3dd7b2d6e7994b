#pragma once
// Eurocode 8 horizontal elastic response spectrum, EN 1998-1:2004 clause 3.2.2.2.
#include "motion/design_spectrum.hpp"

namespace pound {

enum class Ec8Type { type1, type2 };     ///< Type 1 (Ms > 5.5) or Type 2 (Ms <= 5.5)
enum class Ec8Ground { A, B, C, D, E };  ///< ground types of EN 1998-1 Table 3.1

/// Soil factor S [-] and corner periods TB, TC, TD [s] (EN 1998-1 Tables 3.2 and 3.3).
struct Ec8Parameters {
  double S, TB, TC, TD;
};
Ec8Parameters ec8_parameters(Ec8Type type, Ec8Ground ground);

/// Damping correction eta = sqrt(10 / (5 + xi)) >= 0.55, xi in percent (EN 1998-1 eq. 3.6).
double ec8_eta(double damping);

class Ec8Spectrum : public DesignSpectrum {
 public:
  /// ag: design ground acceleration on type A ground [m/s^2] (ag = gamma_I agR);
  /// damping: viscous damping ratio [-], e.g. 0.05.
  Ec8Spectrum(Ec8Type type, Ec8Ground ground, double ag, double damping = 0.05);
  double sa(double period) const override;
  double damping() const override { return damping_; }
  std::string describe() const override;
  const Ec8Parameters& parameters() const { return p_; }

 private:
  Ec8Type type_;
  Ec8Ground ground_;
  double ag_, damping_, eta_;
  Ec8Parameters p_;
};

}  // namespace pound

#pragma once
// Intensity envelopes I(t) (peak 1) that turn a stationary signal into an earthquake-like
// non-stationary one.
//
//  * Trapezoidal-exponential after Jennings, Housner & Tsai (1968), "Simulated earthquake
//    motions", EERL Caltech:  I = (t / t1)^2 for t < t1;  1 for t1 <= t <= t2;
//    exp(-c (t - t2)) for t > t2.
//  * Saragoni & Hart (1974), "Simulation of artificial earthquakes", EESD 2:249-267, in the
//    parametrisation of Boore (2003, PAGEOPH 160:635-676, eq. 20):
//      I = a (t / tw)^b exp(-c t / tw),  b = -eps ln(eta) / (1 + eps (ln(eps) - 1)),
//      c = b / eps,  a = (e / eps)^b,
//    which peaks (I = 1) at t = eps tw and has fallen to eta at t = tw.
#include <string>

namespace pound {

enum class EnvelopeShape { jennings, saragoni_hart };

struct EnvelopeSettings {
  EnvelopeShape shape = EnvelopeShape::jennings;
  double rise = -1.0;        ///< Jennings t1: end of the quadratic rise [s]; < 0: 0.1 tw
  double strong_end = -1.0;  ///< Jennings t2: end of the strong phase [s]; < 0: 0.5 tw
  double decay = 0.0;        ///< Jennings c [1/s]; 0 = chosen so that I = 0.05 at the end
  double epsilon = 0.2;      ///< Saragoni-Hart: time of the peak as a fraction of tw [-]
  double eta = 0.05;         ///< Saragoni-Hart: I at t = tw [-]
};

class Envelope {
 public:
  /// duration: tw, the length of the motion [s]. Throws InputError on invalid settings.
  Envelope(const EnvelopeSettings& settings, double duration);
  /// I(t) [-], 0 <= I <= 1.
  double operator()(double t) const;
  /// Duration of the strong phase [s] (t2 - t1, or the time I exceeds about 0.5 for
  /// Saragoni-Hart), used by the generator's first guess of the power spectral density.
  double strong_duration() const { return strong_; }
  std::string describe() const;

 private:
  EnvelopeSettings s_;  // with the automatic times resolved
  double duration_, decay_ = 0.0, b_ = 0.0, c_ = 0.0, a_ = 0.0, strong_ = 0.0;
};

}  // namespace pound

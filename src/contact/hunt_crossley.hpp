#pragma once
// Exact Hunt-Crossley contact (Hunt & Crossley 1975; exact damping factor after Khatiwada,
// Chouw & Butterworth 2014, Th. 4.20):
//   F = k delta^n (1 + a ddelta / v0),  n = 1 (hc-linear) or 1.5 (hc-hertz),
//   (1 + e) a = ln((1 + a) / (1 - e a)),  0 < a < 1/e.
// a(e) is exact for any n, k, masses and v0: a free two-mass impact returns the nominal e to
// solver precision. In a building the rate can fall below -v0/a; the force is clamped at 0
// (no adhesion).
// Uses: k [N/m] (n = 1) or [N/m^1.5] (n = 1.5), e, v0_min.
#include "contact/contact_law.hpp"

namespace pound {

class HuntCrossley : public ContactLaw {
 public:
  HuntCrossley(const ContactParameters& p, double exponent);
  double force(double delta, double ddelta, double v0) const override;

 private:
  double k_;       // [N/m^n]
  double n_;       // force exponent [-]
  double a_;       // exact damping factor a(e) [-]
  double v0_min_;  // [m/s]
};

}  // namespace pound

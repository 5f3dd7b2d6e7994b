#include "motion/spectrum_nzs1170.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "motion/ground_motion.hpp"

namespace pound {

double nzs_spectral_shape(NzsSiteClass site, double T) {
  // NZS 1170.5:2004 Table 3.1 and the equations of its commentary C3.1.2; for T < 0.1 s the
  // linear rise from the bracketed Ch(0) used for time-history analysis.
  switch (site) {
    case NzsSiteClass::A:
    case NzsSiteClass::B:  // rock: one shape for classes A and B
      if (T < 0.1) return 1.0 + 1.35 * (T / 0.1);
      if (T <= 0.3) return 2.35;
      if (T <= 1.5) return 1.60 * std::pow(0.5 / T, 0.75);
      if (T <= 3.0) return 1.05 / T;
      return 3.15 / (T * T);
    case NzsSiteClass::C:  // shallow soil
      if (T < 0.1) return 1.33 + 1.60 * (T / 0.1);
      if (T <= 0.3) return 2.93;
      if (T <= 1.5) return 2.0 * std::pow(0.5 / T, 0.75);
      if (T <= 3.0) return 1.32 / T;
      return 3.96 / (T * T);
    case NzsSiteClass::D:  // deep or soft soil
      if (T < 0.1) return 1.12 + 1.88 * (T / 0.1);
      if (T <= 0.56) return 3.0;
      if (T <= 1.5) return 2.4 * std::pow(0.75 / T, 0.75);
      if (T <= 3.0) return 2.14 / T;
      return 6.42 / (T * T);
    case NzsSiteClass::E:  // very soft soil
      if (T < 0.1) return 1.12 + 1.88 * (T / 0.1);
      if (T <= 1.0) return 3.0;
      if (T <= 1.5) return 3.0 / std::pow(T, 0.75);
      if (T <= 3.0) return 3.32 / T;
      return 9.96 / (T * T);
  }
  return 0.0;
}
// Table 3.1 ends at 4.5 s; the 1/T^2 branch is continued beyond it.

double nzs_return_period_factor(int years) {
  // NZS 1170.5:2004 Table 3.5 (annual probability of exceedance 1/years).
  static const int rp[] = {20, 25, 50, 100, 250, 500, 1000, 2000, 2500};
  static const double r[] = {0.20, 0.25, 0.35, 0.5, 0.75, 1.0, 1.3, 1.7, 1.8};
  for (int i = 0; i < 9; ++i)
    if (rp[i] == years) return r[i];
  throw InputError("NZS 1170.5 return period " + std::to_string(years) +
                   " years; valid (Table 3.5): 20, 25, 50, 100, 250, 500, 1000, 2000, 2500");
}

double nzs_near_fault_factor(double T, double D) {
  // NZS 1170.5:2004 clause 3.1.6, Nmax(T) of Table 3.7, linear between the tabulated periods.
  static const double tt[] = {1.5, 2.0, 3.0, 4.0, 5.0};
  static const double nm[] = {1.0, 1.12, 1.36, 1.60, 1.72};
  double nmax = 1.0;
  if (T >= 5.0) {
    nmax = 1.72;
  } else if (T > 1.5) {
    int i = 0;
    while (T > tt[i + 1]) ++i;
    nmax = nm[i] + (nm[i + 1] - nm[i]) * (T - tt[i]) / (tt[i + 1] - tt[i]);
  }
  if (D <= 2.0) return nmax;
  if (D <= 20.0) return 1.0 + (nmax - 1.0) * (20.0 - D) / 18.0;
  return 1.0;
}

Nzs1170Spectrum::Nzs1170Spectrum(NzsSiteClass site, double z, double r, double n,
                                 double fault_distance_km)
    : site_(site), z_(z), r_(r), n_(n), distance_km_(fault_distance_km) {
  if (!(z > 0.0 && r > 0.0)) throw InputError("NZS 1170.5 spectrum: Z and R must be > 0");
  if (z * r > 0.7 + 1e-12)
    throw InputError("NZS 1170.5 spectrum: Z R = " + std::to_string(z * r) +
                     "; clause 3.1.1 limits Z R to 0.7");
  if (!(n >= 1.0)) throw InputError("NZS 1170.5 spectrum: N must be >= 1");
}

double Nzs1170Spectrum::sa(double T) const {
  // Eq. 3.1(1): C(T) = Ch(T) Z R N(T, D), in g.
  const double n = distance_km_ >= 0.0 ? nzs_near_fault_factor(T, distance_km_) : n_;
  return nzs_spectral_shape(site_, T) * z_ * r_ * n * kGravity;
}

std::string Nzs1170Spectrum::describe() const {
  std::ostringstream s;
  s << "NZS 1170.5 elastic site spectrum (time-history form), site class "
    << "ABCDE"[static_cast<int>(site_)] << ", Z = " << z_ << ", R = " << r_;
  if (distance_km_ >= 0.0)
    s << ", N(T, D) with D = " << distance_km_ << " km";
  else
    s << ", N = " << n_;
  s << ", 5 % damping; NZS 1170.5:2004 3.1.1, Table 3.1";
  return s.str();
}

}  // namespace pound

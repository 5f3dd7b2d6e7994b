#pragma once
// Correlation across periods of the residuals eps(T) = (ln Sa(T) - mu_ln Sa(T)) / sigma(T) of
// one ground motion: the model that makes a random target spectrum look like the spectrum of a
// recorded motion (spectral_variability.hpp).
//
// Baker, J. W. and Jayaram, N. (2008), "Correlation of spectral acceleration values from NGA
// ground motion models", Earthquake Spectra 24(1), 299-317, the predictive equations (fitted
// for 0.01 s <= T1, T2 <= 10 s), with Tmin = min(T1, T2), Tmax = max(T1, T2):
//
//   C1 = 1 - cos(pi/2 - 0.366 ln(Tmax / max(Tmin, 0.109)))
//   C2 = 1 - 0.105 (1 - 1 / (1 + exp(100 Tmax - 5))) (Tmax - Tmin) / (Tmax - 0.0099)
//        (used only where Tmax < 0.2 s)
//   C3 = C2 if Tmax < 0.109 s, else C1
//   C4 = C1 + 0.5 (sqrt(C3) - C3) (1 + cos(pi Tmin / 0.109))
//
//   rho = C2            if Tmax < 0.109 s
//         C1            else if Tmin > 0.109 s
//         min(C2, C4)   else if Tmax < 0.2 s
//         C4            otherwise.
//
// Checked against Baker's own MATLAB function (bj_2008_corr.m) and two independent ports
// (OpenQuake hazardlib, OpenSRA): the same formula, and the values rho(0.1, 0.5) =
// 0.4745240873, rho(0.15, 0.5) = 0.5734688765, rho(0.05, 0.15) = 0.9153049738, rho(0.05, 0.1)
// = 0.9421213925 that OpenQuake's tests take from Baker's MATLAB code (our test asserts them).
// Baker's MATLAB code takes the C2 branch for Tmax <= 0.109 s, the ports for Tmax < 0.109 s;
// the two differ only at Tmax = 0.109 s exactly, where we follow the ports.
#include <string>
#include <vector>

namespace pound {

enum class SpectralCorrelation {
  baker_jayaram_2008,  ///< the model above
  none,                ///< independent periods: rho = 0 for T1 != T2
  full,                ///< one eps for every period: rho = 1 (a pure scale when sigma is constant)
};

/// Baker & Jayaram (2008) rho(T1, T2) [-]; periods [s] are clamped to the fitted range
/// 0.01-10 s; rho(T, T) = 1.
double baker_jayaram_2008(double t1, double t2);

/// rho(T1, T2) of a model [-].
double spectral_correlation(SpectralCorrelation model, double t1, double t2);

/// "baker-jayaram-2008", "none", "full".
std::string to_string(SpectralCorrelation model);
/// The model named `name`; an unknown name is an InputError naming `where` and the valid names.
SpectralCorrelation parse_spectral_correlation(const std::string& name, const std::string& where);

}  // namespace pound

#pragma once
// sigma(T): the standard deviation of ln Sa(T) [-] around a target spectrum, for random target
// spectra (spectral_variability.hpp). Three kinds:
//
// - a constant (`sigma_lnsa = 0.6`);
// - a user table of (T [s], sigma [-]) lines (`sigma_table = FILE`);
// - the total sigma of a published ground-motion model (`sigma_model = NAME`):
//   `boore-atkinson-2008`: Boore, D. M. and Atkinson, G. M. (2008), "Ground-motion prediction
//   equations for the average horizontal component of PGA, PGV, and 5%-damped PSA at spectral
//   periods between 0.01 s and 10.0 s", Earthquake Spectra 24(1), 99-138, Table 8, column
//   sigma_TU: the total standard deviation sqrt(sigma^2 + tau_U^2) of ln PSA (GMRotI50, 5 %)
//   for an unspecified fault type (a design spectrum has no fault type). It does not depend on
//   magnitude or distance. Values transcribed from, and compared digit for digit with, three
//   independent public implementations: Baker's MATLAB ba_2008_active.m (array sigtu), the
//   Boore_08 model of Geoscience Australia's EQRM (Python) and a Java port (array s_tu); the
//   OpenQuake port lists the specified-fault column sigma_TM, which agrees with the same
//   files' sigma_TM. The test checks sigma_TU^2 = sigma^2 + tau_U^2 with Table 8's other two
//   columns.
//
// Tables (user or model) are interpolated linearly in ln T between their periods and held
// constant outside them (Baker's MATLAB interpolates BA08's sigma the same way).
#include <string>
#include <vector>

namespace pound {

class SigmaLnSa {
 public:
  /// A constant sigma >= 0 [-].
  static SigmaLnSa constant(double sigma);
  /// sigma at periods (> 0, strictly increasing) [s]; values >= 0 [-]; `name` for describe().
  static SigmaLnSa table(std::vector<double> periods, std::vector<double> sigmas, std::string name);
  /// Boore & Atkinson (2008) Table 8, sigma_TU (above).
  static SigmaLnSa boore_atkinson_2008();

  /// sigma(T) [-] at period T [s].
  double operator()(double period) const;
  /// One line: the kind, its values or source.
  const std::string& describe() const { return describe_; }

 private:
  std::vector<double> log_t_, sigma_;  // one entry: a constant
  std::string describe_;
};

/// Reads a table file: lines "T sigma" (s, -), '#' starts a comment line; periods > 0 and
/// increasing, sigma >= 0 and finite, at least one line. Errors name the file and line.
SigmaLnSa read_sigma_table(const std::string& path);

/// The ground-motion model named `name` ("boore-atkinson-2008"); an unknown name is an
/// InputError naming `where` and the valid names.
SigmaLnSa sigma_model(const std::string& name, const std::string& where);

}  // namespace pound

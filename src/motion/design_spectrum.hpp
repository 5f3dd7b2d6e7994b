#pragma once
// A design (target) acceleration response spectrum: the elastic spectral acceleration of a
// code or a user table as a function of period. Each code lives in its own file pair
// (spectrum_ec8, spectrum_nzs1170, spectrum_asce7, spectrum_japan, spectrum_table) and is
// built from options by make_design_spectrum (spectrum_factory.hpp).
#include <string>
#include <vector>

namespace pound {

class DesignSpectrum {
 public:
  virtual ~DesignSpectrum() = default;
  /// Spectral (pseudo-)acceleration [m/s^2] at period T >= 0 [s], at damping().
  virtual double sa(double period) const = 0;
  /// Viscous damping ratio the spectrum is for [-] (0.05 unless corrected).
  virtual double damping() const = 0;
  /// One line naming the code, its parameters and the clause.
  virtual std::string describe() const = 0;

  /// sa() at each period [m/s^2].
  std::vector<double> sample(const std::vector<double>& periods) const {
    std::vector<double> out;
    out.reserve(periods.size());
    for (double T : periods) out.push_back(sa(T));
    return out;
  }
};

}  // namespace pound

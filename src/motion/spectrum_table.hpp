#pragma once
// A user's design spectrum: (T, Sa) pairs interpolated linearly in log T and log Sa.
// Below the first period and above the last one the end values are held constant.
#include <string>
#include <vector>

#include "motion/design_spectrum.hpp"

namespace pound {

class TableSpectrum : public DesignSpectrum {
 public:
  /// periods [s], strictly increasing and > 0; sa [m/s^2] > 0; damping [-] it is for.
  TableSpectrum(std::vector<double> periods, std::vector<double> sa, double damping = 0.05,
                std::string name = "table");
  double sa(double period) const override;
  double damping() const override { return damping_; }
  std::string describe() const override;

 private:
  std::vector<double> log_t_, log_sa_;
  double t_first_, t_last_, damping_;
  std::string name_;
};

/// Reads a table file: '#' comment lines, then lines "T Sa" with T in s and Sa in g.
/// Errors name the file and line.
TableSpectrum read_spectrum_table(const std::string& path, double damping = 0.05);

}  // namespace pound

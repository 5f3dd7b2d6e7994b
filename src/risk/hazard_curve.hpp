#pragma once
// A site's seismic hazard curve: the mean annual rate lambda(x) at which the intensity measure
// exceeds x, given at points and interpolated linearly in log-log (ln lambda linear in ln x,
// a power law between neighbouring points). Beyond its first and last points the end segments'
// power laws are extended (log-log extrapolation), so lambda(x) is a positive, decreasing
// function on (0, inf) and the risk integrals (risk_integral.hpp) cover every intensity.
//
// File format (CSV; read_hazard_curve):
//   # comment lines: where the numbers come from
//   pga [g], annual_rate [1/yr]          header: measure and unit of each column
//   0.05, 2.1e-2                         intensity, annual rate of exceedance
//   ...
// The measure is `pga` or `sa(T)` (5 % damped spectral acceleration at period T in s), the unit
// `g` or `m/s2`; the rates must be > 0 and fall strictly as the intensity rises.
#include <string>
#include <vector>

namespace pound {

struct HazardCurve {
  std::string source;        ///< file it was read from
  std::string measure;       ///< "pga" or "sa"
  double period_s = 0.0;     ///< T of sa(T) [s]; 0 for PGA
  std::string file_unit;     ///< unit of the intensity column in the file ("g" or "m/s2")
  std::vector<double> im;    ///< intensities, strictly increasing [m/s^2]
  std::vector<double> rate;  ///< annual rates of exceedance, strictly decreasing [1/yr]

  /// lambda(x) [1/yr] for x > 0 [m/s^2], log-log interpolated and extrapolated.
  double rate_at(double x) const;
  /// The intensity whose rate of exceedance is `annual_rate` [m/s^2] (inverse of rate_at).
  double im_at_rate(double annual_rate) const;
  /// Segment k of ln lambda = y0 + b (ln x - x0), the line through its point (x0, y0) (so that
  /// it hits its points to round-off whatever its slope): k = 0 is the extension below the
  /// first point, k = 1..n-1 the interpolated segments, k = n the extension above the last
  /// point; the segment covers ln x in [lo, hi] (-inf / +inf at the ends).
  struct Segment {
    double b, lo, hi;
    double x0, y0;  ///< a point of the line, ln x and ln lambda there
    double ln_rate(double u) const { return y0 + b * (u - x0); }  ///< at u = ln x
  };
  std::vector<Segment> segments() const;
  /// How the curve is used beyond its points, for the reports.
  std::string extrapolation_rule() const;
};

/// Validates and converts points given in `unit` ("g" or "m/s2"); throws InputError naming
/// `source` and the offending point.
HazardCurve make_hazard_curve(std::vector<double> im, std::vector<double> rate,
                              const std::string& measure, double period_s, const std::string& unit,
                              const std::string& source);

/// Reads the CSV above. Throws InputError naming the file, the line and what is valid.
HazardCurve read_hazard_curve(const std::string& path);

}  // namespace pound

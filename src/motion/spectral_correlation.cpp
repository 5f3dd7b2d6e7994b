#include "motion/spectral_correlation.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace pound {

double baker_jayaram_2008(double t1, double t2) {
  t1 = std::clamp(t1, 0.01, 10.0);
  t2 = std::clamp(t2, 0.01, 10.0);
  if (t1 == t2) return 1.0;
  const double tmin = std::min(t1, t2), tmax = std::max(t1, t2);
  // Baker & Jayaram (2008), the predictive equations (spectral_correlation.hpp).
  const double c1 = 1.0 - std::cos(M_PI / 2.0 - 0.366 * std::log(tmax / std::max(tmin, 0.109)));
  const double c2 = tmax < 0.2 ? 1.0 - 0.105 * (1.0 - 1.0 / (1.0 + std::exp(100.0 * tmax - 5.0))) *
                                           (tmax - tmin) / (tmax - 0.0099)
                               : 0.0;
  const double c3 = tmax < 0.109 ? c2 : c1;
  const double c4 = c1 + 0.5 * (std::sqrt(c3) - c3) * (1.0 + std::cos(M_PI * tmin / 0.109));
  if (tmax < 0.109) return c2;
  if (tmin > 0.109) return c1;
  if (tmax < 0.2) return std::min(c2, c4);
  return c4;
}

double spectral_correlation(SpectralCorrelation model, double t1, double t2) {
  switch (model) {
    case SpectralCorrelation::baker_jayaram_2008:
      return baker_jayaram_2008(t1, t2);
    case SpectralCorrelation::none:
      return t1 == t2 ? 1.0 : 0.0;
    case SpectralCorrelation::full:
      return 1.0;
  }
  return 0.0;
}

std::string to_string(SpectralCorrelation model) {
  switch (model) {
    case SpectralCorrelation::baker_jayaram_2008:
      return "baker-jayaram-2008";
    case SpectralCorrelation::none:
      return "none";
    case SpectralCorrelation::full:
      return "full";
  }
  return "";
}

SpectralCorrelation parse_spectral_correlation(const std::string& name, const std::string& where) {
  for (auto m : {SpectralCorrelation::baker_jayaram_2008, SpectralCorrelation::none,
                 SpectralCorrelation::full})
    if (name == to_string(m)) return m;
  throw InputError(where + ": unknown correlation model '" + name +
                   "'; valid: baker-jayaram-2008, none, full");
}

}  // namespace pound

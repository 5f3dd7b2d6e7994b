#include "motion/spectrum_japan.hpp"

#include <sstream>

#include "core/error.hpp"

namespace pound {

double japan_amplification(JapanSoil soil, double T) {
  // Notification No. 1457 (2000), article 10, simplified Gs.
  switch (soil) {
    case JapanSoil::bedrock:
      return 1.0;
    case JapanSoil::type1:
      if (T < 0.576) return 1.5;
      if (T < 0.64) return 0.864 / T;
      return 1.35;
    case JapanSoil::type2:
    case JapanSoil::type3: {
      const double gv = soil == JapanSoil::type2 ? 2.025 : 2.7;
      const double tu = 0.64 * gv / 1.5;
      if (T < 0.64) return 1.5;
      if (T < tu) return 1.5 * T / 0.64;
      return gv;
    }
  }
  return 1.0;
}

JapanSpectrum::JapanSpectrum(JapanLevel level, JapanSoil soil, double zone, double damping)
    : level_(level), soil_(soil), zone_(zone), damping_(damping) {
  if (!(zone > 0.0 && zone <= 1.0))
    throw InputError("Japanese spectrum: zone factor Z must be in (0, 1]");
  if (!(damping >= 0.0 && damping < 1.0))
    throw InputError("Japanese spectrum: damping must be in [0, 1)");
}

double JapanSpectrum::sa(double T) const {
  // Notification No. 1461 (2000) item 4 (i): level 2 at the engineering bedrock [m/s^2].
  double s0 = T < 0.16 ? 3.2 + 30.0 * T : T < 0.64 ? 8.0 : 5.12 / T;
  if (level_ == JapanLevel::level1) s0 /= 5.0;
  const double fh = 1.5 / (1.0 + 10.0 * damping_);  // Notification 1457 art. 9
  return s0 * zone_ * japan_amplification(soil_, T) * fh;
}

std::string JapanSpectrum::describe() const {
  static const char* soils[] = {
      "engineering bedrock (no amplification)", "type 1 ground (Gs of Notification 1457)",
      "type 2 ground (Gs of Notification 1457)", "type 3 ground (Gs of Notification 1457)"};
  std::ostringstream s;
  s << "Japanese BSL 2000 spectrum, level " << (level_ == JapanLevel::level1 ? 1 : 2) << " ("
    << (level_ == JapanLevel::level1 ? "rare" : "extremely rare") << "), "
    << soils[static_cast<int>(soil_)] << ", Z = " << zone_ << ", damping " << 100.0 * damping_
    << " %; MOC Notification 1461 (2000) item 4";
  return s.str();
}

}  // namespace pound

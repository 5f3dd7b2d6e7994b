#pragma once
// Japanese design spectrum of the 2000 revision of the Building Standard Law.
//
// Engineering bedrock (exposed, Vs >= about 400 m/s): Notification No. 1461 of 2000 (MOC),
// item 4 (i), acceleration response spectrum at 5 % damping, in m/s^2, times the seismic
// zone factor Z (0.7-1.0, Notification No. 1793 of 1980):
//   level 2 (extremely rare earthquake)   T < 0.16: 3.2 + 30 T;  0.16 <= T < 0.64: 8.0;
//                                           T >= 0.64: 5.12 / T
//   level 1 (rare earthquake): one fifth of level 2.
//
// Ground surface: the bedrock spectrum times the simplified surface amplification Gs of
// Notification No. 1457 of 2000 (limit strength calculation), article 10 (the simplified
// table for the three ground types of Notification No. 1793):
//   type 1 ground: Gs = 1.5 (T < 0.576), 0.864 / T (0.576 <= T < 0.64), 1.35 (T >= 0.64)
//   types 2 and 3: Gs = 1.5 (T < 0.64), 1.5 T / 0.64 (0.64 <= T < Tu), gv (T >= Tu),
//                  gv = 2.025 (type 2) or 2.7 (type 3), Tu = 0.64 gv / 1.5.
// Other damping h: the factor Fh = 1.5 / (1 + 10 h) of Notification No. 1457 article 9
// (Fh = 1 at h = 0.05).
#include "motion/design_spectrum.hpp"

namespace pound {

enum class JapanLevel { level1, level2 };
/// bedrock: no amplification (the spectrum of Notification 1461); type1..type3: ground types.
enum class JapanSoil { bedrock, type1, type2, type3 };

/// Simplified surface amplification Gs [-] (Notification 1457 article 10); 1 for bedrock.
double japan_amplification(JapanSoil soil, double period);

class JapanSpectrum : public DesignSpectrum {
 public:
  /// zone: seismic zone factor Z [-] (0 < Z <= 1); damping: h [-].
  JapanSpectrum(JapanLevel level, JapanSoil soil, double zone = 1.0, double damping = 0.05);
  double sa(double period) const override;
  double damping() const override { return damping_; }
  std::string describe() const override;

 private:
  JapanLevel level_;
  JapanSoil soil_;
  double zone_, damping_;
};

}  // namespace pound

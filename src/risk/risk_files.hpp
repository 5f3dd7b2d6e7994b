#pragma once
// The files of `pound risk`, each written whole or not at all (AtomicPath), in a folder of
// their own so that the campaign file is never touched (docs/risk.md, "Output"):
//   risk_gaps.csv     per pair and gap: pounding samples, fit status, theta [m/s^2], beta,
//                     nu [1/yr], probability in T years and its bootstrap band
//   code_rules.csv    per pair and rule (abs, srss, ddc, ec8): gap [m], governing level, fit,
//                     nu, probability, with the design intensity, rho and ec8's case
//   damage_maf.csv    per building, EDP and limit: nu with and without pounding and their ratio
//   risk.h5           all of it, the hazard curve used (points and the interpolated and
//                     extrapolated curve) and the observed pounding fractions per stripe
// Empty CSV fields stand for "no estimate" (the status column says why).
#include <string>
#include <vector>

#include "fragility/campaign_reader.hpp"
#include "risk/hazard_curve.hpp"
#include "risk/pounding_risk.hpp"

namespace pound {

struct RiskRunInfo {
  std::string input;   ///< campaign file
  std::string config;  ///< resolved options of the risk run
  RiskSettings settings;
};

/// Writes the files into `dir` (which must exist); returns their paths.
std::vector<std::string> write_risk_files(const std::string& dir, const CampaignData& c,
                                          const HazardCurve& h, const RiskReport& r,
                                          const RiskRunInfo& info);

}  // namespace pound

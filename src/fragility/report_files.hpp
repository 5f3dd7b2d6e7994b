#pragma once
// The files of a fragility analysis, each written whole or not at all (AtomicPath), in a
// folder of their own so that the campaign file is never touched:
//   curves.csv        one row per curve: building, edp, limit (SI), pounding, status, theta
//                     [m/s^2], beta, 90 % bootstrap and asymptotic bands, counts (analyses,
//                     exceedances, and left_out: analyses whose EDP is not finite)
//   shift.csv         theta_pounding / theta_free per building, edp and limit, 90 % band,
//                     the two medians [m/s^2 or the IM unit], whether the free one is fitted
//                     on the pounding curve's analyses (FragilityShift::same_analyses), and
//                     that free fit's beta
//   observations.csv  per curve pair and stripe (or IM bin): im [m/s^2], n (the pounding
//                     curve's analyses), exceedances with and without pounding, n_free (the
//                     free curve's: more where a neighbour's collapse censored pounding runs)
//   sensitivity.csv   Spearman and partial rank correlation of each sampled parameter with
//                     the displacement and drift amplification, per building, ranked
//   fragility.h5      the /fragility group: attributes of the run, /fragility/grid_im [G]
//                     (m/s^2) and one group /fragility/curveNNN per curve (attributes as in
//                     curves.csv, left_out included; datasets observed_im, observed_n, observed_z,
//                     probability [G], band_lo [G], band_hi [G])
// Empty CSV fields stand for "no finite estimate" (the status column says why).
#include <string>
#include <vector>

#include "fragility/campaign_reader.hpp"
#include "fragility/fragility_analysis.hpp"

namespace pound {

struct FragilityRunInfo {
  std::string input;   ///< campaign file path
  int replicates = 0;  ///< bootstrap replicates
  std::string seed;    ///< bootstrap seed
  std::string config;  ///< resolved options of the fragility run
};

/// Writes the files into `dir` (which must exist); returns their paths.
std::vector<std::string> write_fragility_files(const std::string& dir, const CampaignData& c,
                                               const FragilityReport& r,
                                               const FragilityRunInfo& info);

}  // namespace pound

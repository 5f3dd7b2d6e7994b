#pragma once
// `pound risk` as library calls (issue 25), shared by the program (app/cmd_risk.cpp) and the
// Python module: the options read and validated, the campaign file and the hazard curve read,
// the pounding risk at every gap, the code rules, the damage limits and collapse computed
// (src/risk), the files written when asked, and the JSON that `pound risk --json` prints. Reads
// HDF5 (io/h5.hpp): one call at a time per process.
#include <string>
#include <vector>

#include "fragility/campaign_reader.hpp"
#include "io/options.hpp"
#include "risk/hazard_curve.hpp"
#include "risk/pounding_risk.hpp"

namespace pound {

/// The options of `pound risk` (--input, --hazard, --gaps, --years, --target-probability,
/// --design-im, --out, --replicates, --seed, --json).
std::vector<OptionSpec> risk_option_specs();
/// Its one-line description (the --help header).
extern const char* const kRiskSummary;

struct RiskRun {
  CampaignData data;
  HazardCurve hazard;
  RiskSettings settings;
  std::vector<BuildingMode> modes;  ///< first modes of the code rules (empty: not computed)
  PairSites sites;                  ///< each pair's contact sites (empty: the study unread)
  RiskReport report;
  std::string dir;                 ///< the output folder ("" when no file was written)
  std::vector<std::string> files;  ///< the files written
};

/// Reads and validates the options, the campaign file of --input and the hazard curve of
/// --hazard, and analyses. With write_files the results go to --out (default RUN-risk/ beside
/// RUN.h5), each file whole or not at all, after everything has been computed.
RiskRun run_risk_analysis(const Options& opt, bool write_files);

/// The JSON object `pound risk --json` prints (one line, no newline).
std::string risk_json(const RiskRun& run);

}  // namespace pound

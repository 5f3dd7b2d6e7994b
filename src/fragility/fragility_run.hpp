#pragma once
// `pound fragility` as library calls (issue 25), shared by the program (app/cmd_fragility.cpp)
// and the Python module: the options read and validated, the campaign file read, the curves,
// shifts and sensitivity computed (src/fragility), the files written when asked, and the JSON
// that `pound fragility --json` prints. Reads HDF5 (io/h5.hpp): one call at a time per process.
#include <string>
#include <vector>

#include "fragility/campaign_reader.hpp"
#include "fragility/fragility_analysis.hpp"
#include "fragility/report_files.hpp"
#include "io/options.hpp"

namespace pound {

/// The options of `pound fragility` (--input, --out, the limits, --replicates, --seed, --json).
std::vector<OptionSpec> fragility_option_specs();
/// Its one-line description (the --help header).
extern const char* const kFragilitySummary;

struct FragilityRun {
  CampaignData data;
  FragilityReport report;
  FragilityRunInfo info;
  std::string dir;                 ///< the output folder ("" when no file was written)
  std::vector<std::string> files;  ///< the files written
};

/// The options --replicates and --seed of the bootstrap bands and --json, last in the options
/// of pound fragility and pound risk.
std::vector<OptionSpec> bootstrap_option_specs();

/// --replicates (10 to 100000) and --seed (>= 0) of the bootstrap bands, validated (InputError
/// naming the option); shared by pound risk.
BootstrapSettings bootstrap_from_options(const Options& opt);

/// Reads the campaign file of --input, the limits (the command line, then the study's
/// [fragility] section stored in the file, then the defaults) and the bootstrap settings,
/// validating each (InputError naming the option), and analyses. With write_files the results
/// go to --out (default RUN-fragility/ beside RUN.h5), each file whole or not at all.
FragilityRun run_fragility_analysis(const Options& opt, bool write_files);

/// The JSON object `pound fragility --json` prints (one line, no newline).
std::string fragility_json(const FragilityRun& run);

}  // namespace pound

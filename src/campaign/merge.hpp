#pragma once
// Joins the result files of a campaign split into sample ranges (`pound campaign
// --sample-range LO:HI`, one per job of a Slurm array) into one file equal to a single run:
// the parts must come from the same study, sample count and seed, and their ranges must cover
// 0..N-1 exactly once. Every dataset under /samples, /response and /run is copied row by row
// into place; the root attributes are those of the part holding sample 0, with sample_range
// "0:N" and merged_from listing the parts; /amplification is computed again for the joined
// samples (amplification_file.hpp). A per-floor array that a part written before its renaming
// holds under its former name (floor_arrays.hpp, peak_drift_pounding) is read from there and
// written under its current name (peak_drift_ratio_pounding).
#include <string>
#include <vector>

namespace pound {

/// Writes `out` (pass a temporary path and rename it). Throws InputError naming the part and
/// what is wrong (another study, a gap or an overlap in the ranges, a missing dataset).
void merge_campaign_parts(const std::vector<std::string>& parts, const std::string& out);

}  // namespace pound

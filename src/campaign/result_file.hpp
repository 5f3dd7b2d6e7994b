#pragma once
// The campaign result file (HDF5), built from the journal when every sample is done. Schema:
//   /samples/id [N]                    sample id (row i holds sample lo + i; lo = 0 unless the
//                                      run was one part of a split campaign, see sample_range)
//   /samples/status [N]                0 ok, 1 numerical failure, 2 input failure
//   /samples/message [N]               "" or what failed
//   /samples/im [N]                    intensity measure of the scaled motion [m/s^2]
//   /samples/scale [N]                 factor applied to the motion [-]
//   /samples/<key> [N]                 each sampled parameter by its study key (model: names)
//   /response/peak_disp_pounding, peak_disp_free [N, buildings, floors]     m
//   /response/peak_drift_ratio_pounding, peak_drift_ratio_free [N, buildings, floors]
//                                      peak storey drift ratio, - (peak_drift_pounding,
//                                      peak_drift_free in files written before 2026-11-26)
//   /response/peak_accel_pounding, peak_accel_free [N, buildings, floors]   m/s^2 (absolute)
//   /response/residual_drift_pounding, residual_drift_free [N, buildings, floors]
//                                      |storey drift| at the end of the run / height, -
//   /response/ductility_pounding, ductility_free [N, buildings, floors]
//                                      peak storey drift / yield drift Fy/k0, - (NaN for a
//                                      building without yield_shears)
//   /response/hysteretic_energy_pounding, hysteretic_energy_free [N, buildings, floors]
//                                      dissipated by the storey below the floor, J
//   (the per-floor arrays are the table of floor_arrays.hpp; the drift, ductility and energy
//   of floor j are those of storey j, between floor j-1 or the ground and floor j)
//   /response/collapsed_pounding, collapsed_free [N, buildings]   1 collapsed, 0 standing
//   /response/collapse_time_pounding, collapse_time_free [N, buildings]   s (NaN: standing)
//                                      (the per-building arrays of building_arrays.hpp)
//   /response/peak_force [N, pairs, levels]                                  N
//   /response/impacts [N, pairs, levels]                                     count
//                                      contact phases started (> 0: the faces touched; every
//                                      phase, also the damped Sears model's below its 1 %
//                                      impact threshold)
//   /response/approach_free [N, pairs, levels]                               m
//                                      peak of u_L - u_R of the facing floors in the free run:
//                                      the smallest gap at that level the motion would not
//                                      close (a pair pounds at gap g when any level exceeds g)
//   /response/peak_column_shear [N, pairs, levels]                           N
//                                      the struck columns' peak shear demand in the pounding
//                                      run at a slab-to-column site (NaN at a slab site; issue 36)
//   /response/crush [N, pairs, levels]                                       m
//                                      the face's permanent indentation at the end of the
//                                      pounding run (contact.force_cap; 0 without)
//   (NaN where a building has fewer floors, a pair fewer levels, or the sample failed)
//   /run/rank [N], /run/wall_seconds [N]   bookkeeping that differs between runs
// Root attributes: study (resolved text), engine_version, git_revision, seed, samples,
// sample_range ("lo:hi", the ids held),
// sampling, intensity_measure, im_period_s, im_building, im_levels_mps2, ranks, start_time,
// end_time, host, building_names ("a, b"), floors (integers, one per building: its floors;
// files written before 2026-11-26 lack it). pound merge copies them from the first part.
#include <string>

#include "campaign/campaign_study.hpp"

namespace pound {

struct RunInfo {
  int ranks = 1;
  std::string start_time, end_time, host;
};

/// Writes `path` (use a temporary name and rename) from the journal's records.
void write_result_file(const std::string& path, const CampaignStudy& st,
                       const std::string& journal_path, const RunInfo& info);

}  // namespace pound

#pragma once
// Writes the time histories of a row simulation (`pound simulate --histories FILE.h5`).
// Schema (SI units in each dataset's "units" attribute):
//   /row/dof_building, /row/dof_floor      building index (0-based) and floor (1-based) of
//                                          each displacement column
//   /row/site_pair, /row/site_floor        pair index (0-based) and floor of each contact column
//   /pounding/time [steps]                 s
//   /pounding/displacement [steps, dofs]   m, relative to the ground
//   /pounding/abs_acceleration [steps, dofs]  m/s^2
//   /pounding/contact_force [steps, sites] N
//   /pounding/storey_shear [steps, dofs]   N, shear of the storey below each floor (against the
//                                          storey drift u_dof - u_below: hysteresis loops; on a
//                                          flexible foundation minus h theta, issue 29)
//   /pounding/storey_drift [steps, dofs]   m, that storey's deformation (the drift its law sees)
//   /pounding/foundation_sway [steps, buildings]      m, each base's sway (0 on a fixed base)
//   /pounding/foundation_rotation [steps, buildings]  rad, each base's rotation
// The displacement columns are the floors, relative to the free-field ground under each
// building: they include the base's sway and rocking (docs/ssi.md).
//   /free/...                              the same without pounding
//   /motion/time, /motion/acceleration     s, m/s^2: the study's (reference) record
//   /ground/time [samples]                 s
//   /ground/acceleration [samples, buildings]  m/s^2, the ground under each building (issue 28:
//                                          delayed, or its own record or generated station)
//   /ground/displacement [samples, buildings]  m, its exact integral from rest
// Root attributes: config (resolved study), engine_version, git_revision.
#include <string>

#include "ground/row_ground.hpp"
#include "motion/ground_motion.hpp"
#include "simulation/simulate_row.hpp"
#include "structure/building_row.hpp"

namespace pound {

/// Writes the file atomically (a temporary renamed into place).
void write_histories(const std::string& path, const BuildingRow& row, const GroundMotion& motion,
                     const RowGround& ground, const RowSimulation& sim,
                     const std::string& config_text);

}  // namespace pound

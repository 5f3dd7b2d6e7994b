#pragma once
// The time histories of a row simulation as flat arrays: what `pound simulate --histories`
// writes (simulation/history_file.hpp) and what the Python module returns with histories=True.
// Rows are the recorded instants (every accepted step and event), columns the floor DOFs (the
// floors of building 1, floor 1 first, then building 2, ...) or the contact sites. A flexible
// foundation's sway and rotation (issue 29) are tables of their own, a column per building, and
// so is the ground under each building (issue 28).
#include <cstddef>
#include <vector>

#include "ground/row_ground.hpp"
#include "simulation/simulate_row.hpp"
#include "structure/building_row.hpp"

namespace pound {

/// Which building and floor each DOF column is, which pair and floor each site column.
struct HistoryLayout {
  std::vector<int> dof_building;  ///< 0-based building of each DOF column
  std::vector<int> dof_floor;     ///< 1-based floor of each DOF column
  std::vector<int> site_pair;     ///< 0-based pair of each site column
  std::vector<int> site_floor;    ///< 1-based site number within its pair (aligned: floor)
  // Where each site's slabs meet (issue 36; the JSON's per-site fields): kind 0 slab to slab, 1
  // slab to column; the striking slab's building and floor and the struck building (1-based);
  // the struck floor (slab sites) or storey (column sites), 1-based; xi [-].
  std::vector<int> site_kind, site_slab_building, site_slab_floor, site_hit_building, site_hit;
  std::vector<double> site_xi;
  /// Per site: the struck columns' peak shear demand with and without pounding [N] (NaN at slab
  /// sites) and the face's permanent indentation at the end of the pounding run [m] (issue 36).
  std::vector<double> site_peak_column_shear, site_peak_column_shear_free, site_crush;
  /// The assembled row's storey of each DOF (for the drifts; not written).
  std::vector<RowStorey> storeys;
  /// Per building the DOF of its base's sway and rotation, -1 on a fixed base (not written).
  std::vector<int> sway_dof, rotation_dof;
};
HistoryLayout history_layout(const BuildingRow& row, const RowSimulation& sim);

/// One run's histories, row-major [steps x dofs] or [steps x sites].
struct HistoryTable {
  std::size_t steps = 0, dofs = 0, sites = 0;
  std::vector<double> time;              ///< [steps], s
  std::vector<double> displacement;      ///< floor displacement relative to the ground, m
  std::vector<double> abs_acceleration;  ///< absolute floor acceleration, m/s^2
  std::vector<double> contact_force;     ///< [steps x sites], N
  std::vector<double> storey_shear;      ///< shear of the storey below each floor, N (NaN when
                                         ///< the run kept none)
  /// Drift of that storey, its deformation: u_j - u_{j-1} (u_0 = 0) on a fixed base, minus the
  /// base's rotation times the storey's height on a flexible one (u_0 the base's sway), m.
  std::vector<double> storey_drift;
  /// [steps x buildings]: each base's sway u0, m, relative to the free-field ground under it,
  /// and rotation theta, rad (physics.md section 5a); 0 on a fixed base.
  std::size_t buildings = 0;
  std::vector<double> foundation_sway, foundation_rotation;
};
HistoryTable history_table(const History& h, const HistoryLayout& layout);

/// The ground under each building at the record's samples, row-major [samples x buildings].
struct GroundTable {
  std::size_t samples = 0, buildings = 0;
  std::vector<double> time;          ///< [samples], s
  std::vector<double> acceleration;  ///< m/s^2
  std::vector<double> displacement;  ///< exact integral from rest (ground/ground_trace.hpp), m
};
/// Samples 0, dt, ... up to the longest channel's last one.
GroundTable ground_table(const RowGround& ground);

}  // namespace pound

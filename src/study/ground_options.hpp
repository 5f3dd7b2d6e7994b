#pragma once
// The study keys of the ground under a row (issue 28, docs/ground.md), read and validated here
// once for `pound simulate`, `pound campaign` and the Python module (study/row_study.hpp):
//   [buildingN] position      the base centre's coordinate along the row [m]
//   [buildingN] motion_file   the building's own record (read with [motion]'s options)
//   [ground] apparent_velocity, coherency, coherency_parameters.
#include <limits>
#include <string>
#include <vector>

#include "ground/coherency.hpp"
#include "ground/row_ground.hpp"
#include "io/options.hpp"
#include "motion/ground_motion.hpp"
#include "structure/building_row.hpp"

namespace pound {

struct GroundSpec {
  /// Each building's base centre along the row [m] (building 1 leftmost); empty when no
  /// building gives one and the default side-by-side positions are unknown (no slab lengths).
  std::vector<double> positions;
  /// Wave passage from building 1 towards the last (v > 0) or back (v < 0) [m/s]; infinite:
  /// every building's motion arrives at once.
  double apparent_velocity = std::numeric_limits<double>::infinity();
  Coherency coherency;  ///< lagged coherency of generated motions (none: fully coherent)
  /// Per building its own record file ("" : the study's motion), read with [motion]'s options.
  std::vector<std::string> motion_files;

  /// Whether a building's position enters: a finite apparent velocity or a coherency model.
  bool positions_matter() const;
  /// Each building's arrival delay [s] (ground/wave_passage.hpp arrival_delays); 0 for a
  /// building on its own record (recorded where it stands) and without wave passage.
  std::vector<double> delays() const;
};

std::vector<OptionSpec> ground_option_specs();

/// Reads the keys. `sampled_velocity`: a campaign samples ground.apparent_velocity, so positions
/// matter whatever the fixed value. Throws InputError naming the key and what is valid: v = 0 or
/// not a number; an unknown coherency model or a parameter out of range; positions not
/// increasing along the row or overlapping (when the slab lengths are known); a position missing
/// where positions matter and no slab_length gives the side-by-side default.
GroundSpec ground_from_options(const Options& opt, const BuildingRow& row, bool sampled_velocity);

/// Coherency loss needs new motions: with recorded motions a coherency model is refused, naming
/// [ground] coherency.
void refuse_coherency_with_records(const Options& opt, const GroundSpec& g);

/// The row's ground: building b on its own record (own[b], when given) or on `reference`, each
/// delayed by its arrival delay (wave passage); buildings on the same motion and delay share a
/// channel. `own` is empty or has one entry per building (empty records: the reference).
/// `generated`: the motions are the engine's own (a campaign's generated stations), and when
/// they differ between buildings each is made to end at rest (ground/at_rest.hpp); recorded
/// motions are used as they are.
RowGround row_ground(const GroundSpec& g, const GroundMotion& reference,
                     const std::vector<GroundMotion>& own = {}, bool generated = false);

}  // namespace pound

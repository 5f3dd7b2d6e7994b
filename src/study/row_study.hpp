#pragma once
// One reader of a study's row (issue 31): the keys that `pound simulate`, `pound campaign` and
// the Python module share (the buildings and gaps, the contact model, the damped Sears model,
// the integrator and the [simulation] keys) are read and validated here, once, by the
// functions of row_options.hpp and sears_row_options.hpp, so that a key has one default, one
// check and one message whichever command reads it. `pound risk` reads what it needs from the
// campaign file instead (campaign/result_file.cpp).
#include <functional>

#include "io/options.hpp"
#include "sears/sears_simulation.hpp"
#include "simulation/contact_spec.hpp"
#include "simulation/simulate_row.hpp"
#include "solver/integrator_settings.hpp"
#include "structure/building_row.hpp"
#include "study/ground_options.hpp"
#include "study/row_options.hpp"

namespace pound {

struct RowStudy {
  BuildingRow row;                  ///< buildings and gaps
  GroundSpec ground;                ///< the ground under each building (issue 28)
  ContactSpec contact;              ///< contact.model and the lumped laws' parameters
  bool has_sears = false;           ///< the damped Sears model is among the models in use
  sears::SearsRowModel sears;       ///< its slabs and options (has_sears)
  IntegratorSettings integrator;    ///< the lumped models' integrator
  RowSimulationOptions simulation;  ///< extra time and collapse drift ratio
};

/// What a study uses that its sampled parameters decide (a campaign): the contact models, and
/// whether the apparent velocity of the ground is sampled.
struct StudyUse {
  ContactUse contact;
  bool sampled_velocity = false;  ///< [sample] ground.apparent_velocity
};
/// The study's use from its row (a campaign: its sampled parameters, which are checked against
/// the row); null: contact.model alone, nothing sampled.
using StudyUseOf = std::function<StudyUse(const BuildingRow&)>;

/// Reads and validates the row's keys; throws InputError (one line naming the file and line or
/// the flag, the key and what is valid) on the first bad value.
RowStudy read_row_study(const Options& opt, const StudyUseOf& use_of = nullptr);

}  // namespace pound

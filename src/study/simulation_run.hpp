#pragma once
// `pound simulate` as library calls (issue 25), shared by the program (app/cmd_simulate.cpp) and
// the Python module (python/): the options of a study read into a row of buildings, a contact
// model, an integrator and a ground motion, every value validated before anything runs
// (prepare_simulation); the row simulated with and without pounding (run_simulation, a pure
// function of the setup: no files, no printing, safe to call from several threads at once);
// and the JSON that `pound simulate --json` prints (study/simulation_json.hpp).
#include <string>
#include <vector>

#include "ground/row_ground.hpp"
#include "io/options.hpp"
#include "motion/ground_motion.hpp"
#include "sears/sears_simulation.hpp"
#include "simulation/contact_spec.hpp"
#include "simulation/simulate_row.hpp"
#include "solver/integrator_settings.hpp"
#include "structure/building_row.hpp"
#include "study/ground_options.hpp"

namespace pound {

/// The options of `pound simulate`: the row's keys (row_and_sears_option_specs()), --json and
/// --histories FILE.
std::vector<OptionSpec> simulate_option_specs();
/// Its one-line description (the --help header).
extern const char* const kSimulateSummary;

/// A record given as values instead of the study's [motion] file (the Python module's
/// motion=(dt, ag)). The [motion] keys file, format, units and dt are then not read; duration,
/// scale, baseline and check_pga act on these values as on a file's.
struct RecordValues {
  double dt = 0.0;            ///< sample spacing [s]
  std::vector<double> accel;  ///< ground acceleration [m/s^2]
  std::string name;           ///< how messages name the record
  std::string check_pga_key;  ///< how the caller turns the plausibility check off
};

/// Everything one simulation needs, read and validated.
struct SimulationSetup {
  BuildingRow row;
  bool is_sears = false;             ///< the damped Sears model (contact.model = sears)
  ContactSpec contact;               ///< the model's name (kSearsModelName for sears) and law
  sears::SearsRowModel sears_model;  ///< is_sears: slabs and model options
  IntegratorSettings integrator;     ///< the lumped models' integrator
  GroundMotion motion;               ///< read, truncated, scaled, baseline-corrected [m/s^2]
  RowGround ground;                  ///< the motion under each building (issue 28)
  GroundSpec ground_spec;            ///< positions, wave passage, coherency, own records
  RowSimulationOptions options;  ///< extra time, histories (--histories given), energy, collapse
  /// "WHERE is not used by contact model M": given keys the chosen model does not read.
  std::vector<std::string> unused_keys;
};

/// Reads the options (a study file and command-line keys, parsed into opt) as `pound simulate`
/// does, the record from the study's [motion] keys or, when given, from `record`. Throws
/// InputError (one line naming the file or flag, the key and what is valid) on any bad value,
/// also a damped Sears step (dt) too large for the motion.
SimulationSetup prepare_simulation(const Options& opt, const RecordValues* record = nullptr);

/// The row with and without pounding.
struct SimulationRun {
  RowSimulation sim;
  std::vector<sears::SlabPeaks> slabs;      ///< damped Sears model: colliding slabs' peaks
  std::vector<sears::SiteContacts> phases;  ///< damped Sears model: contact phases per site
  double sears_dt_s = 0.0;                  ///< damped Sears model: its (fine) step [s]
  /// The buildings' positions along the row [m] (empty: not known) and the ground motion's
  /// arrival delay at each [s] (issue 28; run_simulation).
  std::vector<double> positions, arrival_delays;
};

/// The row on `ground` with and without pounding: by the damped Sears model (`sears`) when
/// contact.model is sears, else by the lumped solver with contact's law and `integrator`. The
/// one place that chooses between the two solvers (`pound simulate`, the Python module and the
/// campaign's samples). Throws NumericalError on a numerical failure.
SimulationRun simulate_model(const BuildingRow& row, const RowGround& ground,
                             const ContactSpec& contact, const sears::SearsRowModel& sears,
                             const IntegratorSettings& integrator,
                             const RowSimulationOptions& options);

/// Simulates the setup (both runs, simulate_model). Throws NumericalError on a numerical failure.
SimulationRun run_simulation(const SimulationSetup& setup);

}  // namespace pound

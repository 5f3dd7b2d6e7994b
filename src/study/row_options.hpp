#pragma once
// The study-file keys shared by every command that simulates buildings in a row
// (`pound simulate`, later `pound campaign`), and their translation into the library's
// structs. Every key carries its unit and default; see docs/study-file.md.
#include <string>
#include <vector>

#include "io/options.hpp"
#include "motion/ground_motion.hpp"
#include "motion/motion_reader.hpp"
#include "simulation/contact_spec.hpp"
#include "simulation/simulate_row.hpp"
#include "solver/integrator_settings.hpp"
#include "structure/building_row.hpp"

namespace pound {

/// [building#], [pair#], [contact], [motion], [integrator], [simulation] keys.
std::vector<OptionSpec> row_option_specs();
/// The same without the storey-law keys below.
std::vector<OptionSpec> row_option_specs_without_laws();
/// The storey laws' parameter keys under `prefix` ("building#." in studies, "" for
/// `pound hysteresis`): hardening, bw_n and the IMK keys, with units, defaults and meanings.
std::vector<OptionSpec> storey_law_option_specs(const std::string& prefix);
/// Reads those keys under `prefix` into b for its b.masses.size() storeys (one value for all or
/// one per storey), each validated with an error naming the key and what is valid; with
/// b.hysteresis = "imk" theta_u is checked against the cap drift ratio, so b's stiffnesses,
/// storey heights and yield shears must be set before.
void read_storey_law_keys(const Options& opt, const std::string& prefix, Building& b);

/// Buildings and gaps. Needs building1 (and building2.. for a row); validates masses,
/// stiffnesses, heights, damping and gaps with errors naming file, line and key.
BuildingRow row_from_options(const Options& opt);
/// The contact models a study may simulate: `pound simulate` its contact.model; a campaign its
/// contact.model or, when it samples the model (sample.model), every label of it.
struct ContactUse {
  std::vector<std::string> models;  ///< model names (lumped, or kSearsModelName)
  /// A sampled parameter (sample.k, sample.k_factor) gives the lumped models their stiffness.
  bool k_sampled = false;
  /// Said after "or" when a lumped model lacks its stiffness (a campaign: its sampled keys).
  std::string k_alternative;
  bool sears() const;   ///< the damped Sears model is among the models
  bool lumped() const;  ///< a lumped model is among them
};
/// The use of `pound simulate`: its contact.model alone.
ContactUse single_model_use(const Options& opt);

/// The [contact] keys, read and validated here alone for every command (issue 31): the model
/// (a lumped one or sears), e, v0_min and xi_relation always; k (or k_factor times the larger
/// storey stiffness of the row) when a lumped model of `use` needs a stiffness and none is
/// sampled. The model name stays contact.model's (the campaign replaces it per sample).
ContactSpec contact_from_options(const Options& opt, const BuildingRow& row, const ContactUse& use);
IntegratorSettings integrator_from_options(const Options& opt);
/// The [simulation] keys: extra_time and collapse_drift_ratio (histories and the energy balance
/// are the caller's).
RowSimulationOptions simulation_from_options(const Options& opt);
/// The record file's format, units, dt and plausibility check from the [motion] keys.
MotionFileSpec motion_file_spec(const Options& opt, const std::string& path);
/// A read record truncated (motion.duration), scaled (motion.scale) and, with motion.baseline,
/// baseline-corrected, as the [motion] keys say.
GroundMotion process_record(const Options& opt, GroundMotion g);
/// Reads, truncates, scales and (optionally) baseline-corrects the record.
GroundMotion motion_from_options(const Options& opt);
/// A record given as values (dt [s], accel [m/s^2]) in place of the [motion] file, whose keys
/// file, format, units and dt are then not read: checked as a file's values are
/// (motion_from_values, with motion.check_pga), then processed by process_record().
GroundMotion record_from_values(const Options& opt, const std::string& name, double dt,
                                std::vector<double> accel, const std::string& check_pga_key);

}  // namespace pound

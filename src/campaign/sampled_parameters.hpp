#pragma once
// The parameters a campaign may sample, as one table (sampled_parameters.cpp): per entry the
// key under [sample] ('#' stands for a building number), its unit and meaning, the range its
// values must stay in, and what it acts on in a sample (the lumped contact, the row of
// buildings or the damped Sears model). The study reader (campaign_study.cpp) and the sample
// runner (sample.cpp) both go through the table, so a new sampled parameter is one entry.
#include <limits>
#include <string>
#include <vector>

#include "io/options.hpp"
#include "sampling/distribution.hpp"
#include "sears/sears_simulation.hpp"
#include "simulation/contact_spec.hpp"
#include "structure/building_row.hpp"
#include "study/ground_options.hpp"

namespace pound {

/// What the sampled values of one sample act on before it is simulated.
struct SampleModel {
  BuildingRow row;
  GroundSpec ground;           ///< positions, wave passage and coherency (issue 28)
  ContactSpec contact;         ///< the lumped contact models (model name, e, k, ...)
  sears::SearsRowModel sears;  ///< the damped Sears model (used when the sample's model is sears)
};

/// When a parameter is applied to a sample; the stages run in this order.
enum class SampleStage {
  label,      ///< picks a label when the sample is drawn (the contact model); nothing to apply
  direct,     ///< sets or scales the row or the contact from its own value
  after_row,  ///< sets the contact from the sample's finished row (after the scales)
  sears,      ///< the damped Sears model only
};

/// The values a numeric parameter may take (checked on the distribution's lower() and
/// upper() when the study is read): above 0 (or from 0), and a further bound with its message.
struct ValidRange {
  bool zero_allowed = false;                              ///< values >= 0 (else > 0)
  double min = -std::numeric_limits<double>::infinity();  ///< further: values >= min
  double max = std::numeric_limits<double>::infinity();   ///< further: values <= max (< max)
  bool max_inclusive = true;
  const char* message = "";  ///< said when the further bound is broken
};

struct SampledParameterSpec;

/// The [sample] key of the sampled contact model (model-form uncertainty), whose labels are
/// contact model names: `sample.model = discrete(sears: 1, hc-linear: 1)`.
inline constexpr char kSampledContactModelKey[] = "model";

/// One sampled parameter of a study: its key as written under [sample] and its distribution.
struct SampledParameter {
  std::string key;  ///< e, k, k_factor, gap, damping, model, chi, D, building2.mass_scale, ...
  Distribution distribution;
  const SampledParameterSpec* spec = nullptr;  ///< its entry of the table
  int building = -1;                           ///< 0-based building of a '#' key, else -1
  bool is_label() const;                       ///< values are labels (stored as their index)
  /// The sampled contact model (kSampledContactModelKey): its labels are model names.
  bool is_contact_model() const { return key == kSampledContactModelKey; }
};

/// One entry of the table.
struct SampledParameterSpec {
  const char* key;   ///< under [sample]; '#' stands for a building number (1 = leftmost)
  const char* unit;  ///< SI unit of the values, "-" dimensionless, "" labels
  const char* help;  ///< one line for --help
  SampleStage stage;
  ValidRange range;  ///< numeric parameters
  /// Applies a drawn value to the sample; `building` is SampledParameter::building.
  void (*apply)(SampleModel& m, int building, double value);
  /// Further checks against the study's fixed row (nullptr: none); throws InputError naming
  /// where the key was given (`sample` is the [sample] section of the study).
  void (*check)(const SampledParameter& p, const BuildingRow& row, const Options& sample);
  bool sets_contact_k = false;        ///< gives the lumped models their contact stiffness
  bool sets_ground_velocity = false;  ///< the ground's apparent velocity (positions matter)
};

/// The table, in the order of --help.
const std::vector<SampledParameterSpec>& sampled_parameter_table();

/// The [sample] keys of the table, declared without the "sample." prefix.
std::vector<OptionSpec> sampled_option_specs();

/// Whether [sample] `key` (without the prefix) is given, and not as `none`: a command line
/// switches off what a study samples with `--sample.gap none`.
bool is_sampled(const Options& sample, const std::string& key);

/// The study's sampled parameters in sorted key order (which fixes each sample's draws), with
/// every distribution checked against its entry's range and checks. Throws InputError naming
/// the file, line and key.
std::vector<SampledParameter> read_sampled_parameters(const Options& study, const BuildingRow& row);

/// Applies one sample's drawn values (values[i] belongs to params[i]) to its model, stage by
/// stage.
void apply_sampled(const std::vector<SampledParameter>& params, const std::vector<double>& values,
                   SampleModel& m);

}  // namespace pound

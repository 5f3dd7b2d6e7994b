#include "study/simulation_run.hpp"

#include <cmath>
#include <utility>

#include "contact/registry.hpp"
#include "core/format.hpp"
#include "motion/motion_reader.hpp"
#include "study/foundation_options.hpp"
#include "study/row_options.hpp"
#include "study/row_study.hpp"
#include "study/sears_row_options.hpp"

namespace pound {

const char* const kSimulateSummary =
    "Buildings in a row under a ground motion, run with and without pounding.";

std::vector<OptionSpec> simulate_option_specs() {
  auto specs = row_and_sears_option_specs();
  specs.push_back({"json", "", "", "print one JSON object", true});
  specs.push_back({"histories", "", "", "write time histories to this HDF5 file"});
  return specs;
}

namespace {

// The given keys that the chosen model does not read, as "where" texts: the damped Sears
// model ignores the lumped contact law and its integrator keys, a lumped model the sears keys.
// A value meant for the other model must not pass for one that was used. `slab_lengths_used`:
// the ground's positions (wave passage, coherency) read [buildingN] slab_length under any model
// (study/ground_options.hpp: side by side by default, and no overlap).
std::vector<std::string> keys_unused_by_model(const Options& opt, bool is_sears,
                                              bool slab_lengths_used) {
  const auto sears_specs = sears_row_option_specs();
  std::vector<std::string> unused;
  for (const auto& key : opt.given_keys()) {
    bool sears_only = false;
    for (const auto& s : sears_specs) sears_only = sears_only || Options::matches(s.key, key);
    if (slab_lengths_used && Options::matches("building#.slab_length", key)) sears_only = false;
    const bool lumped_only = (key.rfind("contact.", 0) == 0 && key != "contact.model") ||
                             key.rfind("integrator.", 0) == 0;
    if (is_sears ? lumped_only : sears_only) unused.push_back(opt.where(key));
  }
  return unused;
}

// The record: the study's [motion] file, or the given values, then the [motion] processing.
GroundMotion record_of(const Options& opt, const RecordValues* record) {
  if (!record) return motion_from_options(opt);
  return record_from_values(opt, record->name, record->dt, record->accel, record->check_pga_key);
}

// Each building's own record ([buildingN] motion_file, read and processed with the [motion]
// keys; empty where none), and the study's record unless every building has its own.
void read_records(const Options& opt, const RecordValues* record, const GroundSpec& g,
                  SimulationSetup& s) {
  std::vector<GroundMotion> own(g.motion_files.size());
  bool all_own = !own.empty();
  for (std::size_t b = 0; b < own.size(); ++b) {
    if (g.motion_files[b].empty()) {
      all_own = false;
      continue;
    }
    own[b] = process_record(opt, read_motion(motion_file_spec(opt, g.motion_files[b])));
  }
  s.motion = all_own && !record ? own.front() : record_of(opt, record);
  for (std::size_t b = 0; b < own.size(); ++b) {
    if (own[b].accel.empty()) continue;
    const std::string key = "building" + std::to_string(b + 1) + ".motion_file";
    if (std::fabs(own[b].dt - s.motion.dt) > 1e-9 * s.motion.dt)
      throw opt.invalid(
          key, "a record sampled at the study's dt = " + format_number(s.motion.dt, "%.9g") +
                   " s (this one: " + format_number(own[b].dt, "%.9g") + " s)");
    own[b].dt = s.motion.dt;  // within round-off of it: one grid
  }
  refuse_coherency_with_records(opt, g);
  s.ground = row_ground(g, s.motion, own);
}

}  // namespace

SimulationSetup prepare_simulation(const Options& opt, const RecordValues* record) {
  SimulationSetup s;
  RowStudy study = read_row_study(opt);  // the reader the campaign uses too
  s.row = std::move(study.row);
  s.contact = std::move(study.contact);
  s.is_sears = is_sears_model(s.contact.model);
  s.sears_model = std::move(study.sears);
  s.integrator = study.integrator;
  read_records(opt, record, study.ground, s);
  s.ground_spec = study.ground;
  s.options = study.simulation;
  s.options.record_history = opt.given("histories");
  s.options.track_energy = true;
  if (s.is_sears) {
    // The step limits need the motion: a too large --dt fails here, before any output.
    const std::string dt_key = opt.given("dt") ? "dt" : "sears.dt";
    try {
      sears::sears_row_steps(s.row, s.ground.dt(), s.sears_model);
    } catch (const InputError& e) {
      if (!opt.given(dt_key)) throw;
      throw opt.invalid(dt_key, e.what());
    }
  }
  s.unused_keys = keys_unused_by_model(opt, s.is_sears, s.ground_spec.positions_matter());
  return s;
}

SimulationRun simulate_model(const BuildingRow& row, const RowGround& ground,
                             const ContactSpec& contact, const sears::SearsRowModel& sears,
                             const IntegratorSettings& integrator,
                             const RowSimulationOptions& options) {
  SimulationRun r;
  if (is_sears_model(contact.model)) {
    auto ss = sears::simulate_sears_row(row, ground, sears, options);
    r.sim = std::move(ss.base);
    r.slabs = std::move(ss.slabs);
    r.phases = std::move(ss.contacts);
    r.sears_dt_s = ss.dt_s;
  } else {
    r.sim = simulate_row(row, ground, contact, integrator, options);
  }
  return r;
}

SimulationRun run_simulation(const SimulationSetup& setup) {
  SimulationRun r = simulate_model(setup.row, setup.ground, setup.contact, setup.sears_model,
                                   setup.integrator, setup.options);
  r.positions = setup.ground_spec.positions;
  r.arrival_delays = setup.ground_spec.delays();
  return r;
}

}  // namespace pound

// _engine.simulate and _engine.impact: `pound simulate --json` and `pound impact --json` as calls
// (study/simulation_run.hpp, study/impact_run.hpp), with the histories as numpy arrays.
#include <chrono>

#include "engine.hpp"
#include "simulation/history_table.hpp"
#include "study/impact_run.hpp"
#include "study/simulation_json.hpp"
#include "study/simulation_run.hpp"

namespace pound::python {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// What the GIL-free part of a simulation hands back.
struct Outcome {
  std::string json;
  std::vector<std::string> notes;
  bool histories = false;
  HistoryLayout layout;
  HistoryTable pounding, free;
  GroundTable ground;
  std::vector<double> motion_time, motion_accel;
  double prepare_s = 0.0, run_s = 0.0, json_s = 0.0;
};

py::dict history_arrays(const HistoryTable& t) {
  py::dict d;
  d["time"] = to_array(t.time);
  d["displacement"] = to_array(t.displacement, t.steps, t.dofs);
  d["storey_drift"] = to_array(t.storey_drift, t.steps, t.dofs);
  d["storey_shear"] = to_array(t.storey_shear, t.steps, t.dofs);
  d["abs_acceleration"] = to_array(t.abs_acceleration, t.steps, t.dofs);
  d["contact_force"] = to_array(t.contact_force, t.steps, t.sites);
  d["foundation_sway"] = to_array(t.foundation_sway, t.steps, t.buildings);
  d["foundation_rotation"] = to_array(t.foundation_rotation, t.steps, t.buildings);
  return d;
}

py::dict histories_of(const Outcome& o) {
  py::dict h, motion;
  h["pounding"] = history_arrays(o.pounding);
  h["free"] = history_arrays(o.free);
  h["dof_building"] = to_int_array(o.layout.dof_building);
  h["dof_floor"] = to_int_array(o.layout.dof_floor);
  h["site_pair"] = to_int_array(o.layout.site_pair);
  h["site_floor"] = to_int_array(o.layout.site_floor);
  // Issue 36: where each site's slabs meet, as the histories file's /row/site_*.
  h["site_kind"] = to_int_array(o.layout.site_kind);
  h["site_slab_building"] = to_int_array(o.layout.site_slab_building);
  h["site_slab_floor"] = to_int_array(o.layout.site_slab_floor);
  h["site_hit_building"] = to_int_array(o.layout.site_hit_building);
  h["site_hit"] = to_int_array(o.layout.site_hit);
  h["site_xi"] = to_array(o.layout.site_xi);
  h["site_peak_column_shear"] = to_array(o.layout.site_peak_column_shear);
  h["site_peak_column_shear_free"] = to_array(o.layout.site_peak_column_shear_free);
  h["site_crush"] = to_array(o.layout.site_crush);
  motion["time"] = to_array(o.motion_time);
  motion["acceleration"] = to_array(o.motion_accel);
  h["motion"] = motion;
  py::dict ground;
  ground["time"] = to_array(o.ground.time);
  ground["acceleration"] = to_array(o.ground.acceleration, o.ground.samples, o.ground.buildings);
  ground["displacement"] = to_array(o.ground.displacement, o.ground.samples, o.ground.buildings);
  h["ground"] = ground;
  return h;
}

// Everything between the arguments and the JSON text, without the GIL.
Outcome simulate_outcome(const std::vector<std::string>& args, const RecordValues* record,
                         bool histories) {
  CLocale c_locale;
  Outcome o;
  const auto t0 = Clock::now();
  const Options opt = parse_options("simulate", simulate_option_specs(), args);
  SimulationSetup setup = prepare_simulation(opt, record);
  setup.options.record_history = histories;  // a study's histories key writes no file here
  for (const auto& w : setup.unused_keys)
    o.notes.push_back(w + " is not used by contact model " + setup.contact.model);
  const auto t1 = Clock::now();
  const SimulationRun run = run_simulation(setup);
  const auto t2 = Clock::now();
  o.json = simulation_json(setup.row, run);
  o.histories = histories;
  if (histories) {
    o.layout = history_layout(setup.row, run.sim);
    o.pounding = history_table(run.sim.pounding.history, o.layout);
    o.free = history_table(run.sim.free.history, o.layout);
    o.ground = ground_table(setup.ground);
    const GroundMotion& m = setup.motion;
    o.motion_time.resize(m.accel.size());
    for (std::size_t i = 0; i < m.accel.size(); ++i) o.motion_time[i] = i * m.dt;
    o.motion_accel = m.accel;
  }
  const auto t3 = Clock::now();
  o.prepare_s = seconds(t0, t1);
  o.run_s = seconds(t1, t2);
  o.json_s = seconds(t2, t3);
  return o;
}

py::tuple simulate(const std::vector<std::string>& args, py::object dt, py::object accel,
                   bool histories, const std::string& record_name,
                   const std::string& check_pga_key) {
  RecordValues record;
  const bool given = !accel.is_none();
  if (given) {
    record.dt = dt.cast<double>();
    record.accel = to_vector(accel.cast<DoubleArray>(), record_name);
    record.name = record_name;
    record.check_pga_key = check_pga_key;
  }
  Outcome o;
  {
    py::gil_scoped_release release;
    o = simulate_outcome(args, given ? &record : nullptr, histories);
  }
  py::dict timing;
  timing["prepare_s"] = o.prepare_s;
  timing["run_s"] = o.run_s;
  timing["json_s"] = o.json_s;
  return py::make_tuple(o.json, o.notes, o.histories ? py::object(histories_of(o)) : py::none(),
                        timing);
}

std::string impact(const std::vector<std::string>& args) {
  py::gil_scoped_release release;
  CLocale c_locale;
  const Options opt = parse_options("impact", impact_option_specs(), args);
  return impact_json(impact_from_options(opt));
}

}  // namespace

void bind_simulate(py::module_& m) {
  m.def("simulate", &simulate, py::arg("args"), py::arg("dt"), py::arg("accel"),
        py::arg("histories"), py::arg("record_name"), py::arg("check_pga_key"),
        "pound simulate --json of the arguments: (json text, notes, histories or None, "
        "timing); accel (m/s^2 at dt s) replaces the study's record when not None.");
  m.def("simulate_keys", [] { return option_keys(simulate_option_specs()); });
  m.def("impact", &impact, py::arg("args"), "pound impact --json of the arguments (json text).");
  m.def("impact_keys", [] { return option_keys(impact_option_specs()); });
}

}  // namespace pound::python

// pound simulate: buildings in a row under one ground motion, with and without pounding.
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "contact/registry.hpp"
#include "io/json.hpp"
#include "io/options.hpp"
#include "simulation/history_file.hpp"
#include "simulation/simulate_row.hpp"
#include "study/row_options.hpp"
#include "study/sears_row_options.hpp"

namespace pound::app {
namespace {

void print_json(const RowSimulation& s, const BuildingRow& row,
                const std::vector<sears::SlabPeaks>& slabs,
                const std::vector<sears::SiteContacts>& phases) {
  JsonWriter w;
  w.begin_object().key("buildings").begin_array();
  for (std::size_t b = 0; b < row.buildings.size(); ++b) {
    w.begin_object().field("index", static_cast<long>(b)).field("name", row.buildings[b].name);
    // Collapse (issue 23): in each run, and when and where.
    auto collapse_of = [&](const std::vector<BuildingCollapse>& c) {
      return b < c.size() ? c[b] : BuildingCollapse{};
    };
    const BuildingCollapse cp = collapse_of(s.collapse_pounding), cf = collapse_of(s.collapse_free);
    w.field("collapsed_pounding", cp.collapsed).field("collapsed_free", cf.collapsed);
    // {"pounding": value, "free": value}, null for a building standing in that run.
    auto per_run = [&](const char* key, auto value) {
      w.key(key).begin_object();
      for (const auto* c : {&cp, &cf}) {
        w.key(c == &cp ? "pounding" : "free");
        if (c->collapsed)
          w.value(value(*c));
        else
          w.null();
      }
      w.end_object();
    };
    per_run("collapse_time_s", [](const BuildingCollapse& c) { return c.time; });
    per_run("collapse_storey", [](const BuildingCollapse& c) { return c.storey; });
    w.key("floors").begin_array();
    for (const auto& f : s.floors) {
      if (f.building != static_cast<int>(b)) continue;
      w.begin_object()
          .field("floor", f.floor)
          .field("peak_disp_pounding_m", f.disp_pounding)
          .field("peak_disp_free_m", f.disp_free)
          .field("disp_amplification", f.disp_amplification)
          .field("peak_drift_ratio_pounding", f.drift_ratio_pounding)
          .field("peak_drift_ratio_free", f.drift_ratio_free)
          .field("drift_amplification", f.drift_amplification)
          .field("peak_abs_accel_pounding_mps2", f.accel_pounding)
          .field("peak_abs_accel_free_mps2", f.accel_free)
          .field("residual_drift_ratio_pounding", f.residual_drift_ratio_pounding)
          .field("residual_drift_ratio_free", f.residual_drift_ratio_free)
          .field("ductility_pounding", f.ductility_pounding)
          .field("ductility_free", f.ductility_free)
          .field("hysteretic_energy_pounding_J", f.hysteretic_energy_pounding)
          .field("hysteretic_energy_free_J", f.hysteretic_energy_free)
          .end_object();
    }
    w.end_array().end_object();
  }
  w.end_array();
  // The pounding run stops at its first collapse (null: it ran to the end).
  w.key("pounding_stopped_at_s");
  if (s.pounding.stopped)
    w.value(s.pounding.t_end);
  else
    w.null();
  w.key("contacts").begin_array();
  for (std::size_t k = 0; k < s.sites.size(); ++k) {
    const auto& c = s.sites[k];
    w.begin_object()
        .field("pair", c.pair)
        .field("floor", c.floor)
        .field("impacts", c.impacts)
        .field("peak_force_N", c.peak_force)
        .field("peak_penetration_m", c.peak_penetration)
        .field("first_contact_s", c.impacts ? c.first_contact : -1.0);
    if (k < phases.size())  // damped Sears: contact phases above 1 % of the site's peak force
      w.field("significant_impacts", phases[k].impacts)
          .field("first_impact_s", phases[k].first_impact_s);
    w.end_object();
  }
  w.end_array();
  if (!slabs.empty()) {
    // Damped Sears model: peak accelerations of the colliding slabs.
    w.key("slabs").begin_array();
    for (const auto& p : slabs)
      w.begin_object()
          .field("building", p.building)
          .field("floor", p.floor)
          .field("peak_face_accel_mps2", p.face_accel)
          .field("peak_centre_accel_mps2", p.centre_accel)
          .end_object();
    w.end_array();
  }
  // Energy balance of each run [J] (RowResult::energy).
  for (const auto* run : {&s.pounding, &s.free}) {
    const EnergyBalance& e = run->energy;
    w.key(run == &s.pounding ? "energy_pounding" : "energy_free")
        .begin_object()
        .field("input_J", e.input)
        .field("kinetic_J", e.kinetic)
        .field("strain_J", e.strain)
        .field("damping_J", e.damping)
        .field("hysteretic_J", e.hysteretic)
        .field("contact_J", e.contact)
        .field("residual_J", e.residual())
        .end_object();
  }
  w.end_object();
  std::cout << w.str() << "\n";
}

// Collapse (issue 23): per building and run, when, where and why; only when one collapsed.
void print_collapse_table(const RowSimulation& s, const BuildingRow& row) {
  bool any = false;
  for (const auto* c : {&s.collapse_pounding, &s.collapse_free})
    for (const auto& x : *c) any = any || x.collapsed;
  if (!any) return;
  std::printf("\n%-12s %-9s %10s %7s %-14s\n", "building", "run", "collapse[s]", "storey", "cause");
  for (std::size_t b = 0; b < row.buildings.size(); ++b)
    for (const auto* c : {&s.collapse_pounding, &s.collapse_free}) {
      const BuildingCollapse x = b < c->size() ? (*c)[b] : BuildingCollapse{};
      const char* run = c == &s.collapse_pounding ? "pounding" : "free";
      if (!x.collapsed) {
        std::printf("%-12s %-9s %10s %7s %-14s\n", row.buildings[b].name.c_str(), run, "-", "-",
                    "standing");
        continue;
      }
      std::printf("%-12s %-9s %10.4f %7d %-14s\n", row.buildings[b].name.c_str(), run, x.time,
                  x.storey, x.cause == CollapseCause::drift ? "drift" : "failed storey");
    }
  if (s.pounding.stopped)
    std::printf(
        "the pounding run stopped at its first collapse, t = %.4f s: its peaks are those up "
        "to then, its residual drifts unknown\n",
        s.pounding.t_end);
}

void print_table(const RowSimulation& s, const BuildingRow& row,
                 const std::vector<sears::SlabPeaks>& slabs,
                 const std::vector<sears::SiteContacts>& phases) {
  std::printf("%-12s %5s %12s %12s %8s %12s %12s %8s %12s %12s\n", "building", "floor",
              "disp_pnd[m]", "disp_free[m]", "ratio", "drift_pnd[-]", "drift_free[-]", "ratio",
              "acc_pnd[g]", "acc_free[g]");
  for (const auto& f : s.floors)
    std::printf("%-12s %5d %12.5g %12.5g %8.4f %12.5g %12.5g %8.4f %12.4g %12.4g\n",
                row.buildings[f.building].name.c_str(), f.floor, f.disp_pounding, f.disp_free,
                f.disp_amplification, f.drift_ratio_pounding, f.drift_ratio_free,
                f.drift_amplification, f.accel_pounding / kGravity, f.accel_free / kGravity);
  // Yielding storeys (hysteresis other than elastic, or yield shears given).
  bool yielding = false;
  for (const auto& b : row.buildings)
    yielding = yielding || b.inelastic() || !b.yield_shears.empty();
  if (yielding) {
    std::printf("\n%-12s %5s %14s %14s %10s %10s %14s %14s\n", "building", "storey", "resid_pnd[-]",
                "resid_free[-]", "duct_pnd", "duct_free", "E_hyst_pnd[J]", "E_hyst_free[J]");
    for (const auto& f : s.floors)
      std::printf("%-12s %5d %14.5g %14.5g %10.4g %10.4g %14.6g %14.6g\n",
                  row.buildings[f.building].name.c_str(), f.floor, f.residual_drift_ratio_pounding,
                  f.residual_drift_ratio_free, f.ductility_pounding, f.ductility_free,
                  f.hysteretic_energy_pounding, f.hysteretic_energy_free);
  }
  print_collapse_table(s, row);
  std::printf("\n%-10s %12s %12s %12s %12s %12s %12s %12s\n", "energy[J]", "input", "kinetic",
              "strain", "damping", "hysteretic", "contact", "residual");
  for (const auto* run : {&s.pounding, &s.free}) {
    const EnergyBalance& e = run->energy;
    std::printf("%-10s %12.6g %12.6g %12.6g %12.6g %12.6g %12.6g %12.3g\n",
                run == &s.pounding ? "pounding" : "free", e.input, e.kinetic, e.strain, e.damping,
                e.hysteretic, e.contact, e.residual());
  }
  std::printf("\n%-6s %5s %8s %14s %16s %14s\n", "pair", "floor", "impacts", "peak_force[N]",
              "peak_penetr[m]", "first_contact[s]");
  for (const auto& c : s.sites)
    std::printf("%-6d %5d %8d %14.6g %16.6g %14.4f\n", c.pair + 1, c.floor, c.impacts, c.peak_force,
                c.peak_penetration, c.first_contact);
  if (!phases.empty()) {
    std::printf(
        "\n%-6s %5s %20s %16s   (damped Sears: contact phases above 1 %% of the site's peak "
        "force)\n",
        "pair", "floor", "significant_impacts", "first_impact[s]");
    for (std::size_t k = 0; k < phases.size() && k < s.sites.size(); ++k)
      std::printf("%-6d %5d %20d %16.4f\n", s.sites[k].pair + 1, s.sites[k].floor,
                  phases[k].impacts, phases[k].first_impact_s);
  }
  if (slabs.empty()) return;
  std::printf("\n%-12s %5s %16s %18s\n", "building", "floor", "face_accel[g]", "centre_accel[g]");
  for (const auto& p : slabs)
    std::printf("%-12s %5d %16.4g %18.4g\n", row.buildings[p.building].name.c_str(), p.floor,
                p.face_accel / kGravity, p.centre_accel / kGravity);
}

// The given keys that the chosen model does not read, as "where" texts: the damped Sears
// model ignores the lumped contact law and its integrator keys, a lumped model the sears keys.
// A value meant for the other model must not pass for one that was used.
std::vector<std::string> keys_unused_by_model(const Options& opt, bool is_sears) {
  const auto sears_specs = sears_row_option_specs();
  std::vector<std::string> unused;
  for (const auto& key : opt.given_keys()) {
    bool sears_only = false;
    for (const auto& s : sears_specs) sears_only = sears_only || Options::matches(s.key, key);
    const bool lumped_only = (key.rfind("contact.", 0) == 0 && key != "contact.model") ||
                             key.rfind("integrator.", 0) == 0;
    if (is_sears ? lumped_only : sears_only) unused.push_back(opt.where(key));
  }
  return unused;
}

}  // namespace

int run_simulate(int argc, const char* const* argv) {
  auto specs = row_and_sears_option_specs();
  specs.push_back({"json", "", "", "print one JSON object", true});
  specs.push_back({"histories", "", "", "write time histories to this HDF5 file"});
  Options opt("simulate",
              "Buildings in a row under a ground motion, run with and without pounding.", specs);
  if (help_asked(opt, argc, argv)) return 0;
  // Everything is read and validated before anything is simulated or written.
  const BuildingRow row = row_from_options(opt);
  const bool is_sears = is_sears_model(opt.get_string("contact.model"));
  ContactSpec contact;
  sears::SearsRowModel sears_model;
  if (is_sears) {
    contact.model = kSearsModelName;
    sears_model = sears_row_from_options(opt, row);
  } else {
    contact = contact_from_options(opt, row);
  }
  const IntegratorSettings integ = integrator_from_options(opt);
  const GroundMotion motion = motion_from_options(opt);
  RowSimulationOptions so;
  so.extra_time = opt.get_nonnegative("simulation.extra_time");
  so.record_history = opt.given("histories");
  so.track_energy = true;
  so.collapse_drift_ratio = opt.get_positive("simulation.collapse_drift_ratio");
  if (is_sears) {
    // The step limits need the motion: a too large --dt fails here, before any output.
    const std::string dt_key = opt.given("dt") ? "dt" : "sears.dt";
    try {
      sears::sears_row_steps(row, &motion, sears_model);
    } catch (const InputError& e) {
      if (!opt.given(dt_key)) throw;
      throw opt.invalid(dt_key, e.what());
    }
  }
  for (const auto& w : keys_unused_by_model(opt, is_sears))
    std::fprintf(stderr, "pound simulate: note: %s is not used by contact model %s\n", w.c_str(),
                 contact.model.c_str());
  std::fprintf(stderr,
               "pound simulate: %zu buildings, contact model %s, motion %s (%zu samples at %g s, "
               "PGA %.4g g)\n",
               row.buildings.size(), contact.model.c_str(), motion.name.c_str(),
               motion.accel.size(), motion.dt, motion.pga() / kGravity);
  RowSimulation sim;
  std::vector<sears::SlabPeaks> slabs;
  std::vector<sears::SiteContacts> phases;
  if (is_sears) {
    auto ss = sears::simulate_sears_row(row, motion, sears_model, so);
    sim = std::move(ss.base);
    slabs = std::move(ss.slabs);
    phases = std::move(ss.contacts);
    std::fprintf(stderr, "pound simulate: damped Sears model, step %.3g s\n", ss.dt_s);
  } else {
    sim = simulate_row(row, motion, contact, integ, so);
  }
  if (so.record_history)
    write_histories(opt.get_string("histories"), row, motion, sim, opt.resolved_text());
  if (opt.flag("json"))
    print_json(sim, row, slabs, phases);
  else
    print_table(sim, row, slabs, phases);
  return 0;
}

}  // namespace pound::app

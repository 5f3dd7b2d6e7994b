// pound simulate: buildings in a row under one ground motion, with and without pounding.
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "app/commands.hpp"
#include "app/help.hpp"
#include "io/options.hpp"
#include "simulation/history_file.hpp"
#include "study/simulation_json.hpp"
#include "study/simulation_run.hpp"

namespace pound::app {
namespace {

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
                f.disp_amplification, f.peak_drift_ratio_pounding, f.peak_drift_ratio_free,
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
  bool crushed = false;  // crushing faces at contact.force_cap
  for (const auto& c : s.sites) crushed = crushed || c.crush > 0.0;
  if (crushed) {
    std::printf(
        "\n%-6s %5s %14s   (crushing faces: permanent indentation; their work, %.6g J, "
        "is in the pounding run's balance)\n",
        "pair", "floor", "crush[m]", s.pounding.energy.crushing);
    for (const auto& c : s.sites) std::printf("%-6d %5d %14.6g\n", c.pair + 1, c.floor, c.crush);
  }
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

}  // namespace

int run_simulate(int argc, const char* const* argv) {
  Options opt("simulate", kSimulateSummary, simulate_option_specs());
  if (help_asked(opt, argc, argv)) return 0;
  // Everything is read and validated before anything is simulated or written.
  const SimulationSetup setup = prepare_simulation(opt);
  const GroundMotion& motion = setup.motion;
  for (const auto& w : setup.unused_keys)
    std::fprintf(stderr, "pound simulate: note: %s is not used by contact model %s\n", w.c_str(),
                 setup.contact.model.c_str());
  std::fprintf(stderr,
               "pound simulate: %zu buildings, contact model %s, motion %s (%zu samples at %g s, "
               "PGA %.4g g)\n",
               setup.row.buildings.size(), setup.contact.model.c_str(), motion.name.c_str(),
               motion.accel.size(), motion.dt, motion.pga() / kGravity);
  for (const std::string& line : describe_sites(setup.row))
    std::fprintf(stderr, "pound simulate: %s\n", line.c_str());
  const SimulationRun run = run_simulation(setup);
  if (setup.is_sears)
    std::fprintf(stderr, "pound simulate: damped Sears model, step %.3g s\n", run.sears_dt_s);
  if (setup.options.record_history)
    write_histories(opt.get_string("histories"), setup.row, motion, setup.ground, run.sim,
                    opt.resolved_text());
  if (opt.flag("json"))
    std::cout << simulation_json(setup.row, run) << "\n";
  else
    print_table(run.sim, setup.row, run.slabs, run.phases);
  return 0;
}

}  // namespace pound::app

#include "study/simulation_json.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include "io/json.hpp"
#include "structure/foundation.hpp"

namespace pound {
namespace {

// Building b's periods with its foundation, the foundation's constants in SI units whatever
// way they were given, and its base's peak sway and rotation in each run (null on a fixed
// base). The floors' displacements are relative to the free-field ground: they include the
// base's sway and rocking (docs/ssi.md); the drifts are the storeys' deformations alone.
void write_foundation(JsonWriter& w, const SimulationRun& run, const AssembledRow& a, int b,
                      const Building& bd) {
  const Eigen::VectorXd& periods = a.periods[static_cast<std::size_t>(b)];
  w.key("periods_s").begin_array();
  for (int i = 0; i < std::min<int>(3, static_cast<int>(periods.size())); ++i) w.value(periods(i));
  w.end_array();
  const FoundationConstants f = foundation_constants(bd.foundation);
  // A base too light for its spring and dashpot is taken as massless (issue 38; structure/
  // building_on_base.hpp, drop_light_base_masses): its given mass, or inertia, is then not used.
  const auto dropped = [&](int dof, double given) {
    return dof >= 0 && given > 0.0 && a.massless[static_cast<std::size_t>(dof)] != 0;
  };
  const bool light = dropped(a.sway[static_cast<std::size_t>(b)], f.foundation_mass) ||
                     dropped(a.rot[static_cast<std::size_t>(b)], f.foundation_inertia);
  w.key("foundation")
      .begin_object()
      .field("kind", std::string(foundation_kind_name(bd.foundation.kind)))
      .field("sway_stiffness", f.sway_stiffness)
      .field("rocking_stiffness", f.rocking_stiffness)
      .field("sway_damping", f.sway_damping)
      .field("rocking_damping", f.rocking_damping)
      .field("trapped_rocking_inertia", f.trapped_rocking_inertia)
      .field("foundation_mass", f.foundation_mass)
      .field("foundation_inertia", f.foundation_inertia)
      .field("light_base_taken_massless", light)
      .end_object();
  for (auto [key, dof] :
       {std::pair{"peak_base_sway_m", a.sway[static_cast<std::size_t>(b)]},
        std::pair{"peak_base_rotation_rad", a.rot[static_cast<std::size_t>(b)]}}) {
    w.key(key).begin_object();
    for (const RowResult* r : {&run.sim.pounding, &run.sim.free}) {
      w.key(r == &run.sim.pounding ? "pounding" : "free");
      if (dof >= 0 && dof < r->peak_disp.size())
        w.value(r->peak_disp(dof));
      else
        w.null();
    }
    w.end_object();
  }
}

// Per building: index, name, position and arrival delay, collapse, foundation, and its floors.
void write_buildings(JsonWriter& w, const SimulationRun& run, const BuildingRow& row) {
  const RowSimulation& s = run.sim;
  const AssembledRow a = assemble(row);
  for (std::size_t b = 0; b < row.buildings.size(); ++b) {
    w.begin_object().field("index", static_cast<long>(b)).field("name", row.buildings[b].name);
    // Where it stands along the row (null: not known) and when the ground motion reaches it.
    w.key("position_m");
    if (b < run.positions.size())
      w.value(run.positions[b]);
    else
      w.null();
    w.field("arrival_delay_s", b < run.arrival_delays.size() ? run.arrival_delays[b] : 0.0);
    // Collapse (issue 23): in each run, and when and where.
    auto collapse_of = [&](const std::vector<BuildingCollapse>& c) {
      return b < c.size() ? c[b] : BuildingCollapse{};
    };
    const BuildingCollapse cp = collapse_of(s.collapse_pounding), cf = collapse_of(s.collapse_free);
    w.field("collapsed_pounding", cp.collapsed).field("collapsed_free", cf.collapsed);
    // Issue 36: the largest column-shear demand over strength of its struck storeys (null:
    // no column_shear_strength, or no storey struck).
    auto at = [&](const std::vector<double>& v) {
      return b < v.size() ? v[b] : std::numeric_limits<double>::quiet_NaN();
    };
    w.field("column_shear_ratio_pounding", at(s.column_shear_ratio_pounding))
        .field("column_shear_ratio_free", at(s.column_shear_ratio_free));
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
    write_foundation(w, run, a, static_cast<int>(b), row.buildings[b]);
    w.key("floors").begin_array();
    for (const auto& f : s.floors) {
      if (f.building != static_cast<int>(b)) continue;
      w.begin_object()
          .field("floor", f.floor)
          .field("peak_disp_pounding_m", f.disp_pounding)
          .field("peak_disp_free_m", f.disp_free)
          .field("disp_amplification", f.disp_amplification)
          .field("peak_drift_ratio_pounding", f.peak_drift_ratio_pounding)
          .field("peak_drift_ratio_free", f.peak_drift_ratio_free)
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
}

// Where the slabs meet (issue 36): kind, the striking slab and what it strikes (1-based),
// xi, the columns' stiffness (null at a slab site) and the struck point's apparent mass.
void write_site_geometry(JsonWriter& w, const ContactSite& s) {
  const SiteGeometry& g = s.geometry;
  const bool column = g.kind == SiteKind::column;
  if (!column) w.field("floor", g.slab_floor + 1);
  w.field("kind", column ? "column" : "slab")
      .field("slab_building", s.pair + g.slab_side + 1)
      .field("slab_floor", g.slab_floor + 1)
      .field("hit_building", s.pair + 1 - g.slab_side + 1)
      .field(column ? "hit_storey" : "hit_floor", g.hit + 1)
      .field("xi", g.xi)
      .key("column_stiffness_N_per_m");
  if (column)
    w.value(s.column_stiffness);
  else
    w.null();
  w.field("apparent_mass_kg", g.slab_side == 0 ? s.mass_right : s.mass_left);
}

// The struck columns' peak shear demand with and without pounding, and over their strength
// (null at slab sites, and the ratios without column_shear_strength): JSON null for NaN.
void write_column_shear(JsonWriter& w, const SiteResponse& c) {
  w.field("peak_column_shear_N", c.column_shear_pounding)
      .field("peak_column_shear_free_N", c.column_shear_free)
      .field("column_shear_ratio", c.column_shear_ratio_pounding)
      .field("column_shear_ratio_free", c.column_shear_ratio_free);
}

}  // namespace

std::string simulation_json(const BuildingRow& row, const SimulationRun& run) {
  const RowSimulation& s = run.sim;
  const std::vector<sears::SlabPeaks>& slabs = run.slabs;
  const std::vector<sears::SiteContacts>& phases = run.phases;
  JsonWriter w;
  w.begin_object().key("buildings").begin_array();
  write_buildings(w, run, row);
  // The pounding run stops at its first collapse (null: it ran to the end).
  w.key("pounding_stopped_at_s");
  if (s.pounding.stopped)
    w.value(s.pounding.t_end);
  else
    w.null();
  w.key("contacts").begin_array();
  for (std::size_t k = 0; k < s.sites.size(); ++k) {
    const auto& c = s.sites[k];
    w.begin_object().field("pair", c.pair);
    write_site_geometry(w, c.site);
    write_column_shear(w, c);
    w.field("impacts", c.impacts)
        .field("peak_force_N", c.peak_force)
        .field("peak_penetration_m", c.peak_penetration)
        .field("first_contact_s", c.impacts ? c.first_contact : -1.0)
        .field("crush_m", c.crush);
    if (k < phases.size())  // damped Sears: contact phases above 1 % of the site's peak force
      w.field("significant_impacts", phases[k].impacts)
          .field("first_impact_s", phases[k].first_impact_s);
    w.end_object();
  }
  w.end_array();
  // The ground (issue 28): each pair's peak relative ground displacement, which its gap must
  // take up besides the buildings' motion relative to their own ground (0 on one motion).
  w.key("pairs").begin_array();
  for (std::size_t p = 0; p < s.ground_relative.size(); ++p)
    w.begin_object()
        .field("pair", static_cast<int>(p))
        .field("peak_ground_relative_m", s.ground_relative[p])
        .end_object();
  w.end_array();
  if (!slabs.empty()) {
    // Damped Sears model: peak accelerations of the colliding slabs.
    w.objects("slabs", slabs, [&](const sears::SlabPeaks& p) {
      w.field("building", p.building)
          .field("floor", p.floor)
          .field("peak_face_accel_mps2", p.face_accel)
          .field("peak_centre_accel_mps2", p.centre_accel);
    });
  }
  // Energy balance of each run [J] (RowResult::energy).
  for (const auto* r : {&s.pounding, &s.free}) {
    const EnergyBalance& e = r->energy;
    w.key(r == &s.pounding ? "energy_pounding" : "energy_free")
        .begin_object()
        .field("input_J", e.input)
        .field("kinetic_J", e.kinetic)
        .field("strain_J", e.strain)
        .field("damping_J", e.damping)
        .field("hysteretic_J", e.hysteretic)
        .field("contact_J", e.contact)
        .field("crushing_J", e.crushing)
        .field("residual_J", e.residual())
        .end_object();
  }
  w.end_object();
  return w.str();
}

}  // namespace pound

#include "simulation/history_table.hpp"

#include <algorithm>
#include <cmath>

namespace pound {

HistoryLayout history_layout(const BuildingRow& row, const RowSimulation& sim) {
  HistoryLayout l;
  for (std::size_t b = 0; b < row.buildings.size(); ++b)
    for (int j = 0; j < row.buildings[b].floors(); ++j) {
      l.dof_building.push_back(static_cast<int>(b));
      l.dof_floor.push_back(j + 1);
    }
  const AssembledRow a = assemble(row);
  l.storeys = a.storeys;
  l.sway_dof = a.sway;
  l.rotation_dof = a.rot;
  for (const auto& s : sim.sites) {
    l.site_pair.push_back(s.pair);
    l.site_floor.push_back(s.floor);
    const SiteGeometry& g = s.site.geometry;
    l.site_kind.push_back(g.kind == SiteKind::column ? 1 : 0);
    l.site_slab_building.push_back(s.pair + g.slab_side + 1);
    l.site_slab_floor.push_back(g.slab_floor + 1);
    l.site_hit_building.push_back(s.pair + 1 - g.slab_side + 1);
    l.site_hit.push_back(g.hit + 1);
    l.site_xi.push_back(g.xi);
    l.site_peak_column_shear.push_back(s.column_shear_pounding);
    l.site_peak_column_shear_free.push_back(s.column_shear_free);
    l.site_crush.push_back(s.crush);
  }
  return l;
}

HistoryTable history_table(const History& h, const HistoryLayout& layout) {
  HistoryTable t;
  t.steps = h.t.size();
  // The floors' columns (a foundation's DOFs follow them in u).
  t.dofs = t.steps ? std::min(static_cast<std::size_t>(h.u[0].size()), layout.dof_floor.size()) : 0;
  t.sites = t.steps ? static_cast<std::size_t>(h.force[0].size()) : 0;
  const std::size_t n = t.steps * t.dofs;
  t.time = h.t;
  t.displacement.resize(n);
  t.abs_acceleration.resize(n);
  t.storey_shear.resize(n);
  t.storey_drift.resize(n);
  t.contact_force.resize(t.steps * t.sites);
  for (std::size_t s = 0; s < t.steps; ++s) {
    for (std::size_t i = 0; i < t.dofs; ++i) {
      const std::size_t k = s * t.dofs + i;
      t.displacement[k] = h.u[s](i);
      t.abs_acceleration[k] = h.a_abs[s](i);
      t.storey_shear[k] = s < h.shear.size() ? h.shear[s](i) : std::nan("");
      t.storey_drift[k] = storey_drift(layout.storeys[i], static_cast<int>(i), h.u[s].data());
    }
    for (std::size_t i = 0; i < t.sites; ++i) t.contact_force[s * t.sites + i] = h.force[s](i);
  }
  t.buildings = layout.sway_dof.size();
  t.foundation_sway.assign(t.steps * t.buildings, 0.0);
  t.foundation_rotation.assign(t.steps * t.buildings, 0.0);
  for (std::size_t s = 0; s < t.steps; ++s)
    for (std::size_t b = 0; b < t.buildings; ++b) {
      const int sw = layout.sway_dof[b], rt = layout.rotation_dof[b];
      if (sw >= 0) t.foundation_sway[s * t.buildings + b] = h.u[s](sw);
      if (rt >= 0) t.foundation_rotation[s * t.buildings + b] = h.u[s](rt);
    }
  return t;
}

GroundTable ground_table(const RowGround& ground) {
  GroundTable g;
  g.buildings = static_cast<std::size_t>(ground.buildings());
  const double dt = ground.dt();
  if (!(dt > 0.0) || g.buildings == 0) return g;
  g.samples = static_cast<std::size_t>(std::llround(ground.duration() / dt)) + 1;
  g.time.resize(g.samples);
  g.acceleration.resize(g.samples * g.buildings);
  g.displacement.resize(g.samples * g.buildings);
  for (std::size_t i = 0; i < g.samples; ++i) {
    const double t = static_cast<double>(i) * dt;
    g.time[i] = t;
    for (std::size_t b = 0; b < g.buildings; ++b) {
      const GroundTrace& tr = ground.under(static_cast<int>(b));
      const std::vector<double>& ag = tr.motion().accel;  // the samples themselves, 0 after
      g.acceleration[i * g.buildings + b] = i < ag.size() ? ag[i] : 0.0;
      g.displacement[i * g.buildings + b] = tr.disp(t);
    }
  }
  return g;
}

}  // namespace pound

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
  l.storeys = assemble(row).storeys;
  for (const auto& s : sim.sites) {
    l.site_pair.push_back(s.pair);
    l.site_floor.push_back(s.floor);
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
  return t;
}

}  // namespace pound

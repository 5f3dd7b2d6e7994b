#include "simulation/simulate_row.hpp"

#include <cmath>
#include <limits>

#include "solver/row_solver.hpp"

namespace pound {

namespace {

// Site s's column shear with and without pounding, over its struck storey's strength, and each
// building's largest ratio (issue 36).
void column_shear_ratios(const BuildingRow& row, SiteResponse& s, const SiteResult& pounding,
                         const SiteResult& free, RowSimulation& out) {
  if (!s.site.column()) return;
  s.column_shear_pounding = pounding.peak_column_shear;
  s.column_shear_free = free.peak_column_shear;
  const std::size_t b = static_cast<std::size_t>(s.pair + 1 - s.site.geometry.slab_side);
  const std::vector<double>& vr = row.buildings[b].column_shear_strength;
  if (vr.empty()) return;
  const double strength = vr[static_cast<std::size_t>(s.site.geometry.hit)];
  s.column_shear_ratio_pounding = s.column_shear_pounding / strength;
  s.column_shear_ratio_free = s.column_shear_free / strength;
  auto raise = [](double& r, double v) {
    if (!(r >= v)) r = v;
  };
  raise(out.column_shear_ratio_pounding[b], s.column_shear_ratio_pounding);
  raise(out.column_shear_ratio_free[b], s.column_shear_ratio_free);
}

}  // namespace

RowSimulation summarize_runs(const BuildingRow& row, const RowGround& ground, double t_end,
                             RowResult free, RowResult pounding) {
  const AssembledRow a = assemble(row);
  RowSimulation out;
  out.free = std::move(free);
  out.pounding = std::move(pounding);
  // Physics.md section 4: amplification of the peak response by pounding.
  auto ratio = [](double x, double y) { return y > 0.0 ? x / y : (x > 0.0 ? INFINITY : 1.0); };
  for (std::size_t b = 0; b < row.buildings.size(); ++b) {
    const Building& bd = row.buildings[b];
    for (int j = 0; j < bd.floors(); ++j) {
      const int i = a.offset[b] + j;
      FloorResponse f;
      f.building = static_cast<int>(b);
      f.floor = j + 1;
      f.disp_pounding = out.pounding.peak_disp(i);
      f.disp_free = out.free.peak_disp(i);
      f.disp_amplification = ratio(f.disp_pounding, f.disp_free);
      f.peak_drift_ratio_pounding = out.pounding.peak_drift(i) / bd.storey_heights[j];
      f.peak_drift_ratio_free = out.free.peak_drift(i) / bd.storey_heights[j];
      f.drift_amplification = ratio(f.peak_drift_ratio_pounding, f.peak_drift_ratio_free);
      f.accel_pounding = out.pounding.peak_abs_accel(i);
      f.accel_free = out.free.peak_abs_accel(i);
      auto residual = [&](const RowResult& r) {
        const bool collapsed = !r.collapse.empty() && r.collapse[b].collapsed;
        if (r.u_end.size() <= i || collapsed || r.stopped)
          return std::numeric_limits<double>::quiet_NaN();
        return std::fabs(storey_drift(a.storeys[i], i, r.u_end.data())) / bd.storey_heights[j];
      };
      f.residual_drift_ratio_pounding = residual(out.pounding);
      f.residual_drift_ratio_free = residual(out.free);
      const double uy = bd.storey(j).uy();  // infinite without yield shears
      const double nan = std::numeric_limits<double>::quiet_NaN();
      f.ductility_pounding = bd.yield_shears.empty() ? nan : out.pounding.peak_drift(i) / uy;
      f.ductility_free = bd.yield_shears.empty() ? nan : out.free.peak_drift(i) / uy;
      auto energy = [&](const RowResult& r) {
        return r.hysteretic_energy.size() > i ? r.hysteretic_energy(i) : 0.0;
      };
      f.hysteretic_energy_pounding = energy(out.pounding);
      f.hysteretic_energy_free = energy(out.free);
      out.floors.push_back(f);
    }
  }
  out.collapse_pounding = out.pounding.collapse;
  out.collapse_free = out.free.collapse;
  out.column_shear_ratio_pounding.assign(row.buildings.size(),
                                         std::numeric_limits<double>::quiet_NaN());
  out.column_shear_ratio_free = out.column_shear_ratio_pounding;
  for (std::size_t k = 0; k < a.sites.size(); ++k) {
    const auto& sr = out.pounding.sites[k];
    SiteResponse s;
    s.pair = a.sites[k].pair;
    s.floor = a.sites[k].level + 1;
    s.site = a.sites[k];
    s.impacts = sr.impacts;
    s.peak_force = sr.peak_force;
    s.peak_penetration = sr.peak_penetration;
    s.first_contact = sr.first_contact;
    s.crush = sr.crush;
    s.approach_free = out.free.sites[k].peak_approach;
    column_shear_ratios(row, s, out.pounding.sites[k], out.free.sites[k], out);
    out.sites.push_back(s);
  }
  for (std::size_t p = 0; p + 1 < row.buildings.size(); ++p)
    out.ground_relative.push_back(
        ground.peak_relative_displacement(static_cast<int>(p), static_cast<int>(p) + 1, t_end));
  return out;
}

RowSimulation simulate_row(const BuildingRow& row, const RowGround& ground,
                           const ContactSpec& contact, const IntegratorSettings& integ,
                           const RowSimulationOptions& opt) {
  const AssembledRow a = assemble(row);
  const auto laws = make_site_laws(contact, a);
  RowProblem p;
  p.row = &a;
  opt.apply_to(p, ground);
  for (const auto& l : laws) p.laws.push_back(l.get());
  p.force_cap = contact.force_cap;
  RunPair runs = solve_free_and_pounding(row, p, integ);  // without and with the contacts
  return summarize_runs(row, ground, p.t_end, std::move(runs.free), std::move(runs.pounding));
}

RowSimulation simulate_row(const BuildingRow& row, const GroundMotion& motion,
                           const ContactSpec& contact, const IntegratorSettings& integ,
                           const RowSimulationOptions& opt) {
  return simulate_row(row, RowGround::uniform(motion, static_cast<int>(row.buildings.size())),
                      contact, integ, opt);
}

}  // namespace pound

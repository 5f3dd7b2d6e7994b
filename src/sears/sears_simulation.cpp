#include "sears/sears_simulation.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "sears/sears_row_layout.hpp"
#include "sears/step_rule.hpp"
#include "solver/row_apart.hpp"
#include "solver/row_solver.hpp"

namespace pound::sears {

void count_impacts(SiteContacts& c, double fraction) {
  double largest = 0.0;
  for (const auto& ph : c.phases) largest = std::max(largest, ph.peak_force_N);
  c.impacts = 0;
  c.first_impact_s = -1.0;
  for (const auto& ph : c.phases)
    if (ph.peak_force_N > 0.0 && ph.peak_force_N >= fraction * largest) {
      if (c.impacts++ == 0) c.first_impact_s = ph.start_s;
    }
}

namespace {
// The step rule's limits for this row and motion (sears/step_rule.hpp), the automatic step
// dividing the record spacing.
StepLimits row_step_limits(const BuildingRow& row, double record_dt, const SearsRowModel& model) {
  const AssembledRow a = assemble(row);
  const RowContactLayout L = make_layout(row, a, model);
  double w_max = 0.0, t_c = std::numeric_limits<double>::infinity();
  for (const auto& f : L.floors)
    w_max = std::max(w_max, floor_slab(row, model, f.building, f.floor - 1).omega(model.modes));
  for (std::size_t s = 0; s < L.laws.size(); ++s) {
    // The sides' apparent masses (a slab: its floor's; a struck column point: 1 / sum w^2 / m).
    const double m1 = a.sites[s].mass_left, m2 = a.sites[s].mass_right;
    t_c = std::min(t_c,
                   L.laws[s].lumped_duration(m1 * m2 / (m1 + m2), model.hertz_reference_velocity));
  }
  const double t_min = w_max > 0.0 ? 2.0 * M_PI / w_max : std::numeric_limits<double>::infinity();
  StepLimits lim = step_limits(t_min, t_c);
  // Buildings: 20 steps per shortest period; ground motion: no step over a record sample.
  lim.auto_dt_s = std::min(lim.auto_dt_s, shortest_period(a) / 20.0);
  if (record_dt > 0.0) lim.auto_dt_s = std::min(lim.auto_dt_s, record_dt);
  if (!std::isfinite(lim.auto_dt_s))
    throw InputError("damped Sears model: no time scale (no contacts, springs or record); give dt");
  if (!std::isfinite(lim.max_dt_s)) lim.max_dt_s = lim.auto_dt_s * 10.0;
  // The automatic step divides the record spacing, so that steps end on its samples.
  if (record_dt > 0.0 && !(model.dt_s > 0.0))
    lim.auto_dt_s = record_dt / std::ceil(record_dt / lim.auto_dt_s - 1e-9);
  return lim;
}
}  // namespace

SearsSteps sears_row_steps(const BuildingRow& row, double record_dt, const SearsRowModel& model) {
  SearsSteps st;
  const StepLimits lim = row_step_limits(row, record_dt, model);
  st.fine_s = st.coarse_s = choose_step(lim, model.dt_s);
  if (model.stepping == SearsStepping::fixed) return st;
  // The lumped solver's grid (row_run.cpp, set_step_limits): h_L = the largest step <=
  // min(record spacing, T_min,b / 20) that divides the record spacing.
  const AssembledRow a = assemble(row);
  const double t_b = shortest_period(a), t_step = step_period(a);
  double h_lumped = std::numeric_limits<double>::infinity();
  if (std::isfinite(t_step)) {
    h_lumped = t_step / 20.0;
    if (record_dt > 0.0) {
      h_lumped = std::min(h_lumped, record_dt);
      h_lumped = record_dt / std::ceil(record_dt / h_lumped * (1 - 1e-12));
    }
  }
  // The coarse step: Newmark accuracy for the buildings (every mode's period, an overdamped
  // raft's too: the trapezoidal rule does not damp a stiff root), and no step over a record
  // sample; it divides h_L, whose stretches carry the floors between contacts (issue 30).
  double hc = t_b * kCoarseStepPerBuildingPeriod;
  if (record_dt > 0.0) hc = std::min(hc, record_dt);
  constexpr double kMaxRatio = 1e5;  // no building period and no record: free floors
  if (!std::isfinite(hc)) hc = kMaxRatio * st.fine_s;
  if (std::isfinite(h_lumped)) {
    st.lumped = std::max(1L, static_cast<long>(std::ceil(h_lumped / hc - 1e-9)));
    hc = h_lumped / static_cast<double>(st.lumped);
  } else if (record_dt > 0.0) {
    hc = record_dt / std::ceil(record_dt / hc - 1e-9);
  }
  if (!(hc > st.fine_s * (1.0 + 1e-9))) {  // the fine step is already coarse enough
    st.lumped = 0;
    return st;
  }
  if (model.dt_s > 0.0) {  // a given fine step is kept
    st.ratio = static_cast<long>(std::floor(std::min(hc / st.fine_s, kMaxRatio) + 1e-9));
    st.ratio = std::max(1L, st.ratio);
  } else {  // the fine step divides the coarse one
    st.ratio =
        std::max(1L, static_cast<long>(std::ceil(std::min(hc / st.fine_s, kMaxRatio) - 1e-9)));
    st.fine_s = hc / st.ratio;
  }
  st.coarse_s = st.ratio * st.fine_s;
  if (model.contact_step_tolerance > 0.0)
    st.longest =
        std::clamp(static_cast<long>(std::floor(lim.max_dt_s / st.fine_s + 1e-9)), 1L, st.ratio);
  return st;
}

SearsRowSimulation simulate_sears_row(const BuildingRow& row, const RowGround& ground,
                                      const SearsRowModel& model, const RowSimulationOptions& opt,
                                      const IntegratorSettings& integrator) {
  // Without contacts: the lumped solver's free run (the floors' physics is the same), each
  // building on its own steps where that pays (issue 38; solver/row_apart.hpp).
  const AssembledRow a = assemble(row);
  RowProblem fp;
  fp.row = &a;
  opt.apply_to(fp, ground);
  RowResult free = apart_pays(row) ? solve_apart(row, fp, integrator) : solve(fp, integrator);
  SearsRowProblem p;
  p.row = &row;
  opt.apply_to(p, ground);
  p.integrator = integrator;
  p.contacts = true;
  SearsRowResult pounding = solve_sears_row(p, model);
  SearsRowSimulation out;
  out.coarse_dt_s = pounding.coarse_dt_s;
  out.counts_pounding = pounding.counts;
  out.slabs = std::move(pounding.slabs);
  out.contacts = std::move(pounding.contacts);
  out.dt_s = pounding.dt_s;
  // Physics.md section 4, shared with the lumped models.
  out.base = summarize_runs(row, ground, p.t_end, std::move(free), std::move(pounding.row));
  return out;
}

SearsRowSimulation simulate_sears_row(const BuildingRow& row, const GroundMotion& motion,
                                      const SearsRowModel& model, const RowSimulationOptions& opt,
                                      const IntegratorSettings& integrator) {
  return simulate_sears_row(row, RowGround::uniform(motion, static_cast<int>(row.buildings.size())),
                            model, opt, integrator);
}

}  // namespace pound::sears

#include "solver/row_solver.hpp"

#include <stdexcept>
#include <utility>

#include "solver/row_run.hpp"

namespace pound {

using detail::RowRun;

RowResult solve(const RowProblem& p, const IntegratorSettings& s) {
  RowRun solver(p, s);
  return solver.run();
}

RunPair solve_free_and_pounding(const RowProblem& p, const IntegratorSettings& s) {
  RowProblem free = p, pounding = p;
  free.laws.clear();
  ExactStepCache cache;  // the free run's propagators serve the pounding run too
  if (!p.exact_cache) free.exact_cache = pounding.exact_cache = &cache;
  RowRun fs(free, s);
  if (!pounding.laws.empty()) fs.fork_into(&pounding);
  RunPair out;
  out.free = fs.run();
  if (pounding.laws.empty()) {
    out.pounding = out.free;                 // the same problem
  } else if (fs.needs_own_pounding_run()) {  // the free run collapsed before the fork
    out.pounding = RowRun(pounding, s).run();
  } else if (fs.fork()) {
    out.pounding = fs.fork()->advance();
  } else if (fs.fork_armed()) {  // no site came near touching: the runs are one
    out.pounding = out.free;
    out.pounding.sites.assign(p.row->sites.size(), SiteResult{});
    for (std::size_t k = 0; k < out.pounding.sites.size(); ++k)  // no contact: the sway shear
      out.pounding.sites[k].peak_column_shear = out.free.sites[k].peak_column_shear;
    out.pounding.steps_from_free = out.pounding.steps;
  } else {  // a site touching at the start
    out.pounding = RowRun(pounding, s).run();
  }
  return out;
}

FreeStretches::FreeStretches(const RowProblem& p, const IntegratorSettings& s)
    : run_(std::make_unique<RowRun>(p, s)) {
  if (!p.laws.empty()) throw std::logic_error("FreeStretches: a problem without contact laws");
}

FreeStretches::~FreeStretches() = default;

void FreeStretches::resume(double t, const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                           const std::vector<StoreyState>& storeys, const double* energies) {
  run_->resume(t, u, v, storeys, energies);
}

bool FreeStretches::advance_to(double t_stop, RunRecorder& rec) {
  std::swap(rec, run_->recorder());
  bool stopped = false;
  try {
    stopped = run_->advance_until(t_stop);
  } catch (...) {
    std::swap(rec, run_->recorder());
    throw;
  }
  std::swap(rec, run_->recorder());
  return stopped;
}

double FreeStretches::time() const {
  return run_->time();
}

void FreeStretches::state(Eigen::VectorXd& u, Eigen::VectorXd& v, Eigen::VectorXd& acc) const {
  const int n = run_->dynamics().layout().dofs;
  u = run_->state().head(n);
  v = run_->state().segment(n, n);
  acc = run_->derivative().segment(n, n);
}

void FreeStretches::storeys(std::vector<StoreyState>& out) const {
  run_->storey_states(out);
}

void FreeStretches::energies(double* e) const {
  const StateLayout& at = run_->dynamics().layout();
  const bool tracked = at.ground > at.energies;  // the energies are states of y
  for (int k = 0; k < 3; ++k) e[k] = tracked ? run_->state()(at.energies + k) : 0.0;
}

}  // namespace pound

#include "solver/row_solver.hpp"

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
    out.pounding.steps_from_free = out.pounding.steps;
  } else {  // a site touching at the start
    out.pounding = RowRun(pounding, s).run();
  }
  return out;
}

}  // namespace pound

#pragma once
// The lumped sample's two runs with the free run stepped building by building (issue 38 part 1;
// docs/speed.md, "Buildings on their own steps", "Design": "A row scheduler", "The approach
// bound across two grids", "The fork at a common time"). Each building's free run is its own
// RowRun (solve_apart's parts, row_apart_parts.hpp); a scheduler advances them in time order,
// always the building whose time is smallest by one accepted step, and tests each contact site
// on the overlap of the new step with the neighbour's last one, where both sides are cubic
// Hermite interpolants of their own steps and so is their difference. When a site comes within
// the fork margin (RowRun's 1 um) on an overlap starting at ta, every building's state at ta
// is taken from its run at the start of its last step, advanced to ta (the stepping building is
// there already; the other re-takes its last step with the length ta - t0), and the pounding
// run of the whole row starts there (RowRun::resume) with the buildings' peaks up to ta
// (RunRecorder::merge_from). The free run goes on building by building to the end. Kernel only.
#include <Eigen/Dense>

#include "solver/row_solver.hpp"
#include "structure/building_row.hpp"

namespace pound {

/// What the fork did (tests and benchmarks).
struct ForkStats {
  double t_fork = -1.0;  ///< the common time the pounding run started from [s]; < 0: no fork
  long copies = 0;       ///< runs copied at a step's start (a site within reach of the margin)
  /// The pounding run solved from t = 0 instead: a building collapsed before the fork, a copy
  /// was missing where the fork fired, or a site was touching at the start.
  bool own_pounding_run = false;
  Eigen::VectorXd u, v;  ///< the row's state the pounding run started from [m], [m/s]
  double retaken = 0.0;  ///< the longest re-taken part of a last step, t_fork - t0 [s]
};

/// Whether solve_free_and_pounding(row, p, s) forks at a common time: two buildings,
/// apart_pays(row), contact laws, no time histories, both on one ground channel, slab sites
/// without struck columns (the sway shear of column sites is the row run's).
bool fork_apart_applies(const BuildingRow& row, const RowProblem& p);

/// solve_free_and_pounding(p, s) with the free run building by building and the pounding run
/// forked at a common time (fork_apart_applies(row, p) must hold; p.row = &assemble(row)). The
/// free run is solve_apart's bit for bit (but for a building's steps after its collapse); the
/// pounding run agrees with solve(p)'s to the integration tolerance. Throws as solve().
RunPair solve_free_and_pounding_apart(const BuildingRow& row, const RowProblem& p,
                                      const IntegratorSettings& s, ForkStats* stats = nullptr);

}  // namespace pound

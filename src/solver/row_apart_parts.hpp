#pragma once
// The pieces of a row's free run stepped building by building (solve_apart, row_apart.hpp),
// shared with the lumped samples' fork at a common time (RowStepper, row_stepper.hpp): each
// building alone (its own assembled row, ground channel, problem, DOF map and dense output),
// and the row's result put together from theirs. Internal to src/solver.
#include <vector>

#include "ground/row_ground.hpp"
#include "solver/row_solver.hpp"
#include "solver/step_watch.hpp"
#include "structure/building_row.hpp"

namespace pound::detail {

// One building of the row, alone: its own assembled row (assemble() of that building, no
// sites), its ground channel, its problem, its DOFs' places in the row (floors first, then
// its base's sway and rotation), what its run watched and its result.
struct ApartPart {
  AssembledRow a;
  RowGround ground;
  RowProblem p;
  std::vector<int> to_row;  // per own DOF its row DOF
  StepWatch watch;
  RowResult r;
};

// The buildings of the row of the free problem `p` (no laws) alone. Parts hold pointers into
// themselves (p.row = &a): the object is neither copied nor moved.
struct ApartRow {
  ApartRow(const BuildingRow& row, const RowProblem& p);
  ~ApartRow();
  ApartRow(const ApartRow&) = delete;
  ApartRow& operator=(const ApartRow&) = delete;
  // The row's result in its DOFs from each part's r: peaks, end state, energy and step counts;
  // each site's peak approach on the union of its two buildings' step grids (from the
  // watches); the struck columns' sway shear.
  RowResult merge() const;

  const RowProblem& p;
  std::vector<ApartPart> parts;
  std::vector<std::vector<int>> to_own;  // per building, per row DOF its own DOF (-1: none)
  std::vector<int> left, right, shear;   // per site: its sides' points, the struck storey
};

}  // namespace pound::detail

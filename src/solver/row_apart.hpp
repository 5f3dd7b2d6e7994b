#pragma once
// A row's run without contacts stepped building by building (issue 38 part 1; docs/speed.md,
// "Buildings on their own steps"). Without contact forces the buildings of a row do not
// interact (M, C and K are block diagonal over them, and each stands on its own ground
// channel), so the run is N independent runs: each building alone on its own steps (its exact
// steps' grid of its own T_min / 20, its own Dormand-Prince stretches, switches, foundation and
// collapse). A building that stays elastic then takes exact steps throughout instead of
// following a yielding neighbour's Dormand-Prince steps. What couples them in the result is the
// approach at each contact site, u_L - u_R (plus the grounds' difference where the sides
// stand on different channels): it is found across the two buildings' step grids from each
// side's cubic Hermite interpolant (the one the row solver locates contact events on) on the
// union of the two grids. Kernel only.
#include "solver/row_solver.hpp"
#include "structure/building_row.hpp"

namespace pound {

/// The run of `p` without contact laws (p.laws empty; p.row = &assemble(row)) with each building
/// of `row` integrated alone and the results put together in the row's DOFs: what solve(p)
/// returns, to the integration tolerance (each building's peaks and end state are those of that
/// building simulated alone, bit for bit; the sites' peak approach is taken on the union of the
/// two buildings' step grids). A run with time histories, or one with an energy balance in
/// which a building collapses (whose balance is the row's at the first collapse), is solve(p)'s.
/// Throws as solve().
RowResult solve_apart(const BuildingRow& row, const RowProblem& p, const IntegratorSettings& s);

/// Whether stepping `row` building by building pays (docs/speed.md, "Buildings on their own
/// steps"): when some building's storeys are elastic and another's are not. The elastic one
/// alone takes exact steps throughout instead of the yielding one's Dormand-Prince steps (the
/// free run at 0.65 of the row's CPU time in `bench_speed . split`); where all yield, or none,
/// each building alone needs 80-95 % of the row's steps and the two runs cost as much as the
/// row's or more (callgrind: 1.04 times the instructions).
bool apart_pays(const BuildingRow& row);

}  // namespace pound

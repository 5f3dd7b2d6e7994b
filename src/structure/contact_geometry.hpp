#pragma once
// Where the slabs of two neighbouring buildings meet (issue 36; physics.md section 5b). Floors
// stand at base_elevation plus the storey heights below them. A slab within (t1 + t2) / 2 of
// one of the neighbour's floors meets that slab (slab to slab); otherwise a slab whose
// elevation lies inside one of the neighbour's storeys strikes that storey's columns (slab to
// column) at xi = (z - z_{j-1}) / h_j; a slab at or below the neighbour's base, or above its
// roof, meets nothing. Both buildings' slabs are tried, so each can strike the other's
// columns. Pure geometry: no DOFs, no files.
#include <vector>

#include "structure/building.hpp"

namespace pound {

enum class SiteKind {
  slab,    ///< slab to slab: the two floors meet face to face
  column,  ///< slab to column: a slab strikes the neighbour's columns between two floors
};

/// One contact site of an adjacent pair (left building L, right building R).
struct SiteGeometry {
  SiteKind kind = SiteKind::slab;
  /// The building of the striking slab: 0 the left one, 1 the right one (a slab site: 0).
  int slab_side = 0;
  int slab_floor = 0;  ///< 0-based floor of the striking slab (slab sites: L's floor)
  /// Slab sites: the 0-based floor of the other building's slab (R's). Column sites: the
  /// 0-based storey j of the struck building, which joins floor j-1 (the base when j = 0) to
  /// floor j (0-based floors, as Building's lists).
  int hit = 0;
  double xi = 1.0;         ///< column sites: (z - z_below) / h of the struck storey [-]; 1 else
  double elevation = 0.0;  ///< the striking slab's elevation above the row's datum [m]
};

/// The elevation of each floor of b above the row's datum [m], floor 1 first.
std::vector<double> floor_elevations(const Building& b);

/// The sites of the pair (left, right), ordered by the striking slab's elevation (a slab site
/// once). With equal storey heights, base elevations and floor counts, floor j meets floor j
/// for every j, as before issue 36.
std::vector<SiteGeometry> pair_sites(const Building& left, const Building& right);

/// The sway shape of a column held against rotation at both floors (a shear-building storey)
/// at xi in [0, 1]: s = 3 xi^2 - 2 xi^3 [-]. The struck point moves (1 - s) u_{j-1} + s u_j, and
/// a force F there loads floor j-1 with F (1 - s) and floor j with F s (the fixed-end
/// reactions of a point load at a = xi h: (b/h)^2 (1 + 2 a/h) F and (a/h)^2 (1 + 2 b/h) F).
double column_shape(double xi);

/// The stiffness of the struck face's columns at xi [N/m]: columns fixed at both ends whose
/// sway stiffness 12 E I / h^3 is phi k_storey carry a point load at a = xi h with the
/// deflection P a^3 b^3 / (3 E I h^3), so k_col = 3 E I h^3 / (a^3 b^3) = phi k_storey /
/// (4 xi^3 (1 - xi)^3) (Roark, Table 8.1 case 1e; 16 phi k_storey at mid-height). Infinite at
/// xi = 0 or 1 (the floors).
double column_point_stiffness(double k_storey, double phi, double xi);

}  // namespace pound

#pragma once
// Buildings the tests share.
#include "structure/building_row.hpp"

namespace pound::test {

/// n equal storeys: floor mass m [kg], storey stiffness k [N/m], storey height 3 m, damping
/// ratio xi [-] of the given kind.
inline Building uniform_building(int n, double m, double k, double xi = 0.05,
                                 DampingKind kind = DampingKind::rayleigh) {
  Building b;
  b.masses.assign(n, m);
  b.stiffnesses.assign(n, k);
  b.storey_heights.assign(n, 3.0);
  b.damping_ratio = xi;
  b.damping = kind;
  return b;
}

/// The thesis' chapter 8 pair (Table 8.2): a 5-storey building (48 t floors, 8.4e7 N/m
/// storeys) left of a 3-storey one (29 t, 6.7e7 N/m), 5 % Rayleigh damping, the same gap [m]
/// at the three colliding floors.
inline BuildingRow chapter8_pair(double gap) {
  BuildingRow row;
  row.buildings = {uniform_building(5, 48e3, 8.4e7), uniform_building(3, 29e3, 6.7e7)};
  row.gaps = {{gap, gap, gap}};
  return row;
}

}  // namespace pound::test

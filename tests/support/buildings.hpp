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

/// The chapter 8 pair with its 5-storey building yielding (bilinear, yield shears 40 % of
/// studies/ch8-yielding.ini's, 2 % hardening) and the 3-storey one elastic: under El Centro the
/// yielding one needs Dormand-Prince steps where the elastic one needs none, and their shortest
/// periods differ, so do their exact steps' grids (T_min / 20) (the tests of solve_apart and
/// RowStepper, issue 38).
inline BuildingRow yielding_and_elastic_pair(double gap) {
  BuildingRow row = chapter8_pair(gap);
  Building& b = row.buildings[0];
  b.hysteresis = "bilinear";
  b.yield_shears = {442e3, 413e3, 354e3, 266e3, 148e3};
  b.hardening.assign(5, 0.02);
  return row;
}

/// The offset pair of the slab-to-column tests (issue 36): left 2 storeys of 3 m (1e5 kg floors,
/// 4e7 N/m storeys), right 2 of 3.5 m (0.8e5 kg, 8e7 N/m), fixed bases, damping ratio xi. Sites
/// by elevation: L's floor 1 (3 m) on R's storey 1 at xi = 6/7, R's floor 1 (3.5 m) on L's
/// storey 2 at xi = 1/6, L's floor 2 (6 m) on R's storey 2 at xi = 5/7; gap [m] at each.
inline BuildingRow offset_pair(double gap, double xi) {
  BuildingRow row;
  Building l = uniform_building(2, 1.0e5, 4.0e7, xi);
  Building r = uniform_building(2, 0.8e5, 8.0e7, xi);
  r.storey_heights.assign(2, 3.5);
  row.buildings = {l, r};
  row.gaps = {{gap, gap, gap}};
  return row;
}

/// A base on springs and dashpots (docs/ssi.md): sway and rocking stiffness kx [N/m], kr
/// [N m/rad], their dashpots cx [N s/m], cr [N m s/rad], the raft's mass m0 [kg] and rotary
/// inertia i0 [kg m^2].
inline Foundation springs_foundation(double kx, double kr, double cx, double cr, double m0 = 0.0,
                                     double i0 = 0.0) {
  Foundation f;
  f.kind = FoundationKind::springs;
  f.sway_stiffness = kx;
  f.rocking_stiffness = kr;
  f.sway_damping = cx;
  f.rocking_damping = cr;
  f.foundation_mass = m0;
  f.foundation_inertia = i0;
  return f;
}

/// A rigid disc of radius r [m] on Wolf's cone (docs/ssi.md): the soil's shear wave velocity vs
/// [m/s], density rho [kg/m^3] and Poisson's ratio nu [-], the raft's m0 [kg] and i0 [kg m^2].
inline Foundation cone_foundation(double r, double vs, double rho, double nu, double m0 = 0.0,
                                  double i0 = 0.0) {
  Foundation f;
  f.kind = FoundationKind::cone;
  f.radius = r;
  f.soil_shear_velocity = vs;
  f.soil_density = rho;
  f.soil_poisson = nu;
  f.foundation_mass = m0;
  f.foundation_inertia = i0;
  return f;
}

}  // namespace pound::test

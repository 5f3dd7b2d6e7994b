#include "structure/foundation.hpp"

#include <algorithm>
#include <cmath>

#include "core/format.hpp"

namespace pound {

namespace {

struct KindName {
  FoundationKind kind;
  const char* name;
};
constexpr KindName kKinds[] = {
    {FoundationKind::fixed, "fixed"},
    {FoundationKind::springs, "springs"},
    {FoundationKind::cone, "cone"},
    {FoundationKind::gazetas, "gazetas"},
};

bool positive(double x) {
  return x > 0.0 && std::isfinite(x);
}
bool nonnegative(double x) {
  return x >= 0.0 && std::isfinite(x);
}

// The cone's constants (Wolf 1994 ch. 2 and its table of cone properties; Wolf & Deeks 2004
// ch. 3; chapter and table numbers of Wolf 1994 as remembered and equation numbers of Wolf &
// Deeks as a public implementation of it cites them, neither book read: docs/ssi.md, "What was
// checked"). A truncated semi-infinite cone of apex height z0 carries
// one-dimensional waves of velocity c: shear waves (c = Vs) for sway, dilatational waves
// (c = Vp) for rocking. Its static stiffness,
//   sway     K_x = rho Vs^2 A0 / z0           A0 = pi r^2,
//   rocking  K_t = 3 rho c^2 I0 / z0          I0 = pi r^4 / 4,
// is matched to the rigid disk's exact static stiffness on the half-space (G = rho Vs^2),
//   K_x = 8 G r / (2 - nu),        K_t = 8 G r^3 / (3 (1 - nu)),
// which fixes the aspect ratios
//   z0 / r = pi (2 - nu) / 8                   (sway; Wolf & Deeks 2004 eq. 3.31),
//   z0 / r = 9 pi (1 - nu) (c / Vs)^2 / 32     (rocking; derived here the same way),
// and the dashpots are the cones' high-frequency limits (the waves the disk radiates):
//   C_x = rho Vs A0,               C_t = rho c I0.
// For nu > 1/3 the dilatational wave velocity, Vp = Vs sqrt(2 (1 - nu) / (1 - 2 nu)), grows
// without bound as nu -> 1/2; the cone takes c = 2 Vs instead (Wolf & Deeks 2004 sec. 3.4) and
// adds the soil trapped under the disk, which moves with it: in rocking
// Delta M_t = 1.2 (nu - 1/3) rho I0 r = 0.3 pi (nu - 1/3) rho r^5 (Wolf 1994, as the issue
// gives it; its vertical counterpart 2.4 (nu - 1/3) rho A0 r is Wolf & Deeks 2004 eq. 3.84).
// K_t keeps the half-space's value: z0 is computed with the capped c. The formulas (29)
// agree with these. Not a discrepancy, but what the constants leave out: C_t is the rocking
// cone's damping coefficient only at high frequency (cone_dynamic_stiffness; docs/ssi.md).
void cone_constants(const Foundation& f, FoundationConstants& c) {
  const double r = f.radius, vs = f.soil_shear_velocity, rho = f.soil_density, nu = f.soil_poisson;
  const double G = rho * vs * vs;
  const double A0 = M_PI * r * r, I0 = M_PI * r * r * r * r / 4.0;
  const bool capped = nu > 1.0 / 3.0;
  const double vp = capped ? 2.0 * vs : vs * std::sqrt(2.0 * (1.0 - nu) / (1.0 - 2.0 * nu));
  c.sway_stiffness = 8.0 * G * r / (2.0 - nu);
  c.sway_damping = rho * vs * A0;
  c.rocking_stiffness = 8.0 * G * r * r * r / (3.0 * (1.0 - nu));
  c.rocking_damping = rho * vp * I0;
  c.trapped_rocking_inertia = capped ? 0.3 * M_PI * (nu - 1.0 / 3.0) * rho * std::pow(r, 5) : 0.0;
  c.sway_aspect_ratio = M_PI * (2.0 - nu) / 8.0;
  c.rocking_aspect_ratio = 9.0 * M_PI * (1.0 - nu) * (vp / vs) * (vp / vs) / 32.0;
  c.rocking_wave_velocity = vp;
  c.rocking_internal_inertia = rho * I0 * c.rocking_aspect_ratio * r;
}

// A rigid rectangular surface footing on the half-space, Gazetas (1991) Table 15.1 (surface
// footings; the handbook not read here: the formulas as remembered and as the public geofound
// package implements them, docs/ssi.md). With 2L x 2B the
// footing's sides, L >= B, x along L, G = rho Vs^2:
//   K_y  = 2 G L / (2 - nu) (2 + 2.5 (B/L)^0.85)                  sway along the short side,
//   K_x  = K_y - 0.2 / (0.75 - nu) G L (1 - B/L)                  sway along the long side,
//   K_rx = G / (1 - nu) I_bx^0.75 (L/B)^0.25 (2.4 + 0.5 B/L)      rocking about x,
//   K_ry = 3 G / (1 - nu) I_by^0.75 (L/B)^0.15                    rocking about y,
// I_bx = 4 L B^3 / 3 and I_by = 4 B L^3 / 3 the area's moments about x and y; the radiation
// dashpots are the high-frequency limits of his coefficients (c_y, c_rx, c_ry -> 1; c_x = 1 at
// every frequency): C = rho Vs A_b in sway (A_b = 4 B L) and C = rho V_La I_b in rocking,
// V_La = 3.4 Vs / (pi (1 - nu)) (Lysmer's analog velocity). The row's plane holds the side
// `length`: sway along it, rocking about the axis across it, whose area moment is
// width length^3 / 12 (I_by when length >= width, else I_bx). Left out, as for the cone: the
// dynamic stiffness factors k(a0) < 1 and the frequency dependence of the rocking dashpot
// (docs/ssi.md).
void gazetas_constants(const Foundation& f, FoundationConstants& c) {
  const double vs = f.soil_shear_velocity, rho = f.soil_density, nu = f.soil_poisson;
  const double G = rho * vs * vs;
  const bool along_long = f.length >= f.width;
  const double L = 0.5 * std::max(f.length, f.width), B = 0.5 * std::min(f.length, f.width);
  const double k_y = 2.0 * G * L / (2.0 - nu) * (2.0 + 2.5 * std::pow(B / L, 0.85));
  const double k_x = k_y - 0.2 / (0.75 - nu) * G * L * (1.0 - B / L);
  const double i_bx = 4.0 * L * B * B * B / 3.0, i_by = 4.0 * B * L * L * L / 3.0;
  const double k_rx =
      G / (1.0 - nu) * std::pow(i_bx, 0.75) * std::pow(L / B, 0.25) * (2.4 + 0.5 * B / L);
  const double k_ry = 3.0 * G / (1.0 - nu) * std::pow(i_by, 0.75) * std::pow(L / B, 0.15);
  const double v_la = 3.4 * vs / (M_PI * (1.0 - nu));
  c.sway_stiffness = along_long ? k_x : k_y;
  c.rocking_stiffness = along_long ? k_ry : k_rx;
  c.sway_damping = rho * vs * 4.0 * B * L;
  c.rocking_damping = rho * v_la * (along_long ? i_by : i_bx);
}

}  // namespace

const char* foundation_kind_name(FoundationKind k) {
  for (const auto& e : kKinds)
    if (e.kind == k) return e.name;
  return "?";
}

std::string foundation_kind_names() {
  return "fixed, springs, cone or gazetas";
}

bool parse_foundation_kind(const std::string& name, FoundationKind& kind) {
  for (const auto& e : kKinds)
    if (name == e.name) {
      kind = e.kind;
      return true;
    }
  return false;
}

FoundationConstants foundation_constants(const Foundation& f) {
  FoundationConstants c;
  c.kind = f.kind;
  if (f.kind == FoundationKind::fixed) return c;
  if (f.kind == FoundationKind::springs) {
    c.sway_stiffness = f.sway_stiffness;
    c.rocking_stiffness = f.rocking_stiffness;
    c.sway_damping = f.sway_damping;
    c.rocking_damping = f.rocking_damping;
  } else if (f.kind == FoundationKind::gazetas) {
    gazetas_constants(f, c);
  } else {
    cone_constants(f, c);
  }
  c.foundation_mass = f.foundation_mass;
  c.foundation_inertia = f.foundation_inertia + c.trapped_rocking_inertia;
  c.floor_inertias = f.floor_inertias;
  return c;
}

DynamicStiffness constant_dynamic_stiffness(const Foundation& f, double omega) {
  const FoundationConstants c = foundation_constants(f);
  const std::complex<double> i(0.0, 1.0);
  return {c.sway_stiffness + i * omega * c.sway_damping,
          c.rocking_stiffness + i * omega * c.rocking_damping -
              omega * omega * c.trapped_rocking_inertia};
}

DynamicStiffness cone_dynamic_stiffness(const Foundation& f, double omega) {
  if (f.kind != FoundationKind::cone) return constant_dynamic_stiffness(f, omega);
  const FoundationConstants c = foundation_constants(f);
  const std::complex<double> i(0.0, 1.0);
  // Sway: u(z) = u0 (z0 / z) exp(-i k (z - z0)), k = omega / Vs; the force at the disk is
  // K (1 + i b0) u0 with b0 = k z0, and K b0 = omega rho Vs A0 = omega C_x.
  const double bx = omega * c.sway_aspect_ratio * f.radius / f.soil_shear_velocity;
  // Rocking: theta(z) = theta0 (z0 / z)^3 (1 + i k z) / (1 + i k z0) exp(-i k (z - z0)),
  // k = omega / c, solves (z^4 theta')' + k^2 z^4 theta = 0 (I(z) = I0 (z / z0)^4); the moment
  // -rho c^2 I0 theta'(z0) = K [1 - (b0^2 / 3) / (1 + i b0)] theta0, b0 = k z0.
  const double bt = omega * c.rocking_aspect_ratio * f.radius / c.rocking_wave_velocity;
  const double b2 = bt * bt;
  const double k_t = 1.0 - b2 / (3.0 * (1.0 + b2));
  const double c_t = b2 / (1.0 + b2);  // of C_theta
  return {c.sway_stiffness * (1.0 + i * bx), c.rocking_stiffness * k_t +
                                                 i * omega * c.rocking_damping * c_t -
                                                 omega * omega * c.trapped_rocking_inertia};
}

std::string foundation_problem(const Foundation& f, int floors) {
  if (f.kind == FoundationKind::springs) {
    if (!positive(f.sway_stiffness)) return "sway_stiffness must be a finite number > 0 N/m";
    if (!positive(f.rocking_stiffness))
      return "rocking_stiffness must be a finite number > 0 N m/rad";
    if (!positive(f.sway_damping)) return "sway_damping must be a finite number > 0 N s/m";
    if (!positive(f.rocking_damping))
      return "rocking_damping must be a finite number > 0 N m s/rad";
  }
  if (f.kind == FoundationKind::cone && !positive(f.radius))
    return "foundation_radius must be a finite number > 0 m";
  if (f.kind == FoundationKind::gazetas) {
    if (!positive(f.length)) return "foundation_length must be a finite number > 0 m";
    if (!positive(f.width)) return "foundation_width must be a finite number > 0 m";
  }
  if (on_soil(f.kind)) {
    if (!positive(f.soil_shear_velocity))
      return "soil_shear_velocity must be a finite number > 0 m/s";
    if (!positive(f.soil_density)) return "soil_density must be a finite number > 0 kg/m^3";
    if (!(f.soil_poisson >= 0.0 && f.soil_poisson < 0.5)) return "soil_poisson must be in [0, 0.5)";
  }
  if (!nonnegative(f.foundation_mass)) return "foundation_mass must be a finite number >= 0 kg";
  if (!nonnegative(f.foundation_inertia))
    return "foundation_inertia must be a finite number >= 0 kg m^2";
  if (!f.floor_inertias.empty() && f.floor_inertias.size() != static_cast<std::size_t>(floors))
    return "floor_inertias: " + std::to_string(f.floor_inertias.size()) + " values for " +
           std::to_string(floors) + " floors; give one per floor";
  for (double j : f.floor_inertias)
    if (!nonnegative(j)) return "floor_inertias must be finite numbers >= 0 kg m^2";
  return "";
}

}  // namespace pound

// The foundation model (issue 29, structure/foundation.hpp): the cone's constants against the
// formulas, worked by hand below for a footing of r = 10 m on soil of Vs = 150 m/s and
// rho = 1900 kg/m^3 (G = rho Vs^2 = 1900 x 22500 = 42.75 MPa, A0 = pi r^2 = 314.159 m^2,
// I0 = pi r^4 / 4 = 7853.98 m^4), once below nu = 1/3 and once above (Vp capped at 2 Vs and
// soil trapped under the footing); the springs passed through; the frequency-dependent cone
// against the frequency-independent constants and against Wolf's spring-dashpot-mass model;
// Gazetas' rectangle against his formulas worked by hand and against the disk.
#include "structure/foundation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "core/error.hpp"
#include "structure/building.hpp"

namespace pound {
namespace {

Foundation cone(double nu) {
  Foundation f;
  f.kind = FoundationKind::cone;
  f.radius = 10.0;
  f.soil_shear_velocity = 150.0;
  f.soil_density = 1900.0;
  f.soil_poisson = nu;
  return f;
}

// Relative closeness: the constants are products of a few factors, so 1e-12 of the value.
void expect_close(double actual, double expected) {
  EXPECT_NEAR(actual, expected, 1e-12 * std::fabs(expected)) << "expected " << expected;
}

TEST(Foundation, ConeConstantsBelowOneThird) {
  const FoundationConstants c = foundation_constants(cone(0.3));
  EXPECT_EQ(c.kind, FoundationKind::cone);
  // Sway: K = 8 G r / (2 - nu) = 8 x 42.75e6 x 10 / 1.7 = 2.0117647e9 N/m;
  // C = rho Vs pi r^2 = 1900 x 150 x 314.159 = 8.9535391e7 N s/m.
  expect_close(c.sway_stiffness, 3.42e9 / 1.7);
  expect_close(c.sway_damping, 1900.0 * 150.0 * M_PI * 100.0);
  EXPECT_NEAR(c.sway_stiffness, 2.0117647e9, 1e2);
  EXPECT_NEAR(c.sway_damping, 8.9535391e7, 1.0);
  // Rocking: K = 8 G r^3 / (3 (1 - nu)) = 3.42e11 / 2.1 = 1.6285714e11 N m/rad;
  // Vp = Vs sqrt(2 x 0.7 / 0.4) = 150 sqrt(3.5) = 280.624 m/s (not capped);
  // C = rho Vp I0 = 1900 x 280.624 x 7853.98 = 4.1876344e9 N m s/rad.
  expect_close(c.rocking_stiffness, 3.42e11 / 2.1);
  EXPECT_NEAR(c.rocking_wave_velocity, 280.62430, 1e-5);
  EXPECT_NEAR(c.rocking_damping, 4.1876344e9, 1e2);
  expect_close(c.rocking_damping, 1900.0 * 150.0 * std::sqrt(3.5) * M_PI * 1e4 / 4.0);
  // No trapped soil below nu = 1/3; nothing else given.
  EXPECT_EQ(c.trapped_rocking_inertia, 0.0);
  EXPECT_EQ(c.foundation_inertia, 0.0);
  EXPECT_EQ(c.foundation_mass, 0.0);
  EXPECT_TRUE(c.floor_inertias.empty());
  EXPECT_EQ(c.floor_inertia(3), 0.0);
  // The cones' aspect ratios: z0 / r = pi (2 - nu) / 8 = 0.667588 (sway) and
  // 9 pi (1 - nu) (Vp / Vs)^2 / 32 = 9 pi 0.7 x 3.5 / 32 = 2.164754 (rocking).
  EXPECT_NEAR(c.sway_aspect_ratio, 0.667588, 1e-6);
  EXPECT_NEAR(c.rocking_aspect_ratio, 2.164754, 1e-6);
  // The internal degree of freedom's inertia rho I0 z0 = 1900 x 7853.98 x 21.6475 = 3.2303678e8.
  EXPECT_NEAR(c.rocking_internal_inertia, 3.2303678e8, 10.0);
}

TEST(Foundation, ConeConstantsAboveOneThirdCapVpAndTrapSoil) {
  Foundation f = cone(0.45);
  f.foundation_inertia = 1e6;
  const FoundationConstants c = foundation_constants(f);
  // Sway: K = 3.42e9 / 1.55 = 2.2064516e9 N/m; C unchanged (no nu in it): 8.9535391e7 N s/m.
  expect_close(c.sway_stiffness, 3.42e9 / 1.55);
  expect_close(c.sway_damping, 1900.0 * 150.0 * M_PI * 100.0);
  // Rocking: K = 3.42e11 / (3 x 0.55) = 2.0727273e11 N m/rad (the half-space's, uncapped).
  // Vp = 150 sqrt(2 x 0.55 / 0.1) = 497.49 m/s is capped at 2 Vs = 300 m/s:
  // C = 1900 x 300 x 7853.98 = 4.4767695e9 N m s/rad.
  expect_close(c.rocking_stiffness, 3.42e11 / 1.65);
  EXPECT_EQ(c.rocking_wave_velocity, 300.0);
  EXPECT_NEAR(c.rocking_damping, 4.4767695e9, 1e2);
  // Trapped: 0.3 pi (0.45 - 1/3) rho r^5 = 0.3 pi x 0.116667 x 1900 x 1e5 = 2.0891591e7 kg m^2,
  // added to the given 1e6 kg m^2 of the base.
  EXPECT_NEAR(c.trapped_rocking_inertia, 2.0891591e7, 1.0);
  expect_close(c.trapped_rocking_inertia, 0.3 * M_PI * (0.45 - 1.0 / 3.0) * 1900.0 * 1e5);
  expect_close(c.foundation_inertia, 1e6 + c.trapped_rocking_inertia);
  // z0 / r with c = 2 Vs: 9 pi x 0.55 x 4 / 32 = 1.943860.
  EXPECT_NEAR(c.rocking_aspect_ratio, 1.943860, 1e-6);
}

// The cones' static stiffness equals the half-space's through the aspect ratios, with and
// without the cap: rho Vs^2 A0 / z0 = K_x and 3 rho c^2 I0 / z0 = K_theta.
TEST(Foundation, AspectRatiosGiveTheHalfSpaceStaticStiffness) {
  for (double nu : {0.0, 0.25, 1.0 / 3.0, 0.4, 0.49}) {
    SCOPED_TRACE(nu);
    const Foundation f = cone(nu);
    const FoundationConstants c = foundation_constants(f);
    const double r = f.radius, rho = f.soil_density, vs = f.soil_shear_velocity;
    const double vc = c.rocking_wave_velocity;
    expect_close(rho * vs * vs * M_PI * r * r / (c.sway_aspect_ratio * r), c.sway_stiffness);
    expect_close(3.0 * rho * vc * vc * M_PI * std::pow(r, 4) / 4.0 / (c.rocking_aspect_ratio * r),
                 c.rocking_stiffness);
    // The cap: c = Vp up to nu = 1/3 (where Vp = 2 Vs), 2 Vs beyond.
    EXPECT_LE(vc, 2.0 * vs * (1 + 1e-15));
    EXPECT_EQ(c.trapped_rocking_inertia > 0.0, nu > 1.0 / 3.0);
  }
}

TEST(Foundation, SpringsPassThrough) {
  Foundation f;
  f.kind = FoundationKind::springs;
  f.sway_stiffness = 1e9;
  f.rocking_stiffness = 2e11;
  f.sway_damping = 3e7;
  f.rocking_damping = 4e9;
  f.foundation_mass = 5e4;
  f.foundation_inertia = 6e6;
  f.floor_inertias = {7e5, 8e5};
  f.soil_poisson = 0.45;  // a cone's key: ignored
  const FoundationConstants c = foundation_constants(f);
  EXPECT_EQ(c.kind, FoundationKind::springs);
  EXPECT_EQ(c.sway_stiffness, 1e9);
  EXPECT_EQ(c.rocking_stiffness, 2e11);
  EXPECT_EQ(c.sway_damping, 3e7);
  EXPECT_EQ(c.rocking_damping, 4e9);
  EXPECT_EQ(c.foundation_mass, 5e4);
  EXPECT_EQ(c.foundation_inertia, 6e6);
  EXPECT_EQ(c.trapped_rocking_inertia, 0.0);
  EXPECT_EQ(c.floor_inertias, (std::vector<double>{7e5, 8e5}));
  EXPECT_EQ(c.floor_inertia(1), 8e5);
  EXPECT_EQ(c.rocking_internal_inertia, 0.0);
}

TEST(Foundation, FixedHasNoConstants) {
  Foundation f;
  f.foundation_mass = 1e5;  // ignored: the base moves with the ground
  EXPECT_FALSE(f.flexible());
  const FoundationConstants c = foundation_constants(f);
  EXPECT_EQ(c.kind, FoundationKind::fixed);
  EXPECT_EQ(c.sway_stiffness, 0.0);
  EXPECT_EQ(c.rocking_damping, 0.0);
  EXPECT_EQ(c.foundation_mass, 0.0);
}

// Sway: the translational cone's dynamic stiffness K (1 + i b0) is K + i omega C at every
// frequency. Rocking: K at omega -> 0, its damping coefficient Im S / omega -> C at high
// frequency and below C in between, and Wolf's spring-dashpot-mass model (K; the dashpot C in
// series with an internal rotary inertia rho I0 z0) reproduces it at every frequency.
TEST(Foundation, ConeDynamicStiffness) {
  for (double nu : {0.3, 0.45}) {
    SCOPED_TRACE(nu);
    const Foundation f = cone(nu);
    const FoundationConstants c = foundation_constants(f);
    for (double omega : {0.1, 1.0, 10.0, 30.0, 100.0}) {
      const DynamicStiffness exact = cone_dynamic_stiffness(f, omega);
      const DynamicStiffness fixed = constant_dynamic_stiffness(f, omega);
      EXPECT_NEAR(std::abs(exact.sway - fixed.sway), 0.0, 1e-12 * std::abs(fixed.sway));
      const std::complex<double> i(0.0, 1.0);
      const std::complex<double> internal =
          c.rocking_damping / (c.rocking_damping + i * omega * c.rocking_internal_inertia);
      const std::complex<double> lumped = c.rocking_stiffness +
                                          i * omega * c.rocking_damping * (1.0 - internal) -
                                          omega * omega * c.trapped_rocking_inertia;
      EXPECT_NEAR(std::abs(exact.rocking - lumped), 0.0, 1e-12 * std::abs(lumped)) << omega;
      EXPECT_LT(exact.rocking.imag(), fixed.rocking.imag());
      EXPECT_LT(exact.rocking.real(), fixed.rocking.real());
    }
    const DynamicStiffness low = cone_dynamic_stiffness(f, 1e-6);
    EXPECT_NEAR(low.rocking.real(), c.rocking_stiffness, 1e-9 * c.rocking_stiffness);
    const double high = 1e6;  // b0 ~ 1e5
    EXPECT_NEAR(cone_dynamic_stiffness(f, high).rocking.imag() / high, c.rocking_damping,
                1e-6 * c.rocking_damping);
  }
  // Worked by hand at nu = 0.3, omega = 20 rad/s: b0 = omega z0 / Vp = 20 x 21.6475 / 280.624
  // = 1.542813, b0^2 = 2.380271; Re S / K = 1 - b0^2 / (3 (1 + b0^2)) = 0.765278; the damping
  // coefficient Im S / omega = C b0^2 / (1 + b0^2) = 0.704166 C.
  const Foundation f = cone(0.3);
  const FoundationConstants c = foundation_constants(f);
  const DynamicStiffness s = cone_dynamic_stiffness(f, 20.0);
  EXPECT_NEAR(s.rocking.real() / c.rocking_stiffness, 0.765278, 1e-6);
  EXPECT_NEAR(s.rocking.imag() / 20.0 / c.rocking_damping, 0.704166, 1e-6);
}

TEST(Foundation, ProblemsNameTheKeyAndWhatIsValid) {
  Foundation f = cone(0.5);
  EXPECT_EQ(foundation_problem(f, 2), "soil_poisson must be in [0, 0.5)");
  f = cone(-0.1);
  EXPECT_EQ(foundation_problem(f, 2), "soil_poisson must be in [0, 0.5)");
  f = cone(0.3);
  EXPECT_EQ(foundation_problem(f, 2), "");
  f.radius = 0.0;
  EXPECT_NE(foundation_problem(f, 2).find("foundation_radius"), std::string::npos);
  f = cone(0.3);
  f.soil_shear_velocity = -1.0;
  EXPECT_NE(foundation_problem(f, 2).find("soil_shear_velocity"), std::string::npos);
  f = cone(0.3);
  f.floor_inertias = {1.0, 2.0, 3.0};
  EXPECT_EQ(foundation_problem(f, 2), "floor_inertias: 3 values for 2 floors; give one per floor");
  f.floor_inertias = {1.0, -2.0};
  EXPECT_NE(foundation_problem(f, 2).find(">= 0"), std::string::npos);
  f = cone(0.3);
  f.foundation_mass = -1.0;
  EXPECT_NE(foundation_problem(f, 2).find("foundation_mass"), std::string::npos);
  Foundation s;
  s.kind = FoundationKind::springs;
  EXPECT_NE(foundation_problem(s, 1).find("sway_stiffness must be"), std::string::npos);
  // validate() of a building made in code checks its foundation.
  Building b;
  b.masses = {1e3};
  b.stiffnesses = {1e6};
  b.storey_heights = {3.0};
  validate(b, "here");
  b.foundation = s;
  try {
    validate(b, "here");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "here: foundation: sway_stiffness must be a finite number > 0 N/m");
  }
}

TEST(Foundation, Names) {
  FoundationKind k = FoundationKind::fixed;
  EXPECT_TRUE(parse_foundation_kind("cone", k));
  EXPECT_EQ(k, FoundationKind::cone);
  EXPECT_TRUE(parse_foundation_kind("springs", k));
  EXPECT_EQ(k, FoundationKind::springs);
  EXPECT_FALSE(parse_foundation_kind("raft", k));
  EXPECT_EQ(k, FoundationKind::springs);
  EXPECT_STREQ(foundation_kind_name(FoundationKind::fixed), "fixed");
  EXPECT_TRUE(parse_foundation_kind("gazetas", k));
  EXPECT_EQ(k, FoundationKind::gazetas);
  EXPECT_EQ(foundation_kind_names(), "fixed, springs, cone or gazetas");
}

Foundation rectangle(double length, double width, double nu) {
  Foundation f = cone(nu);
  f.kind = FoundationKind::gazetas;
  f.length = length;
  f.width = width;
  return f;
}

// Gazetas (1991) Table 15.1 on the soil above (G = 42.75 MPa). A square of side 2a: both sways
// K = 2 G a / (2 - nu) (2 + 2.5) = 9 G a / (2 - nu) (the long-side correction vanishes), both
// rockings about the centre lines 3 G / (1 - nu) (4 a^4 / 3)^0.75 (about y) and
// G / (1 - nu) (4 a^4 / 3)^0.75 x 2.9 (about x: the fits differ by 3.3 % where symmetry would
// make them equal; the row's plane takes the y one, length >= width). Against Wolf's disk of
// the same area (sway) and the same area moment (rocking): 0.997 and 0.939 of it.
TEST(Foundation, GazetasSquareAgainstItsFormulasAndTheDisk) {
  const double G = 1900.0 * 150.0 * 150.0, a = 5.0, nu = 0.3;
  const FoundationConstants c = foundation_constants(rectangle(2 * a, 2 * a, nu));
  EXPECT_EQ(c.kind, FoundationKind::gazetas);
  expect_close(c.sway_stiffness, 9.0 * G * a / (2.0 - nu));
  const double i_b = 4.0 * std::pow(a, 4) / 3.0;
  expect_close(c.rocking_stiffness, 3.0 * G / (1.0 - nu) * std::pow(i_b, 0.75));
  // Dashpots: rho Vs A_b and rho V_La I_b, V_La = 3.4 Vs / (pi (1 - nu)) = 231.898 m/s.
  expect_close(c.sway_damping, 1900.0 * 150.0 * 4.0 * a * a);
  expect_close(c.rocking_damping, 1900.0 * 3.4 * 150.0 / (M_PI * 0.7) * i_b);
  EXPECT_EQ(c.trapped_rocking_inertia, 0.0);
  Foundation disk = cone(nu);
  disk.radius = 2.0 * a / std::sqrt(M_PI);  // the same area
  EXPECT_NEAR(c.sway_stiffness / foundation_constants(disk).sway_stiffness, 0.99701, 1e-5);
  disk.radius = std::pow(4.0 * i_b / M_PI, 0.25);  // the same area moment
  EXPECT_NEAR(c.rocking_stiffness / foundation_constants(disk).rocking_stiffness, 0.93858, 1e-5);
}

// A 20 m x 10 m footing (L = 10 m, B = 5 m, nu = 0.4, G = 42.75 MPa) turned both ways on the
// row, worked by hand: K_y = 2 G L / 1.6 (2 + 2.5 x 0.5^0.85) = 5.34375e8 x 3.38696 = 1.80991e9
// N/m; K_x = K_y - 0.2 / 0.35 G L 0.5 = 1.80991e9 - 1.22143e8 = 1.68776e9 N/m;
// I_by = 4 B L^3 / 3 = 6666.67 m^4, I_bx = 4 L B^3 / 3 = 1666.67 m^4;
// K_ry = 3 G / 0.6 I_by^0.75 2^0.15 = 2.13750e8 x 737.788 x 1.10957 = 1.74982e11 N m/rad;
// K_rx = G / 0.6 I_bx^0.75 2^0.25 2.65 = 7.12500e7 x 260.847 x 1.18921 x 2.65
// = 5.85699e10 N m/rad.
TEST(Foundation, GazetasRectangleAlongAndAcrossTheRow) {
  const FoundationConstants along = foundation_constants(rectangle(20.0, 10.0, 0.4));
  const FoundationConstants across = foundation_constants(rectangle(10.0, 20.0, 0.4));
  EXPECT_NEAR(along.sway_stiffness, 1.68776e9, 1e-5 * 1.68776e9);        // K_x: along the long side
  EXPECT_NEAR(across.sway_stiffness, 1.80991e9, 1e-5 * 1.80991e9);       // K_y
  EXPECT_NEAR(along.rocking_stiffness, 1.74982e11, 1e-5 * 1.74982e11);   // K_ry
  EXPECT_NEAR(across.rocking_stiffness, 5.85699e10, 1e-5 * 5.85699e10);  // K_rx
  // The same area either way: one sway dashpot; rocking on the area moment about the axis
  // across the row, width length^3 / 12.
  EXPECT_EQ(along.sway_damping, across.sway_damping);
  const double v_la = 3.4 * 150.0 / (M_PI * 0.6);
  expect_close(along.rocking_damping, 1900.0 * v_la * 10.0 * 8000.0 / 12.0);
  expect_close(across.rocking_damping, 1900.0 * v_la * 20.0 * 1000.0 / 12.0);
  // Its problems name its keys; the soil's are the cone's.
  EXPECT_EQ(foundation_problem(rectangle(0.0, 10.0, 0.4), 2),
            "foundation_length must be a finite number > 0 m");
  EXPECT_EQ(foundation_problem(rectangle(20.0, -1.0, 0.4), 2),
            "foundation_width must be a finite number > 0 m");
  EXPECT_EQ(foundation_problem(rectangle(20.0, 10.0, 0.5), 2), "soil_poisson must be in [0, 0.5)");
  EXPECT_EQ(foundation_problem(rectangle(20.0, 10.0, 0.4), 2), "");
}

}  // namespace
}  // namespace pound

#pragma once
// Contact stiffness of the damped Sears model.
//
// Curved on flat or curved (Hertz, Th. 7.2; Johnson, Contact Mechanics, 1985, eq. 4.22-4.23):
//     k = (4/3) E* sqrt(R*),   1/E* = (1 - mu1^2)/E1 + (1 - mu2^2)/E2,   1/R* = 1/r1 + 1/r2,
// a flat face having r = infinity. F = k delta^1.5 [N], k in [N/m^1.5].
//
// Flat floor on flat floor (Th. 8.1-8.2): the two slabs act as axial springs in series,
//     k_L = 1 / (1/k_A,L + 1/k_A,R),   k_A,i = D E_i A_i / l_i,
// D >= 1 the fraction factor (D = 1: the whole slab length deforms). F = k_L delta [N].
// E_i here is the material modulus, not reduced by chi (thesis Table 8.2: "longitudinal floor
// stiffness" E A / l = 1.01 and 1.68 GN/m for the 20 m and 12 m slabs).
#include <limits>

#include "sears/slab.hpp"

namespace pound::sears {

/// Radius of a flat face [m].
inline constexpr double kFlatRadius = std::numeric_limits<double>::infinity();

/// Hertz stiffness k = (4/3) E* sqrt(R*) [N/m^1.5] (Th. 7.2). E in [Pa], radii in [m]
/// (kFlatRadius for a flat face; not both flat).
double hertz_stiffness(double E1_Pa, double poisson1, double r1_m, double E2_Pa, double poisson2,
                       double r2_m);

/// Axial stiffness of one slab taking part in a flat contact, D E A / l [N/m] (Th. 8.2).
double slab_axial_stiffness(double E_Pa, double area_m2, double length_m, double D);

/// Flat contact stiffness of two slabs in series, k_L [N/m] (Th. 8.1); the slabs' effective
/// areas follow from their masses, A = m / (rho l).
double flat_contact_stiffness(const Slab& left, const Slab& right, double D);

}  // namespace pound::sears

#pragma once
// The separation rules of building codes and of the pounding literature, from the peak
// displacements u_A, u_B of two adjacent buildings at one level (each computed as if the other
// were absent):
//
//   abs  (absolute sum):            g = u_A + u_B
//   srss (square root of the sum of squares; EN 1998-1 4.4.2.7(2)):  g = sqrt(u_A^2 + u_B^2)
//   ddc  (double difference combination; Jeng, Kasai & Maison 1992, Earthquake Spectra 8(2);
//         Penzien 1997, Earthquake Eng. Struct. Dyn. 26(8)):
//                                   g = sqrt(u_A^2 + u_B^2 - 2 rho u_A u_B)
//   ec8  (EN 1998-1 4.4.2.7(2)-(3)): the SRSS gap, times 0.7 where the floor elevations of the
//         two buildings coincide (every colliding floor meets a slab, slab to slab), the SRSS
//         gap itself otherwise (a slab can strike the neighbour's columns)
//
// with rho the correlation coefficient of the two buildings' first-mode responses, taken as
// the CQC modal correlation of Der Kiureghian (1981, Earthquake Eng. Struct. Dyn. 9(5),
// 419-435) for two oscillators of frequencies w_A, w_B and damping ratios xi_A, xi_B,
// r = w_B / w_A = T_A / T_B:
//
//   rho = 8 sqrt(xi_A xi_B) (xi_A + r xi_B) r^1.5
//         / ((1 - r^2)^2 + 4 xi_A xi_B r (1 + r^2) + 4 (xi_A^2 + xi_B^2) r^2)
//
// which for equal damping is 8 xi^2 (1 + r) r^1.5 / ((1 - r^2)^2 + 4 xi^2 r (1 + r)^2). The DDC
// rule is the CQC rule applied to the relative displacement u_A - u_B (Lopez-Garcia & Soong
// 2009, Probabilistic Eng. Mech. 24, call it "also known simply as the CQC rule").
#include <string>
#include <vector>

namespace pound {

/// Der Kiureghian's (1981) correlation coefficient of two modes [-]: periods [s] and damping
/// ratios [-] of the first and the second.
double cqc_correlation(double period_a, double xi_a, double period_b, double xi_b);

enum class SeparationRule { abs, srss, ddc, ec8 };
const char* to_string(SeparationRule r);  ///< "abs", "srss", "ddc", "ec8"
constexpr SeparationRule kSeparationRules[] = {SeparationRule::abs, SeparationRule::srss,
                                               SeparationRule::ddc, SeparationRule::ec8};

/// Which case of EN 1998-1 4.4.2.7(3) the ec8 rule takes for a pair.
enum class Ec8Case {
  floors_coincide,  ///< every colliding floor meets a slab, slab to slab: 0.7 x SRSS
  floors_offset,    ///< a slab strikes the neighbour's columns: SRSS
  floors_unknown,   ///< the floors' elevations could not be read: SRSS (no reduction shown)
};
/// "floors_coincide", "floors_offset", "floors_unknown" (CSV, JSON, HDF5).
const char* to_string(Ec8Case c);
/// In words: "floors coincide: 0.7 x SRSS", "floors do not coincide: SRSS", "floor levels
/// unknown: SRSS".
const char* describe(Ec8Case c);
/// The factor on the SRSS gap: 0.7 where the floors coincide, 1 otherwise [-].
double ec8_factor(Ec8Case c);

/// The rule's gap [m] for peak displacements u_a, u_b [m] (rho used by ddc only, the case by
/// ec8 only).
double separation_gap(SeparationRule r, double u_a, double u_b, double rho,
                      Ec8Case ec8 = Ec8Case::floors_offset);

}  // namespace pound

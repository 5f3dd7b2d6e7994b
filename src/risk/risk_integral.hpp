#pragma once
// The mean annual frequency of an event from its fragility and the site's hazard (PEER
// framework; Cornell et al. 2002, J. Struct. Eng. 128(4), eq. 3):
//
//   nu = integral over x of P(event | IM = x) |d lambda(x)|
//      = integral over x of lambda(x) dP(x)          (by parts: P(0) = 0, lambda(inf) = 0)
//
// For a lognormal fragility P(x) = Phi(ln(x / theta) / beta) and a hazard curve that is a power
// law on each segment, ln lambda = a + b u with u = ln x, every segment integrates in closed
// form (mu = ln theta):
//
//   int_{u1}^{u2} e^{a + b u} phi((u - mu) / beta) / beta du
//     = e^{a + b mu + b^2 beta^2 / 2} [Phi((u2 - mu - b beta^2) / beta) - Phi((u1 - mu - b beta^2)
//     / beta)]
//
// (a + b mu evaluated from the segment's own point, Segment::ln_rate(mu), without cancellation)
//
// which for one power law lambda = k0 x^-k over (0, inf) is Cornell et al.'s
// nu = k0 theta^-k exp(k^2 beta^2 / 2) (their eq. 11 with the median demand at the capacity).
//
// The part of nu from intensities in [x_lo, x_hi] is integral_lo^hi P |d lambda|; by parts
// (d lambda < 0) it is NOT the by-parts form restricted to [x_lo, x_hi] but
//
//   integral_lo^hi P |d lambda| = integral_lo^hi lambda dP + P(x_lo) lambda(x_lo)
//                                                          - P(x_hi) lambda(x_hi)
//
// (the boundary terms vanish only at x_lo = 0 and x_hi = inf), so the pieces of any partition
// of (0, inf) add up to nu.
//
// The probability of at least one event in T years (Poisson) is 1 - exp(-nu T).
#include <limits>

#include "risk/hazard_curve.hpp"

namespace pound {

/// nu [1/yr] of a lognormal fragility (theta [m/s^2], beta > 0) on the hazard curve; with
/// x_lo, x_hi [m/s^2] the part of nu from the events whose intensity lies between them,
/// integral_lo^hi P(x) |d lambda(x)| (by parts with the boundary terms above; 0 when
/// x_hi <= x_lo): to tell how much of nu comes from intensities a campaign did not simulate.
double mean_annual_frequency(const HazardCurve& h, double theta, double beta, double x_lo = 0.0,
                             double x_hi = std::numeric_limits<double>::infinity());

/// 1 - exp(-nu T): the probability of at least one occurrence in `years` (Poisson arrivals).
double probability_in_years(double maf, double years);

}  // namespace pound

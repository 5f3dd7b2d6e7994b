#pragma once
// Relations between a model's damping parameter and the coefficient of restitution e.
#include <string>

namespace pound {

/// LVe damping ratio (Anagnostopoulos 1988): xi = -ln e / sqrt(pi^2 + (ln e)^2). Exact for the
/// linear spring-dashpot contact separating at delta = 0 (the published criterion).
double lve_damping_ratio(double e);

/// Exact restitution of a contact with a linear spring and an approach-only dashpot of ratio
/// xi (MLVe): e = exp(-xi acos(xi)/sqrt(1-xi^2)) for xi < 1, exp(-1) at xi = 1,
/// exp(-xi acosh(xi)/sqrt(xi^2-1)) for xi > 1 (physics.md section 2).
double mlve_restitution(double xi);
/// Inverse of mlve_restitution by bracketed root finding: xi giving restitution e.
double mlve_damping_ratio_exact(double e);
/// Mahmoud & Jankowski (2011) closed-form approximation (Th. 3.2a as cited by Khatami et al.
/// 2019): xi = (1 - e^2) / (e (e (pi - 2) + 2)). Within about 3 % of the exact e.
double mlve_damping_ratio_published(double e);

/// NlVe damping ratio (Jankowski 2005): xi = (9 sqrt(5) / 2) (1 - e^2) / (e (e (9 pi - 16) + 16)).
double nlve_damping_ratio(double e);

/// Exact Hunt-Crossley damping factor a(e) (Khatiwada et al. 2014; Th. 4.20): the root of
/// (1 + e) a = ln((1 + a) / (1 - e a)) with 0 < a < 1/e; a = 0 for e = 1. Independent of the
/// force exponent, stiffness, masses and v0.
double hunt_crossley_factor(double e);

/// Validates e in (0, 1]; throws InputError naming `where` otherwise.
void check_restitution(double e, const std::string& where);

}  // namespace pound

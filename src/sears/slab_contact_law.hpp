#pragma once
// The contact force between two slab faces in the damped Sears model (physics.md section 3):
//     flat  (Th. 8.1): F = k_L delta
//     hertz (Th. 7.1): F = k delta^1.5
// for overlap delta > 0, F = 0 otherwise (never tensile), then F = min(F, PF_max) when a force
// cap is given (Th. 9.1). There is no dashpot: the model loses energy only through the damped
// internal vibration of the bars, and, with a cap, through crushing faces (issue 36; the same
// rule as the lumped laws' [contact] force_cap, docs/sears.md "The force cap"): where the law's
// own penetration would pass d_cap = (PF_max / k)^(1/p), the excess becomes a permanent
// indentation c (crush_increment), which the caller adds to the site's gap, so that the law
// never holds more than its elastic energy up to d_cap and the work PF_max x c is dissipated.
// Where a slab strikes the neighbour's columns (issue 36; docs/contact-geometry.md), the
// columns' point stiffness k_col acts in series with the law: the law sees its own penetration
// delta_c = delta - F / k_col (series_compliance_m_per_N = 1 / k_col; 0 at a slab site).
#include <limits>

namespace pound::sears {

enum class ContactKind { flat, hertz };

struct SlabContactLaw {
  ContactKind kind = ContactKind::flat;
  double stiffness = 0.0;  ///< k_L [N/m] (flat) or k [N/m^1.5] (hertz)
  double force_cap_N = std::numeric_limits<double>::infinity();  ///< PF_max [N]
  /// 1 / k_col of the struck columns in series with the law [m/N]; 0 at a slab site.
  double series_compliance_m_per_N = 0.0;

  /// Exponent of the force-overlap law: 1 (flat) or 1.5 (hertz).
  double exponent() const { return kind == ContactKind::flat ? 1.0 : 1.5; }
  /// Contact force [N] for the law's own penetration delta [m] (no series spring).
  double force(double delta_m) const;
  /// Stored contact energy, the integral of force(delta) from 0 to delta [J] (no series spring).
  double potential(double delta_m) const;
  /// Solves F = force(delta_pred - (S + c) F) for F >= 0, c = series_compliance_m_per_N: the
  /// force at the end of a step whose overlap is an affine function of that force, delta =
  /// delta_pred - S F, with S > 0 the step compliance [m/N], the law seeing delta - c F (a
  /// column in series). Unique because force() is non-decreasing. [N]
  double solve_implicit(double delta_pred_m, double compliance_m_per_N) const;
  /// Crushing (issue 36): the growth of the permanent indentation [m] at the end of a step whose
  /// overlap, measured from the gap already widened by the indentation, is delta [m] and whose
  /// force is F [N]. Zero unless F is at the cap and the law's own penetration delta - F c (c =
  /// series_compliance_m_per_N) passes d_cap; otherwise that excess, so that the law's own
  /// penetration after the step is d_cap (force(d_cap) = PF_max).
  double crush_increment(double delta_m, double force_N) const;
  /// Duration of an elastic lumped-mass impact with reduced mass m* [kg] at approach velocity
  /// v0 [m/s], ignoring the cap: pi sqrt(m*/k) (flat, k in series with the column: 1 / (1/k +
  /// c)) or 2.9432 delta_max / v0 with delta_max = (5 m* v0^2 / (4 k))^(2/5) (hertz, without
  /// the column, which only lengthens it; Goldsmith, Impact, 1960, sec. 4.2) [s].
  double lumped_duration(double reduced_mass_kg, double v0_m_s) const;
};

/// Throws InputError unless the stiffness is finite and > 0 and the cap is > 0.
void validate(const SlabContactLaw& law);

}  // namespace pound::sears

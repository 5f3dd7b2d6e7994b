#include "sears/slab_contact_law.hpp"

#include <cmath>

#include "core/error.hpp"

namespace pound::sears {

double SlabContactLaw::force(double delta_m) const {
  if (!(delta_m > 0.0)) return 0.0;
  const double f =
      kind == ContactKind::flat ? stiffness * delta_m : stiffness * delta_m * std::sqrt(delta_m);
  return std::fmin(f, force_cap_N);
}

double SlabContactLaw::potential(double delta_m) const {
  if (!(delta_m > 0.0)) return 0.0;
  const double p = exponent();
  // Overlap at which the cap is reached, then elastic part plus a constant-force part.
  const double d_cap =
      std::isinf(force_cap_N) ? delta_m : std::pow(force_cap_N / stiffness, 1.0 / p);
  const double d_el = std::fmin(delta_m, d_cap);
  const double e_el = stiffness * std::pow(d_el, p + 1.0) / (p + 1.0);
  return delta_m > d_cap ? e_el + force_cap_N * (delta_m - d_cap) : e_el;
}

double SlabContactLaw::solve_implicit(double delta_pred_m, double S_step) const {
  if (!(delta_pred_m > 0.0)) return 0.0;
  // A column in series (issue 36): delta_c + F / k_col + S F = delta_pred, so the column's
  // compliance adds to the step's. For a Hertz law this is the scalar root of
  // contact/column_series.hpp (SeriesHertz: delta_c + F(delta_c) / k_col = delta) with the
  // step's compliance beside the column's; a flat law gets k k_col / (k + k_col).
  // (At a slab site c = 0 and S_step > 0: S_step + 0 is S_step.)
  const double S = S_step + series_compliance_m_per_N;
  double f = 0.0;
  if (kind == ContactKind::flat) {
    f = stiffness * delta_pred_m / (1.0 + stiffness * S);
  } else {
    // h(d) = d + S k d^1.5 - delta_pred is convex and increasing on d >= 0; Newton from
    // d = delta_pred (where h >= 0) decreases monotonically to the root in (0, delta_pred].
    double d = delta_pred_m;
    for (int it = 0; it < 100; ++it) {
      const double s = std::sqrt(d);
      const double h = d + S * stiffness * d * s - delta_pred_m;
      const double step = h / (1.0 + 1.5 * S * stiffness * s);
      d -= step;
      if (!(d > 0.0)) d = 0.5 * (d + step);  // stay inside (0, delta_pred]
      if (std::fabs(step) <= 1e-15 * d) break;
    }
    f = stiffness * d * std::sqrt(d);
  }
  return std::fmin(f, force_cap_N);
}

double SlabContactLaw::crush_increment(double delta_m, double force_N) const {
  if (std::isinf(force_cap_N) || !(force_N >= force_cap_N)) return 0.0;
  const double d_cap = std::pow(force_cap_N / stiffness, 1.0 / exponent());
  const double d_law = delta_m - force_N * series_compliance_m_per_N;
  return d_law > d_cap ? d_law - d_cap : 0.0;
}

double SlabContactLaw::lumped_duration(double m_red, double v0) const {
  if (kind == ContactKind::flat) {
    const double c = series_compliance_m_per_N;
    return M_PI * std::sqrt(c > 0.0 ? m_red * (1.0 / stiffness + c) : m_red / stiffness);
  }
  const double delta_max = std::pow(5.0 * m_red * v0 * v0 / (4.0 * stiffness), 0.4);
  return 2.9432 * delta_max / v0;
}

void validate(const SlabContactLaw& law) {
  if (!(std::isfinite(law.stiffness) && law.stiffness > 0.0))
    throw InputError("contact stiffness must be finite and > 0");
  if (!(law.force_cap_N > 0.0)) throw InputError("force cap must be > 0 [N]");
  if (!(law.series_compliance_m_per_N >= 0.0 && std::isfinite(law.series_compliance_m_per_N)))
    throw InputError("column compliance must be finite and >= 0 [m/N]");
}

}  // namespace pound::sears

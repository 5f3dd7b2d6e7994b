#include "contact/column_series.hpp"

#include <cmath>

namespace pound {

std::unique_ptr<ContactLaw> column_law(const ContactModelInfo& info, ContactParameters p,
                                       double k_col) {
  if (!std::isfinite(k_col) || info.stiffness_unit.empty()) return info.make(p);
  if (info.stiffness_unit == "N/m") {
    p.k = p.k * k_col / (p.k + k_col);  // springs in series
    return info.make(p);
  }
  return std::make_unique<SeriesHertz>(info.make(p), k_col);
}

// The inner law at its own penetration dc, with the approach rate shared between the law
// (tangent k_t) and the column (k_col) as two springs in series share it.
double SeriesHertz::inner_force(double dc, double ddelta, double v0) const {
  if (!(dc > 0.0)) return inner_->force(dc, ddelta, v0);
  const double kt = 1.5 * inner_->force(dc, 0.0, v0) / dc;
  return inner_->force(dc, ddelta * k_col_ / (k_col_ + kt), v0);
}

double SeriesHertz::law_penetration(double delta, double ddelta, double v0) const {
  if (!(delta > 0.0)) return delta;
  // g(dc) = dc + F(dc) / k_col - delta on [0, delta]: g(0) = -delta, g(delta) = F / k_col >= 0.
  double a = 0.0, fa = -delta, b = delta;
  double fb = inner_force(delta, ddelta, v0) / k_col_;
  if (!(fb > 0.0)) return delta;
  int side = 0;
  for (int it = 0; it < 200; ++it) {
    const double c = (a * fb - b * fa) / (fb - fa);
    const double fc = c + inner_force(c, ddelta, v0) / k_col_ - delta;
    if (std::fabs(fc) <= 1e-14 * delta || b - a <= 1e-15 * delta) return c;
    if (fc > 0.0) {
      b = c;
      fb = fc;
      if (side == 1) fa *= 0.5;  // Illinois: halve the stale end's value
      side = 1;
    } else {
      a = c;
      fa = fc;
      if (side == -1) fb *= 0.5;
      side = -1;
    }
  }
  return 0.5 * (a + b);
}

double SeriesHertz::force(double delta, double ddelta, double v0) const {
  return inner_force(law_penetration(delta, ddelta, v0), ddelta, v0);
}

}  // namespace pound

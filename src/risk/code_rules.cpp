#include "risk/code_rules.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pound {

double cqc_correlation(double period_a, double xi_a, double period_b, double xi_b) {
  // Der Kiureghian (1981), the general form (header); r = w_b / w_a.
  const double r = period_a / period_b;
  const double num = 8.0 * std::sqrt(xi_a * xi_b) * (xi_a + r * xi_b) * std::pow(r, 1.5);
  const double den = std::pow(1.0 - r * r, 2) + 4.0 * xi_a * xi_b * r * (1.0 + r * r) +
                     4.0 * (xi_a * xi_a + xi_b * xi_b) * r * r;
  return num / den;
}

const char* to_string(SeparationRule r) {
  switch (r) {
    case SeparationRule::abs:
      return "abs";
    case SeparationRule::srss:
      return "srss";
    case SeparationRule::ddc:
      return "ddc";
  }
  throw std::logic_error("unknown separation rule");
}

double separation_gap(SeparationRule r, double u_a, double u_b, double rho) {
  switch (r) {
    case SeparationRule::abs:
      return u_a + u_b;
    case SeparationRule::srss:
      return std::sqrt(u_a * u_a + u_b * u_b);
    case SeparationRule::ddc:  // Jeng et al. (1992), Penzien (1997)
      return std::sqrt(std::max(0.0, u_a * u_a + u_b * u_b - 2.0 * rho * u_a * u_b));
  }
  throw std::logic_error("unknown separation rule");
}

}  // namespace pound

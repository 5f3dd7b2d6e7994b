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
    case SeparationRule::ec8:
      return "ec8";
  }
  throw std::logic_error("unknown separation rule");
}

const char* to_string(Ec8Case c) {
  switch (c) {
    case Ec8Case::floors_coincide:
      return "floors_coincide";
    case Ec8Case::floors_offset:
      return "floors_offset";
    case Ec8Case::floors_unknown:
      return "floors_unknown";
  }
  throw std::logic_error("unknown EC8 case");
}

const char* describe(Ec8Case c) {
  switch (c) {
    case Ec8Case::floors_coincide:
      return "floors coincide: 0.7 x SRSS";
    case Ec8Case::floors_offset:
      return "floors do not coincide: SRSS";
    case Ec8Case::floors_unknown:
      return "floor levels unknown: SRSS";
  }
  throw std::logic_error("unknown EC8 case");
}

double ec8_factor(Ec8Case c) {
  // EN 1998-1 4.4.2.7(3): where the floor elevations of the adjacent buildings coincide, the
  // separation of 4.4.2.7(2) (the SRSS of the peak displacements) may be reduced by 0.7.
  return c == Ec8Case::floors_coincide ? 0.7 : 1.0;
}

double separation_gap(SeparationRule r, double u_a, double u_b, double rho, Ec8Case ec8) {
  switch (r) {
    case SeparationRule::abs:
      return u_a + u_b;
    case SeparationRule::srss:
      return std::sqrt(u_a * u_a + u_b * u_b);
    case SeparationRule::ddc:  // Jeng et al. (1992), Penzien (1997)
      return std::sqrt(std::max(0.0, u_a * u_a + u_b * u_b - 2.0 * rho * u_a * u_b));
    case SeparationRule::ec8:  // EN 1998-1 4.4.2.7(2)-(3): SRSS, x 0.7 where floors coincide
      return ec8_factor(ec8) * std::sqrt(u_a * u_a + u_b * u_b);
  }
  throw std::logic_error("unknown separation rule");
}

}  // namespace pound

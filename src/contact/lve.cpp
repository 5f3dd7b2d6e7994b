#include "contact/lve.hpp"

#include <cmath>

#include "contact/restitution.hpp"

namespace pound {

LinearViscoelastic::LinearViscoelastic(const ContactParameters& p)
    : k_(p.k), c_(2.0 * lve_damping_ratio(p.e) * std::sqrt(p.k * reduced_mass(p.m1, p.m2))) {}

// Th. 3.1: F = k delta + c ddelta (tension kept, as published).
double LinearViscoelastic::force(double delta, double ddelta, double) const {
  return k_ * delta + c_ * ddelta;
}

}  // namespace pound

#pragma once
// A contact law in series with the struck columns' stiffness (issue 36; physics.md section
// 5b): where a slab strikes the neighbour's columns between its floors, the columns' point
// stiffness k_col (structure/contact_geometry.hpp) acts in series with the contact spring.
//   - Linear laws (k in N/m: lve, mlve, kelvin-ye, hc-linear) take k_eff = k k_col / (k +
//     k_col); their damping then follows from e and k_eff by each law's own formula.
//   - Hertz-type laws (k in N/m^1.5: nlve, hertzdamp, hertzdamp-ye, hc-hertz): SeriesHertz
//     below finds the force at which the law's own penetration plus F / k_col equals the
//     approach delta (a scalar root).
//   - The stereomechanical law has no force history: k_col plays no part.
// Kernel only: no files, no printing.
#include <memory>

#include "contact/contact_law.hpp"
#include "contact/registry.hpp"

namespace pound {

/// The law of `info` with parameters p (k, e, the sides' apparent masses m1, m2) in series with
/// a column of stiffness k_col [N/m]; infinite k_col (a slab site): info.make(p) itself.
std::unique_ptr<ContactLaw> column_law(const ContactModelInfo& info, ContactParameters p,
                                       double k_col);

/// A Hertz-type law (force ~ delta^1.5) in series with a linear spring k_col [N/m]. With the
/// approach delta and its rate ddelta, the law's own penetration delta_c in (0, delta] solves
///   delta_c + F(delta_c, r_c, v0) / k_col = delta,
/// where F is the inner law and its rate r_c = ddelta k_col / (k_col + k_t) is the approach rate
/// shared as the elastic tangent stiffnesses share it (k_t = 1.5 F(delta_c, 0, v0) / delta_c,
/// the law's elastic part's tangent). The root is bracketed by g(0) = -delta < 0 and g(delta) =
/// F / k_col >= 0 and found by the Illinois method to 1e-14 delta. The spring stores F^2 /
/// (2 k_col) and gives it back: the contact work F ddelta still closes the energy ledger.
class SeriesHertz : public ContactLaw {
 public:
  SeriesHertz(std::unique_ptr<ContactLaw> inner, double k_col)
      : inner_(std::move(inner)), k_col_(k_col) {}
  double force(double delta, double ddelta, double v0) const override;
  /// The inner law's penetration delta_c at approach delta and rate ddelta [m].
  double law_penetration(double delta, double ddelta, double v0) const;

 private:
  double inner_force(double dc, double ddelta, double v0) const;
  std::unique_ptr<ContactLaw> inner_;
  double k_col_;  // [N/m]
};

}  // namespace pound

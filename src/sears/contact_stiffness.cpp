#include "sears/contact_stiffness.hpp"

#include <cmath>

#include "core/error.hpp"

namespace pound::sears {

double hertz_stiffness(double E1_Pa, double poisson1, double r1_m, double E2_Pa, double poisson2,
                       double r2_m) {
  if (!(E1_Pa > 0 && E2_Pa > 0 && r1_m > 0 && r2_m > 0))
    throw InputError("Hertz contact: moduli and radii must be > 0");
  if (std::isinf(r1_m) && std::isinf(r2_m))
    throw InputError("Hertz contact: at least one face must be curved (radius1 or radius2)");
  const double inv_E = (1.0 - poisson1 * poisson1) / E1_Pa + (1.0 - poisson2 * poisson2) / E2_Pa;
  const double inv_R = 1.0 / r1_m + 1.0 / r2_m;  // 1/inf = 0 for a flat face
  return (4.0 / 3.0) * (1.0 / inv_E) * std::sqrt(1.0 / inv_R);
}

double slab_axial_stiffness(double E_Pa, double area_m2, double length_m, double D) {
  return D * E_Pa * area_m2 / length_m;
}

double flat_contact_stiffness(const Slab& left, const Slab& right, double D) {
  const double kl = slab_axial_stiffness(left.E_Pa, left.area_m2(), left.length_m, D);
  const double kr = slab_axial_stiffness(right.E_Pa, right.area_m2(), right.length_m, D);
  return 1.0 / (1.0 / kl + 1.0 / kr);
}

}  // namespace pound::sears

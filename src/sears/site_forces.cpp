#include "sears/site_forces.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"

namespace pound::sears {

void solve_site_forces(const std::vector<SlabContactLaw>& laws, const Eigen::MatrixXd& S,
                       const Eigen::VectorXd& delta_pred, const std::vector<char>& frozen,
                       Eigen::VectorXd& F) {
  const int n = static_cast<int>(F.size());
  for (int it = 0; it < 500; ++it) {
    double change = 0.0, scale = 1e-300;
    for (int s = 0; s < n; ++s) {
      if (frozen[s]) continue;
      const double r = delta_pred(s) - S.row(s).dot(F) + S(s, s) * F(s);
      const double f = laws[s].solve_implicit(r, S(s, s));
      change = std::max(change, std::fabs(f - F(s)));
      scale = std::max(scale, f);
      F(s) = f;
    }
    if (change <= 1e-13 * scale) return;
  }
  throw NumericalError("damped Sears model: contact forces did not converge in 500 sweeps");
}

}  // namespace pound::sears

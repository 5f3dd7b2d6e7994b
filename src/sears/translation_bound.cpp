#include "sears/translation_bound.hpp"

#include <algorithm>
#include <cmath>

namespace pound::sears {

TranslationBound::TranslationBound(const AssembledRow& a, double ag_max)
    : K_(a.K), M_(a.M), ag_max_(std::fabs(ag_max)) {
  const int n = a.dofs(), nb = static_cast<int>(a.offset.size());
  building_of_.assign(n, 0);
  for (int b = 0; b < nb; ++b) {
    const int end = b + 1 < nb ? a.offset[b + 1] : n;
    begin_.push_back(a.offset[b]);
    size_.push_back(end - a.offset[b]);
    double m = 0.0;
    for (int k = a.offset[b]; k < end; ++k) {
      building_of_[k] = b;
      m += a.M(k, k);
    }
    sqrt_mass_.push_back(std::sqrt(m));
  }
  sqrt2E_.assign(nb, 0.0);
  // alpha_k^2 = e_k^T M^-1 K M^-1 e_k; beta_k^2 = e_k^T M^-1 C M^-1 C M^-1 e_k (M diagonal).
  G_.resize(n);
  for (int k = 0; k < n; ++k) {
    const double ik = a.inv_mass(k);
    const double alpha2 = ik * ik * a.K(k, k);
    double beta2 = 0.0;
    for (int j = 0; j < n; ++j) beta2 += a.C(j, k) * a.C(j, k) * a.inv_mass(j);
    beta2 *= ik * ik;
    G_(k) = std::sqrt(alpha2 + beta2);
  }
}

void TranslationBound::set_state(const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                 const std::vector<double>& strain) {
  for (std::size_t b = 0; b < begin_.size(); ++b) {
    const int o = begin_[b], m = size_[b];
    const bool own = !strain.empty() && strain[b] >= 0.0;
    double twoE = own ? 2.0 * strain[b] : 0.0;
    for (int i = o; i < o + m; ++i) {
      twoE += M_(i, i) * v(i) * v(i);
      if (!own)
        for (int j = o; j < o + m; ++j) twoE += u(i) * K_(i, j) * u(j);
    }
    sqrt2E_[b] = std::sqrt(std::max(0.0, twoE));
  }
}

double TranslationBound::approach(int l, int r, const Eigen::VectorXd& v, double h) const {
  auto accel = [&](int k) {
    const int b = building_of_[k];
    return G_(k) * (sqrt2E_[b] + sqrt_mass_[b] * ag_max_ * h);
  };
  return std::max(0.0, v(l) - v(r)) * h + 0.5 * h * h * (accel(l) + accel(r));
}

}  // namespace pound::sears

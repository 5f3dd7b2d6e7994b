#include "sears/translation_bound.hpp"

#include <algorithm>
#include <cmath>

namespace pound::sears {

namespace {

// Gershgorin's bound on the largest eigenvalue of M^-1/2 A M^-1/2 for the DOFs `d` of a
// symmetric A [1/s^2].
double largest_eigenvalue_bound(const AssembledRow& a, const Eigen::MatrixXd& A,
                                const std::vector<int>& d) {
  double lam = 0.0;
  for (int i : d) {
    double row = 0.0;
    for (int j : d) row += std::fabs(A(i, j)) * std::sqrt(a.inv_mass(i) * a.inv_mass(j));
    lam = std::max(lam, row);
  }
  return lam;
}

}  // namespace

TranslationBound::TranslationBound(const AssembledRow& a, double ag_max)
    : K_(a.K),
      Kg_(a.Kg.size() ? a.Kg : Eigen::MatrixXd::Zero(a.dofs(), a.dofs())),
      M_(a.M),
      ag_max_(std::fabs(ag_max)) {
  const int n = a.dofs(), nb = static_cast<int>(a.offset.size());
  building_of_.assign(n, 0);
  influence_.assign(n, 1.0);
  for (int k = 0; k < n && a.influence.size() == n; ++k) influence_[k] = a.influence(k);
  dofs_.assign(nb, {});
  const int floors = a.floors > 0 ? a.floors : n;  // (a row built by hand has floors only)
  for (int b = 0; b < nb; ++b) {
    const int end = b + 1 < nb ? a.offset[b + 1] : floors;
    for (int k = a.offset[b]; k < end; ++k) dofs_[b].push_back(k);
  }
  // A flexible foundation's sway and rotation belong to their building (issue 29).
  for (int k = floors; k < n; ++k) dofs_[a.building_of[k]].push_back(k);
  for (int b = 0; b < nb; ++b) {
    // The translating mass: the earthquake's load on the building is -ag sum m (influence 1).
    double m = 0.0;
    for (int k : dofs_[b]) {
      building_of_[k] = b;
      if (a.influence.size() != n || a.influence(k) != 0.0) m += a.M(k, k);
    }
    sqrt_mass_.push_back(std::sqrt(m));
  }
  std::vector<int> massless;
  for (int k = 0; k < n; ++k)
    if (!(a.M(k, k) > 0.0)) massless.push_back(k);
  sqrt2E_.assign(nb, 0.0);
  own_.assign(nb, 0);
  omega_g_.assign(nb, 0.0);
  // Per building: w_g of P-Delta, and with tangent damping the bound beta_t of its damping
  // forces (translation_bound.hpp).
  std::vector<double> lambda0(nb, 0.0), a0(nb, 0.0), a1(nb, 0.0);
  std::vector<char> tangent(nb, 0);
  const Eigen::MatrixXd K0 = a.K + Kg_;
  for (int b = 0; b < nb; ++b) {
    omega_g_[b] = std::sqrt(largest_eigenvalue_bound(a, Kg_, dofs_[b]));
    lambda0[b] = largest_eigenvalue_bound(a, K0, dofs_[b]);
  }
  for (int k = 0; k < n && static_cast<int>(a.storeys.size()) == n; ++k) {
    const RowStorey& st = a.storeys[k];
    if (!(st.damping_a1 > 0.0)) continue;
    tangent[st.building] = 1;
    a1[st.building] = st.damping_a1;
    a0[st.building] = (a.C(k, k) - st.damping_a1 * K0(k, k)) * a.inv_mass(k);  // C = a0 M + a1 K0
  }
  // alpha_k^2 = e_k^T M^-1 K M^-1 e_k; beta_k^2 = e_k^T M^-1 C M^-1 C M^-1 e_k (M diagonal).
  G_.resize(n);
  G_own_.resize(n);
  for (int k = 0; k < n; ++k) {
    const double ik = a.inv_mass(k);
    const double alpha2 = ik * ik * a.K(k, k);
    double beta2 = 0.0;
    for (int j = 0; j < n; ++j) beta2 += a.C(j, k) * a.C(j, k) * a.inv_mass(j);
    beta2 *= ik * ik;
    const int b = building_of_[k];
    if (tangent[b]) {
      const double beta_t = a0[b] * std::sqrt(ik) + a1[b] * std::sqrt(K0(k, k) * lambda0[b]) * ik;
      beta2 = std::max(beta2, beta_t * beta_t);
    }
    G_(k) = std::sqrt(alpha2 + beta2);
    if (Kg_(k, k) != 0.0) {
      const double alpha02 = ik * ik * K0(k, k), gamma2 = ik * ik * Kg_(k, k);
      G_own_(k) = std::sqrt(alpha02 + gamma2 + beta2);
    } else {
      G_own_(k) = G_(k);
    }
  }
  if (!massless.empty()) massless_bounds(a, massless, K0);
}

// A massless base (issue 29): its DOFs b are first-order, C_bb v_b = -(C_ba v_a + f_b), so a
// floor k's absolute acceleration is -(1/m_k) [C*_ka v_a + f_k - (C_kb S) f_b] with S = C_bb^-1
// and C* = C_aa - C_ab S C_ba (positive semi-definite). With T = v_a^T M_a v_a / 2 (the massless
// DOFs carry no kinetic energy) and U the storeys' and springs' energy, E = T + U still grows
// only by the ground's work. Then
//   |C*_ka v_a| / m_k <= beta*_k sqrt(2 T),  beta*_k^2 = sum_j (C*_kj / m_k)^2 / m_j,
//   linear: |(K_k - C_kb S K_b) q| / m_k <= alpha*_k sqrt(2 U),
//           alpha*_k^2 = w K^-1 w^T / m_k^2, w = K_k - C_kb S K_b (K positive definite);
//   yielding: |f_k| / m_k <= alpha0_k sqrt(2 U) as above, and |(C_kb S f_b)| / m_k <= kappa_k
//           sqrt(2 U) with |f_b,i| <= sum_s |g_s,i| |V_s| and |V_s| <= sqrt(k0_s) sqrt(2 U_s).
// Tangent damping (C changes with the branches, and S with it) and P-Delta (its energy's growth
// rests on the velocities of every DOF it couples) are outside this proof: such a row is left
// without a valid bound (valid() false: its stretches without contact are tested on their own
// motion instead, sears/sears_located.cpp).
void TranslationBound::massless_bounds(const AssembledRow& a, const std::vector<int>& bs,
                                       const Eigen::MatrixXd& K0) {
  const int n = a.dofs(), m = static_cast<int>(bs.size());
  for (int k = 0; k < n && valid_; ++k)
    if (static_cast<int>(a.storeys.size()) == n &&
        (a.storeys[k].damping_a1 > 0.0 || a.storeys[k].kg != 0.0))
      valid_ = false;
  if (!valid_) return;
  std::vector<char> is_b(n, 0);
  for (int b : bs) is_b[b] = 1;
  Eigen::MatrixXd Cbb(m, m), Cb(m, n), Kb(m, n);
  for (int i = 0; i < m; ++i) {
    Cb.row(i) = a.C.row(bs[i]);
    Kb.row(i) = a.K.row(bs[i]);
    for (int j = 0; j < m; ++j) Cbb(i, j) = a.C(bs[i], bs[j]);
  }
  const Eigen::MatrixXd S = Cbb.inverse();
  const Eigen::LDLT<Eigen::MatrixXd> Kf(a.K);
  // Per massless DOF i: sum_s |g_s,i| sqrt(k0_s) over the storeys and springs acting on it.
  Eigen::VectorXd F = Eigen::VectorXd::Zero(m);
  for (int s = 0; s < n && static_cast<int>(a.storeys.size()) == n; ++s) {
    const RowStorey& st = a.storeys[s];
    const double r = std::sqrt(st.p.k0);
    for (int i = 0; i < m; ++i) {
      if (s == bs[i]) F(i) += r;
      if (st.below == bs[i]) F(i) += r;
      if (st.rot == bs[i]) F(i) += st.p.h * r;
    }
  }
  for (int k = 0; k < n; ++k) {
    if (is_b[k]) {
      G_(k) = G_own_(k) = 0.0;  // no contact acts on a base DOF
      continue;
    }
    const double ik = a.inv_mass(k);
    Eigen::RowVectorXd ckb(m);
    for (int i = 0; i < m; ++i) ckb(i) = a.C(k, bs[i]);
    const Eigen::RowVectorXd cs = ckb * S;
    const Eigen::RowVectorXd cstar = a.C.row(k) - cs * Cb;
    double beta2 = 0.0;
    for (int j = 0; j < n; ++j)
      if (!is_b[j]) beta2 += cstar(j) * cstar(j) * a.inv_mass(j);
    beta2 *= ik * ik;
    const Eigen::RowVectorXd w = a.K.row(k) - cs * Kb;
    const double alpha2 = ik * ik * w.dot(Kf.solve(w.transpose()).transpose());
    G_(k) = std::sqrt(std::max(0.0, alpha2) + beta2);
    double kappa = 0.0;
    for (int i = 0; i < m; ++i) kappa += std::fabs(cs(i)) * F(i);
    G_own_(k) = std::sqrt(ik * ik * K0(k, k) + beta2) + ik * kappa;
  }
}

void TranslationBound::set_state(const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                                 const std::vector<double>& strain) {
  for (std::size_t b = 0; b < dofs_.size(); ++b) {
    const std::vector<int>& d = dofs_[b];
    const bool own = !strain.empty() && strain[b] >= 0.0;
    own_[b] = own;
    double twoE = own ? 2.0 * strain[b] : 0.0;
    for (int i : d) {
      twoE += M_(i, i) * v(i) * v(i);
      if (!own)
        for (int j : d) twoE += u(i) * K_(i, j) * u(j);
      else if (omega_g_[b] > 0.0)  // P-Delta: E' = T + U + G
        for (int j : d) twoE += u(i) * Kg_(i, j) * u(j);
    }
    sqrt2E_[b] = std::sqrt(std::max(0.0, twoE));
  }
}

double TranslationBound::accel(int k, double h) const {
  const int b = building_of_[k];
  if (own_[b] && omega_g_[b] > 0.0) {  // P-Delta on yielding storeys: E' may grow
    const double w = omega_g_[b], c = sqrt_mass_[b] * ag_max_ / w;
    return G_own_(k) * ((sqrt2E_[b] + c) * std::exp(w * h) - c);
  }
  return (own_[b] ? G_own_(k) : G_(k)) * (sqrt2E_[b] + sqrt_mass_[b] * ag_max_ * h);
}

double TranslationBound::approach(int l, int r, const Eigen::VectorXd& v, double ground_rate,
                                  double h) const {
  return std::max(0.0, v(l) - v(r) + ground_rate) * h + 0.5 * h * h * (accel(l, h) + accel(r, h));
}

double TranslationBound::approach(const SitePoint& l, const SitePoint& r, const Eigen::VectorXd& v,
                                  double ground_rate, double h) const {
  // Per side sum |w_k| A_k and the ground's share |1 - sum w_k i_k| |ag|_max
  // (translation_bound.hpp); a slab (one DOF, w = 1, i = 1) gives A_k and 0, as approach(int,
  // int) does.
  auto side = [&](const SitePoint& p) {
    double a = std::fabs(p.weight[0]) * accel(p.dof[0], h);
    double wi = p.weight[0] * influence_[p.dof[0]];
    for (int k = 1; k < p.count; ++k) {
      a += std::fabs(p.weight[k]) * accel(p.dof[k], h);
      wi += p.weight[k] * influence_[p.dof[k]];
    }
    return wi != 1.0 ? a + std::fabs(1.0 - wi) * ag_max_ : a;
  };
  const double rate = l.of(v.data()) - r.of(v.data()) + ground_rate;
  return std::max(0.0, rate) * h + 0.5 * h * h * (side(l) + side(r));
}

}  // namespace pound::sears

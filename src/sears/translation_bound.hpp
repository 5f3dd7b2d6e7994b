#pragma once
// Rigorous bound on how far two floors of neighbouring buildings can approach each other within
// the next h seconds while no contact acts (event-driven stepping of the damped Sears model,
// docs/speed.md). Buildings are linear (physics.md section 1): M u'' + C u' + K u = -M 1 ag.
//
// Per building b, E_b = (v^T M v + u^T K u) / 2 obeys dE_b/dt = -v^T C v - ag v^T M 1
// <= |ag| sqrt(2 m_b E_b) (C positive semi-definite, Cauchy-Schwarz), so
//     sqrt(2 E_b(t + tau)) <= sqrt(2 E_b(t)) + sqrt(m_b) |ag|_max tau.
// Floor k's acceleration relative to the ground plus ag is -(M^-1 (C v + K u))_k, and
//     |(M^-1 K u)_k| <= alpha_k sqrt(u^T K u),  alpha_k = |K^1/2 M^-1 e_k|
//     |(M^-1 C v)_k| <= beta_k sqrt(v^T M v),   beta_k = |M^-1/2 C M^-1 e_k|
// hence |u_k'' + ag| <= G_k sqrt(2 E_b), G_k = sqrt(alpha_k^2 + beta_k^2). For floors L, R of
// two buildings the absolute approach x = (u_L + ug_L) - (u_R + ug_R) has x'' = (u_L'' + ag_L) -
// (u_R'' + ag_R) (each building on its own ground, issue 28), and Taylor's theorem gives
//     x(t + tau) - x(t) <= max(0, x'(t)) h + h^2/2 (A_L + A_R)
// for 0 <= tau <= h, A_k the acceleration bound above at the largest energy in the step.
// A side of a site is a point u = sum w_k u_k of its building's DOFs (SitePoint; a slab: its
// floor, w = 1; a struck column point, issue 36: its two floors, or one floor and the ground on a
// fixed base, and a rocking base's rotation). With the DOFs' ground influences i_k (1 for a
// floor or a base's sway, 0 for its rotation), its absolute acceleration is sum w_k (u_k'' + i_k
// ag) + (1 - sum w_k i_k) ag, so the bound takes sum |w_k| A_k + |1 - sum w_k i_k| |ag|_max per
// side; a slab's second term is 0.
// Yielding storeys (hysteresis/storey_law.hpp): with u^T K u / 2 replaced by the storeys'
// recoverable energy U = sum U_j, both steps still hold, because every law keeps
// dE_h/dt >= 0 (E_b can only grow by the ground's work) and V_j^2 <= 2 k0_j U_j, so that
// |(M^-1 f)_k| <= (|V_k| + |V_k+1|) / m_k <= sqrt(k0_k + k0_k+1) sqrt(2 U) / m_k = alpha_k sqrt(2
// U).
// P-Delta on yielding storeys (the linear case needs nothing: K = K0 - Kg stays positive definite,
// structure/building.cpp): E = T + U - G, G = u^T Kg u / 2, still obeys the energy equation, but
// -G is not bounded below. E' = T + U + G grows by at most 2 dG/dt = 2 u^T Kg v
// <= 2 sqrt(2 G) sqrt(v^T Kg v) <= 2 w_g sqrt(2 G) sqrt(2 T) <= 2 w_g E', w_g^2 >= the largest
// eigenvalue of M^-1 Kg (Gershgorin), so X = sqrt(2 E') obeys X' <= sqrt(m_b) |ag| + w_g X:
//     X(t + tau) <= (X(t) + sqrt(m_b) |ag|_max / w_g) e^(w_g tau) - sqrt(m_b) |ag|_max / w_g,
// and the geometric forces add gamma_k sqrt(2 G), gamma_k^2 = Kg_kk / m_k^2, to the acceleration:
// G_k = sqrt(alpha_k^2 + gamma_k^2 + beta_k^2) with alpha from K0.
// Tangent-stiffness damping (RowStorey::damping_a1): C_t = a0 M + a1 K_t with 0 <= K_t <= K0, so
// v^T C_t v >= 0 and |(M^-1 C_t v)_k| <= (a0 / sqrt(m_k) + a1 sqrt(K0_kk lambda0) / m_k)
// sqrt(v^T M v), lambda0 >= the largest eigenvalue of M^-1 K0 (Gershgorin): beta_k is that.
// The IMK law's unloading stiffness falls at reversals, which raises its U by V^2 (1/Ku' - 1/Ku)/2
// without work (hysteresis/imk.hpp): within a coarse step that is a fraction beta_K of one
// storey's elastic energy, which kCoarseBoundSafety covers; bound_violations counts any miss.
#include <Eigen/Dense>
#include <vector>

#include "structure/building_row.hpp"

namespace pound::sears {

class TranslationBound {
 public:
  /// For the assembled row `a`; ag_max bounds |ag| over the run [m/s^2].
  TranslationBound(const AssembledRow& a, double ag_max);

  /// Updates the energies of every building from the state (u, v) [m], [m/s]. No allocation.
  /// `strain` [J], when not empty, holds each building's recoverable strain energy (yielding
  /// storeys); a negative entry means u^T K u / 2 of that building.
  void set_state(const Eigen::VectorXd& u, const Eigen::VectorXd& v,
                 const std::vector<double>& strain = {});
  /// Upper bound on the increase of the absolute approach (u + ug)(dof_left) - (u + ug)(dof_right)
  /// within h [s] of contact-free motion from the state given to set_state() [m]; `ground_rate`
  /// the two buildings' relative ground velocity vg_L - vg_R now [m/s] (issue 28: the bound is
  /// on the floors' absolute accelerations, so it holds on different grounds). The two DOFs must
  /// be in different buildings.
  double approach(int dof_left, int dof_right, const Eigen::VectorXd& v, double ground_rate,
                  double h) const;
  /// The same for the points of a contact site's sides (SitePoint, the two in different
  /// buildings): x = sum w u over each side; a slab's point gives the bound above to the bit.
  double approach(const SitePoint& left, const SitePoint& right, const Eigen::VectorXd& v,
                  double ground_rate, double h) const;
  /// False for a row whose bound is not proved: a massless base (a foundation without mass or
  /// rotary inertia) with tangent-stiffness damping or P-Delta (translation_bound.cpp,
  /// massless_bounds); no step may rely on it then (the located stretches instead,
  /// sears_located.cpp).
  bool valid() const { return valid_; }

 private:
  void massless_bounds(const AssembledRow& a, const std::vector<int>& massless,
                       const Eigen::MatrixXd& K0);

 private:
  double accel(int k, double h) const;  // A_k over h [m/s^2]
  std::vector<int> building_of_;        // per DOF
  std::vector<double> influence_;       // per DOF: its ground influence i_k [-]
  std::vector<std::vector<int>> dofs_;  // per building: its floors, then its base's DOFs
  bool valid_ = true;                   // no massless DOF (the proof needs M > 0)
  std::vector<double> sqrt_mass_;       // sqrt(m_b) per building [sqrt(kg)]
  std::vector<double> sqrt2E_;          // sqrt(2 E_b) (yielding storeys: sqrt(2 E'_b)) [sqrt(J)]
  std::vector<double> omega_g_;         // per building: w_g (P-Delta) [1/s]
  std::vector<char> own_;               // per building: its strain energy given (yielding storeys)
  Eigen::VectorXd G_;                   // per DOF, linear storeys [1/(s sqrt(kg))]
  Eigen::VectorXd G_own_;               // per DOF, yielding storeys (with P-Delta's gamma_k)
  Eigen::MatrixXd K_, Kg_, M_;
  double ag_max_ = 0.0;
};

}  // namespace pound::sears

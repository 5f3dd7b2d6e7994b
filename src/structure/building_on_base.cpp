#include "structure/building_on_base.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "structure/foundation.hpp"

namespace pound {

ModalProperties modal_properties(const Eigen::MatrixXd& M, const Eigen::MatrixXd& K,
                                 const Eigen::MatrixXd& C) {
  const int n = static_cast<int>(M.rows());
  std::vector<int> a, b;  // DOFs with and without mass
  for (int i = 0; i < n; ++i) (M(i, i) > 0.0 ? a : b).push_back(i);
  const int na = static_cast<int>(a.size()), nb = static_cast<int>(b.size());
  Eigen::MatrixXd Kaa(na, na), Kab(na, nb), Kbb(nb, nb);
  Eigen::VectorXd m(na);
  for (int i = 0; i < na; ++i) {
    m(i) = M(a[i], a[i]);
    for (int j = 0; j < na; ++j) Kaa(i, j) = K(a[i], a[j]);
    for (int j = 0; j < nb; ++j) Kab(i, j) = K(a[i], b[j]);
  }
  for (int i = 0; i < nb; ++i)
    for (int j = 0; j < nb; ++j) Kbb(i, j) = K(b[i], b[j]);
  // Static condensation of the massless DOFs (Guyan): their forces are in equilibrium.
  const Eigen::LDLT<Eigen::MatrixXd> kbb(Kbb);
  if (nb > 0) Kaa -= Kab * kbb.solve(Kab.transpose());
  const Eigen::VectorXd s = m.cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd A = s.asDiagonal() * Kaa * s.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
  const Eigen::VectorXd w = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();  // ascending
  // The mode shapes, mass-normalised (phi^T M phi = 1), on every DOF: a massless DOF's entry
  // from its equilibrium, phi_b = -K_bb^-1 K_ba phi_a.
  const Eigen::MatrixXd pa = s.asDiagonal() * eig.eigenvectors();
  Eigen::MatrixXd phi = Eigen::MatrixXd::Zero(n, na);
  for (int i = 0; i < na; ++i) phi.row(a[i]) = pa.row(i);
  if (nb > 0) {
    const Eigen::MatrixXd pb = -kbb.solve(Kab.transpose() * pa);
    for (int i = 0; i < nb; ++i) phi.row(b[i]) = pb.row(i);
  }
  ModalProperties out;
  out.periods.resize(na);
  out.damping_ratios = Eigen::VectorXd::Zero(na);
  for (int i = 0; i < na; ++i) {
    out.periods(i) = w(i) > 0.0 ? 2.0 * M_PI / w(i) : std::numeric_limits<double>::infinity();
    if (w(i) > 0.0) out.damping_ratios(i) = phi.col(i).dot(C * phi.col(i)) / (2.0 * w(i));
  }
  return out;
}

namespace {

// A base mass so light that its own root is far faster than any mode of the building (issue 38:
// "a stiff root a foundation brings", here the inertial one, C / m_0 of a raft of 100 kg on a
// Gazetas footing ~ 6e5 1/s) is dropped: the base is taken as massless, a first-order DOF of
// its spring and dashpot (the singular-perturbation limit m_0 -> 0; Kokotovic, Khalil & O'Reilly
// 1986, ch. 1), which both solvers step at the building's own rates, where an explicit step
// would need h < 3.3 / rate. Threshold: rate x T_min >= kLightBase (T_min the fixed-base
// building's shortest period), the bound of IntegratorSettings::stiff_root's condensation: the
// base's lag behind its quasi-static motion is at most 2 pi / kLightBase = 6e-4 of it at the
// building's highest frequency, and the base's own mode is left out of the response.
constexpr double kLightBase = 1e4;  // [-]

}  // namespace

BaseRoots base_roots(double m, double c, double k) {
  if (m == 0.0) return {k / c, k / c, true};
  const double disc = c * c - 4.0 * m * k;
  if (disc > 0.0) {
    const double q = c + std::sqrt(disc);
    return {2.0 * k / q, q / (2.0 * m), true};
  }
  const double w = std::sqrt(k / m);
  return {w, w, false};
}

void drop_light_base_masses(BaseMatrices& out, const Eigen::VectorXd& fixed_periods, int sway,
                            int rot) {
  double t_min = std::numeric_limits<double>::infinity();  // [s]
  for (int i = 0; i < fixed_periods.size(); ++i)
    if (fixed_periods(i) > 0.0) t_min = std::min(t_min, fixed_periods(i));
  if (!std::isfinite(t_min)) return;
  for (const int d : {sway, rot}) {
    const double m = out.M(d, d), c = out.C(d, d), k = out.K0(d, d);
    if (m > 0.0 && base_roots(m, c, k).fast * t_min >= kLightBase) {
      out.M(d, d) = 0.0;
      out.light_base.push_back(d);
    }
  }
}

BaseMatrices assemble_on_base(const Building& b) {
  const BuildingMatrices fixed = assemble(b);
  BaseMatrices out;
  out.rayleigh_a1 = fixed.rayleigh_a1;
  const int n = b.floors();
  out.heights.resize(n);
  double h = 0.0;
  for (int j = 0; j < n; ++j) out.heights[j] = h += b.storey_heights[j];
  if (!b.foundation.flexible()) {
    out.M = fixed.M;
    out.K0 = fixed.K;
    out.Kg = fixed.Kg;
    out.C = fixed.C;
    out.influence = Eigen::VectorXd::Ones(n);
    out.periods = fixed.periods;  // (Building's own periods, as before foundations)
    out.damping_ratios = modal_properties(out.M, out.K0, out.C).damping_ratios;
    return out;
  }
  const FoundationConstants f = foundation_constants(b.foundation);
  const int m = n + 2, sway = n, rot = n + 1;
  out.flexible = true;
  out.M = Eigen::MatrixXd::Zero(m, m);
  out.K0 = Eigen::MatrixXd::Zero(m, m);
  out.Kg = Eigen::MatrixXd::Zero(m, m);
  out.C = Eigen::MatrixXd::Zero(m, m);
  out.influence = Eigen::VectorXd::Ones(m);
  out.influence(rot) = 0.0;
  double inertia = f.foundation_inertia;
  for (int j = 0; j < n; ++j) {
    out.M(j, j) = b.masses[j];
    inertia += f.floor_inertia(static_cast<std::size_t>(j));
  }
  out.M(sway, sway) = f.foundation_mass;
  out.M(rot, rot) = inertia;
  // Storey j: its deformation d_j = g_j . x with g_j = e_j - e_j-1 (e_-1: the sway) - h_j e_rot,
  // its chord c_j = e_j - e_j-1 (physics.md section 5a).
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(m), c = Eigen::VectorXd::Zero(m);
    c(j) = 1.0;
    c(j > 0 ? j - 1 : sway) = -1.0;
    g = c;
    g(rot) = -b.storey_heights[j];
    out.K0 += b.stiffnesses[j] * g * g.transpose();
    out.Kg += b.geometric_stiffness(j) * c * c.transpose();
  }
  out.K0(sway, sway) += f.sway_stiffness;
  out.K0(rot, rot) += f.rocking_stiffness;
  // The structure's damping on the floors' displacements relative to the base,
  // U_j - u0 - H_j theta: C = T^T C_fixed T, and the dashpots.
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(n, m);
  for (int j = 0; j < n; ++j) {
    T(j, j) = 1.0;
    T(j, sway) = -1.0;
    T(j, rot) = -out.heights[j];
  }
  out.C = T.transpose() * fixed.C * T;
  out.C(sway, sway) += f.sway_damping;
  out.C(rot, rot) += f.rocking_damping;
  drop_light_base_masses(out, fixed.periods, sway, rot);
  ModalProperties modes = modal_properties(out.M, out.K0, out.C);
  out.periods = std::move(modes.periods);
  out.damping_ratios = std::move(modes.damping_ratios);
  return out;
}

}  // namespace pound

#include "structure/building.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstdio>

#include "core/constants.hpp"
#include "core/error.hpp"
#include "core/format.hpp"
#include "hysteresis/registry.hpp"
#include "structure/building_on_base.hpp"

namespace pound {

void validate_gravity(const Building& b, const std::string& where) {
  const std::size_t n = b.masses.size();
  if (!b.gravity_loads.empty() && b.gravity_loads.size() != n)
    throw InputError(where + ": " + std::to_string(n) + " floors but " +
                     std::to_string(b.gravity_loads.size()) +
                     " gravity loads; give one value or one per floor");
  for (std::size_t j = 0; j < b.gravity_loads.size(); ++j)
    if (!(b.gravity_loads[j] > 0.0 && std::isfinite(b.gravity_loads[j])))
      throw InputError(where + ": gravity load of floor " + std::to_string(j + 1) +
                       " must be a finite number > 0 N");
  for (std::size_t j = 0; b.p_delta && j < n; ++j) {
    const double P = b.storey_gravity_load(static_cast<int>(j)), h = b.storey_heights[j];
    if (!(b.stiffnesses[j] > P / h))
      throw InputError(where + ": storey " + std::to_string(j + 1) +
                       " cannot carry its gravity load with P-Delta: its stiffness " +
                       format_number(b.stiffnesses[j]) + " N/m must exceed P / h = " +
                       format_number(P / h) + " N/m (P = " + format_number(P) +
                       " N of the floors at and above it, h = " + format_number(h) +
                       " m); raise the stiffness or lower gravity_loads");
  }
  if (b.damping_stiffness == DampingStiffness::tangent) {
    if (b.damping != DampingKind::rayleigh)
      throw InputError(where +
                       ": damping_stiffness = tangent needs damping_type = rayleigh (the "
                       "stiffness-proportional part is what it changes)");
    const StoreyLaw& law = find_storey_law(b.hysteresis, where);
    double slope, offset;
    if (!law.branch_line(b.storey(0), StoreyState{}, slope, offset))
      throw InputError(where +
                       ": damping_stiffness = tangent needs a piecewise-linear storey law "
                       "(elastic, bilinear, imk), not '" +
                       b.hysteresis + "'");
  }
}

void validate(const Building& b, const std::string& where) {
  const auto n = b.masses.size();
  if (n == 0) throw InputError(where + ": a building needs at least one floor mass");
  if (b.stiffnesses.size() != n)
    throw InputError(where + ": " + std::to_string(n) + " floor masses but " +
                     std::to_string(b.stiffnesses.size()) +
                     " storey stiffnesses; give one per storey");
  if (b.storey_heights.size() != n)
    throw InputError(where + ": " + std::to_string(n) + " floors but " +
                     std::to_string(b.storey_heights.size()) + " storey heights");
  for (std::size_t j = 0; j < n; ++j) {
    const std::string f = " of floor " + std::to_string(j + 1);
    if (!(b.masses[j] > 0.0 && std::isfinite(b.masses[j])))
      throw InputError(where + ": mass" + f + " must be a finite number > 0 kg");
    if (!(b.stiffnesses[j] > 0.0 && std::isfinite(b.stiffnesses[j])))
      throw InputError(where + ": storey stiffness" + f + " must be a finite number > 0 N/m");
    if (!(b.storey_heights[j] > 0.0 && std::isfinite(b.storey_heights[j])))
      throw InputError(where + ": storey height" + f + " must be a finite number > 0 m");
  }
  if (!(b.damping_ratio >= 0.0 && b.damping_ratio < 1.0))
    throw InputError(where + ": damping ratio must be in [0, 1)");
  if (!std::isfinite(b.base_elevation))
    throw InputError(where + ": base_elevation must be a finite number in m");
  if (!(b.slab_thickness > 0.0 && std::isfinite(b.slab_thickness)))
    throw InputError(where + ": slab_thickness must be a finite number > 0 m");
  if (!(b.face_column_share > 0.0 && b.face_column_share <= 1.0))
    throw InputError(where + ": face_column_share must be in (0, 1]");
  if (!b.column_shear_strength.empty() && b.column_shear_strength.size() != n)
    throw InputError(where + ": " + std::to_string(n) + " storeys but " +
                     std::to_string(b.column_shear_strength.size()) +
                     " column shear strengths; give one value or one per storey");
  for (double v : b.column_shear_strength)
    if (!(v > 0.0 && std::isfinite(v)))
      throw InputError(where + ": column_shear_strength must be finite numbers > 0 N");
  find_storey_law(b.hysteresis, where);
  auto per_storey = [&](const std::vector<double>& v, const char* what) {
    if (!v.empty() && v.size() != n)
      throw InputError(where + ": " + std::to_string(n) + " storeys but " +
                       std::to_string(v.size()) + " values of " + what +
                       "; give one value or one per storey");
  };
  per_storey(b.yield_shears, "yield_shears");
  per_storey(b.hardening, "hardening");
  per_storey(b.bw_n, "bw_n");
  per_storey(b.cap_strength_ratio, "cap_strength_ratio");
  per_storey(b.plastic_drift_ratio, "plastic_drift_ratio");
  per_storey(b.post_cap_drift_ratio, "post_cap_drift_ratio");
  per_storey(b.ultimate_drift_ratio, "ultimate_drift_ratio");
  per_storey(b.residual_strength_ratio, "residual_strength_ratio");
  per_storey(b.energy_capacity, "energy_capacity");
  per_storey(b.energy_exponent, "energy_exponent");
  if (b.inelastic() && b.yield_shears.empty())
    throw InputError(where + ": hysteresis '" + b.hysteresis +
                     "' needs yield_shears (the storey yield shears Fy > 0 in N, one value or one "
                     "per storey)");
  validate_gravity(b, where);
  for (std::size_t j = 0; j < n; ++j) {
    const std::string f = " of storey " + std::to_string(j + 1);
    if (!b.yield_shears.empty() && !(b.yield_shears[j] > 0.0 && !std::isnan(b.yield_shears[j])))
      throw InputError(where + ": yield shear" + f + " must be a number > 0 N");
    if (!b.hardening.empty() && !(b.hardening[j] >= 0.0 && b.hardening[j] < 1.0))
      throw InputError(where + ": hardening" + f + " must be in [0, 1) (b = k_post / k0)");
    if (!b.bw_n.empty() && !(b.bw_n[j] > 0.0 && std::isfinite(b.bw_n[j])))
      throw InputError(where + ": bw_n" + f + " must be a finite number > 0");
    const std::string imk_problem =
        imk_parameter_problem(b.storey(static_cast<int>(j)), b.hysteresis == "imk");
    if (!imk_problem.empty())
      throw InputError(where + ": storey " + std::to_string(j + 1) + ": " + imk_problem);
  }
  const std::string foundation = foundation_problem(b.foundation, b.floors());
  if (!foundation.empty()) throw InputError(where + ": foundation: " + foundation);
  if (b.p_delta && b.foundation.flexible()) {
    // Gravity on the rotation (the overturning moment of the floors' weights about the base):
    // the stiffness K0 - Kg of the building on its foundation must stay positive definite, or
    // the building topples under its own weight (issue 29).
    const BaseMatrices m = assemble_on_base(b);
    const Eigen::LLT<Eigen::MatrixXd> llt(m.K0 - m.Kg);
    if (llt.info() != Eigen::Success)
      throw InputError(where +
                       ": with P-Delta the foundation cannot hold the building's overturning "
                       "moment: raise rocking_stiffness (or the soil's stiffness) above the "
                       "floors' weights times their heights, sum W_j H_j = " +
                       format_number(overturning_stiffness(b)) + " N m/rad, with margin");
  }
}

double overturning_stiffness(const Building& b) {
  double s = 0.0, h = 0.0;
  for (int j = 0; j < b.floors(); ++j) s += b.gravity_load(j) * (h += b.storey_heights[j]);
  return s;
}

std::string imk_parameter_problem(const StoreyParameters& p, bool imk) {
  auto positive = [](double x) { return x > 0.0 && std::isfinite(x); };
  if (!(p.cap_strength_ratio >= 1.0 && std::isfinite(p.cap_strength_ratio)))
    return "cap_strength_ratio must be a finite Fc / Fy >= 1";
  if (!positive(p.plastic_drift_ratio)) return "plastic_drift_ratio must be a finite theta_p > 0";
  if (!positive(p.post_cap_drift_ratio))
    return "post_cap_drift_ratio must be a finite theta_pc > 0";
  if (!(p.residual_strength_ratio >= 0.0 && p.residual_strength_ratio < 1.0))
    return "residual_strength_ratio must be Fr / Fy in [0, 1)";
  if (!positive(p.energy_capacity)) return "energy_capacity must be a finite lambda > 0";
  if (!positive(p.energy_exponent)) return "energy_exponent must be a finite c > 0";
  if (!(p.ultimate_drift_ratio > 0.0)) return "ultimate_drift_ratio must be theta_u > 0";
  const double cap = p.uy() / p.h + p.plastic_drift_ratio;  // the cap drift ratio
  if (imk && !(p.ultimate_drift_ratio >= cap)) {
    char b[160];
    std::snprintf(b, sizeof b,
                  "ultimate_drift_ratio must not be below the cap drift ratio uy / h + theta_p = "
                  "%.6g (theta_u >= %.6g)",
                  cap, cap);
    return b;
  }
  return "";
}

StoreyParameters Building::storey(int j) const {
  StoreyParameters p;
  p.k0 = stiffnesses[j];
  if (!yield_shears.empty()) p.Fy = yield_shears[j];
  if (!hardening.empty()) p.b = hardening[j];
  if (!bw_n.empty()) p.bw_n = bw_n[j];
  p.h = storey_heights[j];
  auto take = [j](const std::vector<double>& v, double& x) {
    if (!v.empty()) x = v[j];
  };
  take(cap_strength_ratio, p.cap_strength_ratio);
  take(plastic_drift_ratio, p.plastic_drift_ratio);
  take(post_cap_drift_ratio, p.post_cap_drift_ratio);
  take(ultimate_drift_ratio, p.ultimate_drift_ratio);
  take(residual_strength_ratio, p.residual_strength_ratio);
  take(energy_capacity, p.energy_capacity);
  take(energy_exponent, p.energy_exponent);
  return p;
}

double Building::gravity_load(int j) const {
  return gravity_loads.empty() ? masses[j] * kGravity : gravity_loads[j];
}

double Building::storey_gravity_load(int j) const {
  double P = 0.0;
  for (int i = floors() - 1; i >= j; --i) P += gravity_load(i);
  return P;
}

double Building::geometric_stiffness(int j) const {
  return p_delta ? storey_gravity_load(j) / storey_heights[j] : 0.0;
}

BuildingMatrices assemble(const Building& b) {
  const int n = b.floors();
  BuildingMatrices out;
  out.M = Eigen::MatrixXd::Zero(n, n);
  out.K = Eigen::MatrixXd::Zero(n, n);
  // Storey j, a spring of stiffness k, joins floor j-1 (the ground for j = 0) and floor j.
  auto add_storey = [](Eigen::MatrixXd& K, int j, double k) {
    K(j, j) += k;
    if (j > 0) {
      K(j - 1, j - 1) += k;
      K(j - 1, j) -= k;
      K(j, j - 1) -= k;
    }
  };
  for (int j = 0; j < n; ++j) {
    out.M(j, j) = b.masses[j];
    add_storey(out.K, j, b.stiffnesses[j]);
  }
  // P-Delta: storey j's shear gains -P_j d_j / h_j, a spring of stiffness -P_j / h_j between the
  // same floors (the geometric stiffness, Kg in the pattern of K).
  out.Kg = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < n && b.p_delta; ++j) add_storey(out.Kg, j, b.geometric_stiffness(j));
  out.C = Eigen::MatrixXd::Zero(n, n);
  out.periods = Eigen::VectorXd::Zero(n);
  bool has_stiffness = false;
  for (double k : b.stiffnesses) has_stiffness = has_stiffness || k > 0.0;
  if (!has_stiffness) return out;

  // K phi = w^2 M phi; M is diagonal so the symmetric form M^-1/2 K M^-1/2 is used.
  const Eigen::VectorXd s = out.M.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd A = s.asDiagonal() * out.K * s.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(A);
  const Eigen::VectorXd w = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();  // ascending
  for (int i = 0; i < n; ++i) out.periods(i) = 2.0 * M_PI / w(i);
  const double xi = b.damping_ratio;
  if (b.damping == DampingKind::modal) {
    // C = M Phi diag(2 xi w_i) Phi^T M with mass-normalised Phi = M^-1/2 V (Chopra 11.4).
    const Eigen::MatrixXd Phi = s.asDiagonal() * eig.eigenvectors();
    const Eigen::VectorXd d = 2.0 * xi * w;
    out.C = out.M * Phi * d.asDiagonal() * Phi.transpose() * out.M;
  } else if (n == 1 && b.damping_stiffness == DampingStiffness::tangent) {
    // One mode: the same ratio from the stiffness alone, C = a1 k0 with a1 = 2 xi / w (Chopra
    // 11.4.1 with a0 = 0), so that the tangent stiffness has a damping to change.
    out.rayleigh_a1 = 2.0 * xi / w(0);
    out.C(0, 0) = out.rayleigh_a1 * out.K(0, 0);
  } else if (n == 1) {
    out.C(0, 0) = 2.0 * xi * w(0) * b.masses[0];
    out.rayleigh_a0 = 2.0 * xi * w(0);
  } else {
    // Rayleigh damping with ratio xi on modes 1 and 2 (Chopra 11.4.1).
    const double a0 = 2.0 * xi * w(0) * w(1) / (w(0) + w(1));
    const double a1 = 2.0 * xi / (w(0) + w(1));
    out.C = a0 * out.M + a1 * out.K;
    out.rayleigh_a0 = a0;
    out.rayleigh_a1 = a1;
  }
  return out;
}

}  // namespace pound

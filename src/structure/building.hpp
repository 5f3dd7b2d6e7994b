#pragma once
// A lumped-mass shear building (physics.md section 1; Th. 3.6, 8.5): floors j = 1..n with
// masses m_j and storey stiffnesses k_j between floor j-1 and j (floor 0 is the ground).
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "hysteresis/storey_law.hpp"

namespace pound {

enum class DampingKind {
  rayleigh,  ///< C = a0 M + a1 K with ratio xi on modes 1 and 2 (mass-proportional for 1 DOF)
  modal,     ///< classical modal damping, ratio xi on every mode
};

struct Building {
  std::string name;                    ///< label for reports
  std::vector<double> masses;          ///< floor masses, floor 1 first [kg]
  std::vector<double> stiffnesses;     ///< storey stiffnesses, storey 1 first [N/m]
  std::vector<double> storey_heights;  ///< storey heights, for drift ratios [m]
  double damping_ratio = 0.05;         ///< inherent damping ratio [-]
  DampingKind damping = DampingKind::rayleigh;
  /// Storey hysteresis (hysteresis/registry.hpp): "elastic", "bilinear" or "bouc-wen". The
  /// damping matrix stays the one built from the initial stiffnesses, constant through yielding.
  std::string hysteresis = "elastic";
  std::vector<double> yield_shears;  ///< storey yield shears Fy, storey 1 first [N]; may be
                                     ///< empty for "elastic" (no ductility is reported then)
  std::vector<double> hardening;     ///< post-yield stiffness ratio b per storey [-]; empty: 0.02
  std::vector<double> bw_n;          ///< Bouc-Wen sharpness n per storey [-]; empty: 2

  int floors() const { return static_cast<int>(masses.size()); }
  bool inelastic() const { return hysteresis != "elastic"; }
  /// The parameters of storey j (0-based): k0, Fy (infinite when none), b, n.
  StoreyParameters storey(int j) const;
};

/// Mass, stiffness and damping matrices of one building (floor DOFs relative to the ground).
struct BuildingMatrices {
  Eigen::MatrixXd M, K, C;
  Eigen::VectorXd periods;  ///< undamped periods, longest first [s]
};

/// Assembles the matrices (Th. 3.6). Stiffness may be zero only for free bodies (no modes).
BuildingMatrices assemble(const Building& b);

/// Checks masses > 0, stiffnesses > 0, heights > 0, 0 <= xi < 1, matching lengths, a known
/// hysteresis law with its parameters (Fy > 0 for every storey of an inelastic law,
/// 0 <= b < 1, n > 0); throws InputError naming `where` and the offending floor.
void validate(const Building& b, const std::string& where);

}  // namespace pound

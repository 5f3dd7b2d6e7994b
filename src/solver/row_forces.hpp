#pragma once
// The internal forces of the floors of a row (physics.md section 1; docs/hysteresis.md): the
// accelerations dv = -M^-1 (C v + f(u)) - ag of the row solver's right-hand side (ag: the
// ground acceleration under each floor DOF, its building's, issue 28), with
//   - linear storeys: f = K u, from the bands of the tridiagonal K and Rayleigh C of shear
//     buildings (Th. 3.6; Chopra 11.4.1), or compressed rows when C is full (modal damping);
//   - piecewise-linear storeys (elastic, bilinear): f = K_t u + off, the bands of the current
//     tangent stiffness and the forces of the branches' offsets, rebuilt at every switch;
//   - other laws (Bouc-Wen): f_j = V_j - V_j+1 from the laws' shears, storey by storey;
//   - a row with buildings on flexible foundations (issue 29, structure/building_on_base.hpp):
//     storey by storey along the deformations d_j = U_j - U_j-1 - h_j theta, P-Delta along the
//     chords, and the fixed-base damping on the floors' motion relative to the base (below);
// with P-Delta (RowStorey::kg) every storey's shear gains -kg d (in K for linear storeys), and with
// tangent-stiffness damping (RowStorey::damping_a1) the damping bands follow the storeys' branches
// (set_tangent_damping).
// Each path costs O(nonzeros) and allocates nothing. Kernel only: no files, no printing.
#include <Eigen/Dense>
#include <array>
#include <vector>

#include "structure/building_row.hpp"

namespace pound {

class RowForces {
 public:
  /// `storeys` one per floor DOF of `row` (AssembledRow::storeys or elastic_storeys()).
  RowForces(const AssembledRow& row, const std::vector<RowStorey>& storeys);

  /// dv = -M^-1 (C v + K u) - ag [m/s^2] (linear storeys); ag[i] the ground acceleration under
  /// floor DOF i [m/s^2].
  void linear(const double* u, const double* v, const double* ag, double* dv) const;
  /// dv = -M^-1 (C v + K_t u + off) - ag with the lines of set_lines().
  void affine(const double* u, const double* v, const double* ag, double* dv) const;
  /// The tangent bands and offsets from every storey's current branch (branch_line()).
  void set_lines(const std::vector<StoreyState>& states);
  /// dv = -M^-1 (C v + f) - ag with f from the laws' shears at drifts d of u; the laws'
  /// continuous states are read at `x` + xoff[i] and their rates written at dy + xoff[i]
  /// (dy = the whole state derivative, dv = dy + n); `v` the velocities (null: y's).
  void general(const Eigen::VectorXd& y, const std::vector<StoreyState>& states,
               const std::vector<int>& xoff, const double* ag, double* dy,
               const double* v = nullptr) const;
  /// Tangent-stiffness damping: C = C0 + sum a1 (max(k_t, 0) - k0) per such storey, from every
  /// storey's current branch.
  void set_tangent_damping(const std::vector<StoreyState>& states);
  bool tangent_damping() const { return tangent_damping_; }
  /// C v [N].
  void damping(const double* v, double* cv) const;
  /// The current damping matrix C [N s/m].
  void damping_matrix(Eigen::MatrixXd& C) const;
  /// The stiffness of the linear or affine right-hand side [N/m]: K (linear storeys) or the
  /// tangent K_t of set_lines() (affine), so that f = K u + offsets().
  void stiffness(bool affine, Eigen::MatrixXd& K) const;
  /// The offsets of set_lines() [N] (zero before the first call).
  const std::vector<double>& offsets() const { return off_; }
  /// Whether linear() takes the buildings' dense blocks (a linear row on flexible foundations,
  /// every DOF with mass, no building over kDenseDofs DOFs; set_dense).
  bool dense_path() const { return !dense_.empty(); }

  /// The force C v + f(u) on DOF i alone [N] (no mass, no ground, no contact), for a massless
  /// base DOF's velocity (a row with a flexible foundation; issue 29): f from K (`kind` 0,
  /// linear storeys), the lines of set_lines() (1) or the laws' shears (2; `y` the whole state
  /// for the laws' continuous states at y + xoff[s]).
  double raw_force(int i, const double* u, const double* v, int kind,
                   const std::vector<StoreyState>& states, const double* y,
                   const std::vector<int>& xoff) const;
  /// The entries of row i of the current damping matrix, and of the stiffness of `kind` 0 or 1
  /// (for the massless DOFs' elimination): calls f(column, C_ij, K_ij).
  template <class F>
  void row_entries(int i, int kind, F f) const {
    for (int e = row_start_[i]; e < row_start_[i + 1]; ++e)
      f(col_[e], c_val_[e], kind == 0 ? k_val_[e] : (topology_ ? kt_val_[e] : 0.0));
  }

 private:
  // A row with a storey on a flexible foundation (RowStorey::rot, or a base sway below it,
  // issue 29): its storeys' lines and tangent dampers go into compressed rows along each
  // storey's deformation g = e_i - e_below - h e_rot and chord c = e_i - e_below.
  struct StoreyEntry {
    int entry;  // in the compressed rows
    double g;   // g_a g_b
    double c;   // c_a c_b
  };
  void set_topology();
  void set_lines_general(const std::vector<StoreyState>& states);
  void set_base_path();
  void set_base_tangent_damping(int i, double dc);
  /// f = C v + K_t u + off (the lines of set_lines(), or K u with the initial slopes) on a row
  /// with flexible foundations, in O(n) (base_path_).
  void base_forces(const double* u, const double* v, double* f) const;
  /// C v [N] on such a row: C = T^T C_fixed T + diag(dashpots), so C v = T^T (C_fixed (T v)) +
  /// the dashpots' forces, T v = the floors' velocities relative to the base.
  void base_damping(const double* v, double* cv) const;
  void base_accelerations(const double* u, const double* v, const double* ag, double* dv) const;
  // Linear storeys on flexible foundations, every DOF with mass (set_dense, issue 38): per
  // building its DOFs (floors, sway, rotation) and A_v = -M^-1 [K C] over them (K and C the
  // row's, block diagonal over the buildings), lda rows (nd padded to a multiple of 4) by 2 nd
  // columns, column-major: dv = A_v [u; v] - ag by small dense products, fewer operations than
  // base_forces' O(n) pass for buildings of up to kDenseDofs DOFs (the same forces up to
  // round-off: tests/solver/row_forces_base_test.cpp).
  struct DenseBlock {
    std::vector<int> dofs;
    int lda = 0;
    std::vector<double> a;  // [1/s^2], [1/s]
  };
  static constexpr int kDenseDofs = 12;
  void set_dense();
  void dense_accelerations(const double* u, const double* v, const double* ag, double* dv) const;
  std::vector<DenseBlock> dense_;
  mutable std::vector<double> dense_out_;  // scratch: a block's A_v [u; v] [m/s^2]
  struct BaseSegment {
    int first, floors;  // the building's floor DOFs
    int sway, rot;      // its base DOFs (-1: a fixed base)
  };
  void segment_damping(const BaseSegment& g, const double* v, double* f, double& sum,
                       double& moment) const;

  const AssembledRow& row_;
  const std::vector<RowStorey>& storeys_;
  const int n_;
  bool topology_ = false;                          // a storey off the shear building's bands
  std::vector<std::vector<StoreyEntry>> entries_;  // per storey (topology_)
  // Per DOF the storeys acting on it: (storey, coefficient of its law's shear, of its P-Delta
  // force along the chord) (topology_).
  struct Touch {
    int storey;
    double g, c;
  };
  std::vector<std::vector<Touch>> touching_;
  std::vector<double> kt_val_;                       // K_t in the compressed rows (topology_)
  bool tridiagonal_ = false;                         // K and C tridiagonal
  std::vector<double> kl_, kd_, ku_, cl_, cd_, cu_;  // their bands [N/m], [N s/m]
  std::vector<int> row_start_, col_;                 // compressed rows of K and C
  std::vector<double> k_val_, c_val_;                // their entries [N/m], [N s/m]
  std::vector<double> tl_, td_, tu_, off_;           // K_t bands [N/m], offsets [N]
  bool tangent_damping_ = false;                     // a storey with damping_a1 > 0
  std::vector<double> cl0_, cd0_, cu0_, c_val0_;     // the initial C's bands and entries
  std::vector<std::array<int, 4>> damping_entry_;    // per storey: its entries of C
  mutable Eigen::VectorXd cv_;                       // scratch: C v [N]
  // The O(n) path of a row with flexible foundations (issue 29; set_base_path), per building
  // (segments_). Per DOF i: its storey's height h [m], geometric stiffness [N/m] and current
  // line (slope [N/m], offset [N]; on a base DOF its foundation spring), the foundation's
  // dashpot on a base DOF [N s/m, N m s/rad] and the floor's height H above its base [m]. The
  // floors (the first floors_ DOFs) carry the fixed-base damping C_fixed, block diagonal over
  // the buildings: its bands (xl_, xd_, xu_, tangent damping included) or, when full (modal
  // damping), compressed rows over the floors (xrow_, xcol_, xval_).
  bool base_path_ = false;
  int floors_ = 0;
  std::vector<BaseSegment> segments_;
  std::vector<double> s_h_, s_kg_, s_slope_, s_off_, f_height_, dashpot_;
  bool x_tridiagonal_ = false;
  std::vector<double> xl_, xd_, xu_, xl0_, xd0_, xu0_;
  std::vector<int> xrow_, xcol_;
  std::vector<double> xval_;
  mutable std::vector<double>
      xv_;  // scratch: T v, the floors' velocities relative to the base [m/s]
};

// The two hot paths are defined here so that the solver's right-hand side inlines them.
inline void RowForces::linear(const double* __restrict u, const double* __restrict v,
                              const double* __restrict ag, double* __restrict dv) const {
  const double* im = row_.inv_mass.data();
  if (tridiagonal_ && n_ > 1) {
    const double *kl = kl_.data(), *kd = kd_.data(), *ku = ku_.data();
    const double *cl = cl_.data(), *cd = cd_.data(), *cu = cu_.data();
    const int m = n_ - 1;
    dv[0] = -im[0] * (cd[0] * v[0] + cu[0] * v[1] + (kd[0] * u[0] + ku[0] * u[1])) - ag[0];
    for (int i = 1; i < m; ++i)
      dv[i] = -im[i] * (cl[i] * v[i - 1] + cd[i] * v[i] + cu[i] * v[i + 1] +
                        (kl[i] * u[i - 1] + kd[i] * u[i] + ku[i] * u[i + 1])) -
              ag[i];
    dv[m] = -im[m] * (cl[m] * v[m - 1] + cd[m] * v[m] + (kl[m] * u[m - 1] + kd[m] * u[m])) - ag[m];
    return;
  }
  if (base_path_) {
    if (!dense_.empty())
      dense_accelerations(u, v, ag, dv);
    else
      base_accelerations(u, v, ag, dv);
    return;
  }
  for (int i = 0; i < n_; ++i) {
    double f = 0.0;
    for (int e = row_start_[i]; e < row_start_[i + 1]; ++e) {
      const int j = col_[e];
      f += c_val_[e] * v[j] + k_val_[e] * u[j];
    }
    dv[i] = -im[i] * f - ag[i];
  }
}

inline void RowForces::affine(const double* __restrict u, const double* __restrict v,
                              const double* __restrict ag, double* __restrict dv) const {
  const double* im = row_.inv_mass.data();
  const double *tl = tl_.data(), *td = td_.data(), *tu = tu_.data(), *off = off_.data();
  if (tridiagonal_ && n_ > 1) {
    const double *cl = cl_.data(), *cd = cd_.data(), *cu = cu_.data();
    const int m = n_ - 1;
    dv[0] = -im[0] * (cd[0] * v[0] + cu[0] * v[1] + (td[0] * u[0] + tu[0] * u[1]) + off[0]) - ag[0];
    for (int i = 1; i < m; ++i)
      dv[i] = -im[i] * (cl[i] * v[i - 1] + cd[i] * v[i] + cu[i] * v[i + 1] +
                        (tl[i] * u[i - 1] + td[i] * u[i] + tu[i] * u[i + 1]) + off[i]) -
              ag[i];
    dv[m] =
        -im[m] * (cl[m] * v[m - 1] + cd[m] * v[m] + (tl[m] * u[m - 1] + td[m] * u[m]) + off[m]) -
        ag[m];
    return;
  }
  if (base_path_) {
    base_accelerations(u, v, ag, dv);
    return;
  }
  double* cv = cv_.data();
  damping(v, cv);
  if (topology_) {
    for (int i = 0; i < n_; ++i) {
      double ku = 0.0;
      for (int e = row_start_[i]; e < row_start_[i + 1]; ++e) ku += kt_val_[e] * u[col_[e]];
      dv[i] = -im[i] * (cv[i] + ku + off[i]) - ag[i];
    }
    return;
  }
  for (int i = 0; i < n_; ++i) {
    const double ku =
        td[i] * u[i] + (i > 0 ? tl[i] * u[i - 1] : 0.0) + (i + 1 < n_ ? tu[i] * u[i + 1] : 0.0);
    dv[i] = -im[i] * (cv[i] + ku + off[i]) - ag[i];
  }
}

}  // namespace pound

#pragma once
// One step of Kennedy & Carpenter's additive Runge-Kutta pair ARK5(4)8L[2]SA (Appl. Numer.
// Math. 44 (2003) 139-181, the "ARK5(4)8L[2]SA" coefficients; as tabulated in SUNDIALS' ARKode,
// ARK548L2SA_ERK_8_4_5 and ARK548L2SA_DIRK_8_4_5): y' =
// f_E(t, y) + f_I(y), the explicit tableau on f_E and the L-stable, stiffly accurate ESDIRK
// (gamma = 41/200) on f_I, one set of weights b (fifth order) and b-hat (fourth, the embedded
// error estimate) for both.
//
// Here f_I is linear and diagonal on a few entries of y (ImplicitSet): f_I(y)_k = -lambda_k y_k
// (a massive flexible base's own dashpot on its own velocity, lambda = C_dd / M_d [1/s]; issue
// 38, docs/speed.md "Buildings on their own steps", "IMEX steps on soil"), so that each stage's
// implicit solve is one division (1 + gamma h lambda_k) per entry. f = f_E + f_I is the whole
// right-hand side; f_E is never evaluated apart: F_E = F - F_I at every stage.
#include <Eigen/Dense>
#include <array>
#include <vector>

namespace pound {

/// The entries of y treated implicitly, each with its rate lambda [1/s]: f_I(y)_k = -lambda y_k.
struct ImplicitSet {
  std::vector<int> index;      ///< entries of y (velocities of base DOFs)
  std::vector<double> lambda;  ///< C_dd / M_d [1/s], > 0
  bool empty() const { return index.empty(); }
};

struct AssembledRow;
class RowDynamics;

/// Dormand-Prince's stability bound on the negative real axis, -3.3 < h lambda (Hairer & Wanner
/// II, IV.2, Fig. 2.1) [-].
inline constexpr double kDormandPrinceBound = 3.3;

/// The implicit set of a row (issue 38): the velocities of its bases with mass whose own
/// dashpots are too stiff for Dormand-Prince's steps of h_max [s], lambda = C_dd / M_d [1/s] with
/// lambda h_max >= from [-] (at least kDormandPrinceBound; IntegratorSettings::imex_from) for
/// one of them (then every base DOF with mass and a dashpot is in the set). Massless and
/// quasi-statically condensed base DOFs keep their own treatment (RowDynamics::project,
/// condense_stiff_roots). Empty otherwise: the row steps by Dormand-Prince, as before.
ImplicitSet stiff_base_dashpots(const AssembledRow& row, const RowDynamics& dyn, double h_max,
                                double from = kDormandPrinceBound);

/// ARK5(4)8L[2]SA's coefficients (Kennedy & Carpenter 2003): the explicit tableau ae, the
/// ESDIRK ai (diagonal gamma), the nodes c, the weights b and the embedded weights bh.
struct Ark548 {
  static constexpr int s = 8;
  std::array<std::array<double, 8>, 8> ae{}, ai{};
  std::array<double, 8> c{}, b{}, bh{};
  double gamma = 0.0;
  static const Ark548& get();
};

struct ArkImexWork {
  std::array<Eigen::VectorXd, 8> F;   // the stages' whole right-hand sides f(t_i, Y_i)
  std::array<Eigen::VectorXd, 8> FI;  // f_I(Y_i) on the implicit entries (their order in set)
  Eigen::VectorXd tmp;
  void resize(Eigen::Index n, std::size_t m) {
    for (auto& v : F) v.resize(n);
    for (auto& v : FI) v.resize(static_cast<Eigen::Index>(m));
    tmp.resize(n);
  }
};

namespace detail {
/// Stage i's explicit sum y0 + h sum_{j<i} (ae_ij (F_j - FI_j) + ai_ij FI_j), then the implicit
/// solve of its entries in `set`; FI_i from the result. Into w.tmp.
void ark_stage(int i, double h, const Eigen::VectorXd& y0, const ImplicitSet& set, ArkImexWork& w);
/// y1 = y0 + h sum_j b_j F_j and err = h sum_j (b_j - bh_j) F_j.
void ark_finish(double h, const Eigen::VectorXd& y0, const ImplicitSet& set, const ArkImexWork& w,
                Eigen::VectorXd& y1, Eigen::VectorXd& err);
}  // namespace detail

/// Advances y' = f(t, y) from (t, y, k1 = f(t, y)) by h into y1, with err = y5 - y4 (the local
/// error estimate; on the entries of `set` filtered by 1 / (1 + h gamma lambda), Hairer & Wanner
/// II, IV.8), the entries of `set` implicit (above). `f(t, y, dydt)` writes the whole
/// derivative. The derivative at (t + h, y1) is left to the caller (it is not a stage).
template <class F>
void ark_imex_step(F&& f, double t, double h, const Eigen::VectorXd& y, const Eigen::VectorXd& k1,
                   Eigen::VectorXd& y1, Eigen::VectorXd& err, const ImplicitSet& set,
                   ArkImexWork& w) {
  const Ark548& a = Ark548::get();
  const Eigen::Index n = y.size();
  if (w.tmp.size() != n || w.FI[0].size() != static_cast<Eigen::Index>(set.index.size()))
    w.resize(n, set.index.size());
  y1.resize(n);
  err.resize(n);
  w.F[0] = k1;
  for (std::size_t k = 0; k < set.index.size(); ++k) w.FI[0](k) = -set.lambda[k] * y(set.index[k]);
  for (int i = 1; i < Ark548::s; ++i) {
    detail::ark_stage(i, h, y, set, w);
    f(t + a.c[i] * h, w.tmp, w.F[i]);
  }
  detail::ark_finish(h, y, set, w, y1, err);
}

}  // namespace pound

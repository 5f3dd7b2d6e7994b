#pragma once
// The contact forces at the end of a damped Sears step (sears_simulation.hpp, step 4): the
// end-of-step overlaps are delta = delta_pred - S F with S the step's constant, symmetric
// positive definite compliance, and F_s = law_s(delta_s) at every site at once. Solved by
// nonlinear Gauss-Seidel: each sweep solves one site's monotone scalar equation
// (SlabContactLaw::solve_implicit); it converges because it minimises a strictly convex
// function. Kernel only.
#include <Eigen/Dense>
#include <vector>

#include "sears/slab_contact_law.hpp"

namespace pound::sears {

/// F_s = law_s(delta_pred_s - sum_t S(s,t) F_t) [N], warm started from F. Sites marked in
/// `frozen` keep F_s = 0 (the caller has shown that their faces stay apart). Throws
/// NumericalError after 500 sweeps.
void solve_site_forces(const std::vector<SlabContactLaw>& laws, const Eigen::MatrixXd& S,
                       const Eigen::VectorXd& delta_pred, const std::vector<char>& frozen,
                       Eigen::VectorXd& F);

}  // namespace pound::sears

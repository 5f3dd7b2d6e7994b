#include "sears/newmark_row.hpp"

namespace pound::sears {

Eigen::MatrixXd newmark_matrix(const AssembledRow& a, double h) {
  return a.M + (0.5 * h) * a.C + (0.25 * h * h) * a.K;
}

NewmarkOperator::NewmarkOperator(const AssembledRow& a, const Eigen::LLT<Eigen::MatrixXd>& mt)
    : CK(a.dofs(), 2 * a.dofs()), g(mt.solve(a.M * Eigen::VectorXd::Ones(a.dofs()))) {
  CK.leftCols(a.dofs()) = mt.solve(a.C);
  CK.rightCols(a.dofs()) = mt.solve(a.K);
}

void NewmarkFloors::predict(double h, const NewmarkOperator& op, double ag_next,
                            Eigen::VectorXd& a_next) {
  const int n = static_cast<int>(u.size());
  for (int j = 0; j < n; ++j) {
    work(j) = v(j) + (0.5 * h) * acc(j);
    work(n + j) = u(j) + h * v(j) + (0.25 * h * h) * acc(j);
  }
  a_next = op.g * (-ag_next);
  a_next.noalias() -= op.CK * work;
}

void NewmarkFloors::update(double h, const Eigen::VectorXd& a_next) {
  u += h * v + (0.25 * h * h) * (acc + a_next);
  v += (0.5 * h) * (acc + a_next);
  acc = a_next;
}

}  // namespace pound::sears

#include "sears/newmark_row.hpp"

namespace pound::sears {

Eigen::MatrixXd newmark_matrix(const AssembledRow& a, double h) {
  return a.M + (0.5 * h) * a.C + (0.25 * h * h) * a.K;
}

NewmarkOperator::NewmarkOperator(const AssembledRow& a, const Eigen::LLT<Eigen::MatrixXd>& mt,
                                 const FloorGround& ground)
    : CK(a.dofs(), 2 * a.dofs()) {
  const int n = a.dofs(), m = ground_inputs(ground);
  g.resize(n, m);
  for (int c = 0; c < m; ++c) {  // 1_c: the floors on channel c (all of them without ground)
    Eigen::VectorXd ones = Eigen::VectorXd::Zero(n);
    for (int i = 0; i < n; ++i)
      if (ground.channel(i) == c) ones(i) = 1.0;
    g.col(c) = mt.solve(Eigen::VectorXd(a.M * ones));
  }
  CK.leftCols(a.dofs()) = mt.solve(a.C);
  CK.rightCols(a.dofs()) = mt.solve(a.K);
}

void NewmarkFloors::predict(double h, const NewmarkOperator& op, const double* ag_next,
                            Eigen::VectorXd& a_next) {
  const int n = static_cast<int>(u.size());
  for (int j = 0; j < n; ++j) {
    work(j) = v(j) + (0.5 * h) * acc(j);
    work(n + j) = u(j) + h * v(j) + (0.25 * h * h) * acc(j);
  }
  a_next = op.g.col(0) * (-ag_next[0]);
  for (Eigen::Index c = 1; c < op.g.cols(); ++c) a_next -= op.g.col(c) * ag_next[c];
  a_next.noalias() -= op.CK * work;
}

void NewmarkFloors::update(double h, const Eigen::VectorXd& a_next) {
  u += h * v + (0.25 * h * h) * (acc + a_next);
  v += (0.5 * h) * (acc + a_next);
  acc = a_next;
}

}  // namespace pound::sears

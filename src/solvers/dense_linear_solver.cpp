#include "solvers/dense_linear_solver.hpp"

namespace openmss::solvers {

void DenseLinearSolver::analyze(const Eigen::SparseMatrix<double>& pattern) {
  dense_.resize(pattern.rows(), pattern.cols());
  work_.resize(pattern.rows());
}

bool DenseLinearSolver::factor(const Eigen::SparseMatrix<double>& matrix) {
  dense_ = matrix;  // same size as analysed: no allocation
  return factor(dense_);
}

bool DenseLinearSolver::factor(const Eigen::MatrixXd& matrix) {
  lu_.compute(matrix);
  // Partial pivoting does not report singularity; a zero pivot shows as a zero determinant.
  return lu_.matrixLU().diagonal().cwiseAbs().minCoeff() > 0.0;
}

void DenseLinearSolver::solve(Eigen::VectorXd& x) {
  work_.resize(x.size());
  work_ = lu_.solve(x);
  x = work_;
}

}  // namespace openmss::solvers

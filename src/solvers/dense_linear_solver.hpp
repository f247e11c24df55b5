#pragma once
// LU with partial pivoting on a dense copy: the fastest choice for small Newton matrices
// (fewer than BdfIntegrator's sparse threshold of unknowns), and the solver for problems
// that offer only a dense Newton matrix.

#include "solvers/linear_solver.hpp"

namespace openmss::solvers {

class DenseLinearSolver final : public LinearSolver {
 public:
  void analyze(const Eigen::SparseMatrix<double>& pattern) override;
  bool factor(const Eigen::SparseMatrix<double>& matrix) override;
  // The dense form, without a copy of the pattern.
  bool factor(const Eigen::MatrixXd& matrix);
  void solve(Eigen::VectorXd& x) override;
  const char* name() const override { return "dense LU"; }

 private:
  Eigen::MatrixXd dense_;
  Eigen::PartialPivLU<Eigen::MatrixXd> lu_;
  Eigen::VectorXd work_;
};

}  // namespace openmss::solvers

#pragma once
// The linear solves of a Newton iteration: a matrix whose sparsity pattern is fixed for a run
// is analysed once (ordering, symbolic factorisation), factorised whenever its values change,
// and solved against many right-hand sides (docs/theory.md, "Sparse Newton matrix").

#include <Eigen/Dense>
#include <Eigen/SparseCore>

namespace openmss::solvers {

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  // The pattern of the matrices to come (values ignored).
  virtual void analyze(const Eigen::SparseMatrix<double>& pattern) = 0;
  // Factorises a matrix with the analysed pattern (a different pattern is analysed anew).
  // False when the matrix is numerically singular; solve() then returns NaNs, which the
  // Newton iteration treats as a failed attempt.
  virtual bool factor(const Eigen::SparseMatrix<double>& matrix) = 0;
  // Overwrites x = b with the solution of A x = b for the last factorised A.
  virtual void solve(Eigen::VectorXd& x) = 0;
  virtual const char* name() const = 0;
};

}  // namespace openmss::solvers

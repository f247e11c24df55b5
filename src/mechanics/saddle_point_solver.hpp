#pragma once
// Sparse solves of the saddle-point systems of the set-up analyses (docs/theory.md §7):
//   [H  C^T] [x]   [f]
//   [C   0 ] [z] = [g]
// with H block diagonal (the mass matrix for accelerations and multipliers, the weights of the
// least-change velocity and position problems) and C the sparse constraint Jacobian. The
// assembled matrix is factored by SuiteSparse KLU (BTF and AMD ordering, threshold partial
// pivoting, so the indefinite matrix needs no special treatment). The
// symbolic analysis is kept and reused as long as the pattern is the same; the pattern depends
// on the model only (explicit zeros are kept), so a run analyses once and factors per output
// step, reusing the last pivot sequence (docs/theory.md §7, "Saddle-point solves").

#include <vector>

#include <Eigen/SparseCore>

namespace openmss::mechanics {

class SaddlePointSolver {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double>;

  // Factors the matrix of H (n x n) and C (m x n). False when it is singular: an exactly zero
  // pivot, or (checked by solve) a solution that does not reproduce the right-hand side.
  bool factor(const SparseMatrix& h, const SparseMatrix& c);
  // x (n) and z (m) for the right-hand side (f, g). False when the solution is not finite or
  // its relative residual exceeds kResidualTolerance (a numerically singular matrix) even after
  // a factorisation with fresh pivots.
  bool solve(const Eigen::VectorXd& f, const Eigen::VectorXd& g, Eigen::VectorXd& x,
             Eigen::VectorXd& z);

  // Largest |K s - b| / (|K| |s| + |b|) (infinity norms) accepted from the LU solve. A
  // backward-stable solve of a regular matrix gives ~1e-16 here; a matrix that the LU
  // factored through a round-off pivot gives O(1).
  static constexpr double kResidualTolerance = 1e-9;
  // KLU's threshold for keeping the (transversal's) diagonal entry as pivot: a tenth of the
  // column's largest, stricter than KLU's default 1e-3 for the Newton matrices, since the
  // multiplier rows of K have no diagonal of their own.
  static constexpr double kPivotTolerance = 0.1;

  SaddlePointSolver();
  ~SaddlePointSolver();
  SaddlePointSolver(const SaddlePointSolver&) = delete;
  SaddlePointSolver& operator=(const SaddlePointSolver&) = delete;

  int symbolicAnalyses() const { return analyses_; }
  // Factorisations with fresh pivots (the others reuse the last pivot sequence).
  int fullFactorizations() const { return fullFactorizations_; }

 private:
  bool factorFresh();
  bool solveOnce(const Eigen::VectorXd& b, Eigen::VectorXd& s);

  struct Klu;  // KLU's handles (saddle_point_solver.cpp)
  Klu* klu_;
  SparseMatrix kkt_;
  std::vector<int> outer_, inner_;  // the pattern KLU has analysed
  int analyses_ = 0, fullFactorizations_ = 0;
  double rcondAtFresh_ = 0.0;
  int n_ = 0, m_ = 0;
  double kktNorm_ = 0.0;
  bool factored_ = false;
};

}  // namespace openmss::mechanics

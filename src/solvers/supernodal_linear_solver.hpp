#pragma once
// Sparse LU for Newton matrices whose factors fill heavily (the contact graph of a landing
// pile): Eigen's SparseLU, a supernodal left-looking LU (SuperLU's algorithm) whose updates
// are dense matrix products, ordered by AMD on the pattern of A + Aᵀ with the diagonal
// preferred as pivot, so that a structurally symmetric matrix keeps its symmetric ordering.
// KLU (non-supernodal) does the same arithmetic one column at a time and is the better choice
// when there is little fill; SparseLinearSolver picks between the two (docs/theory.md, §9a,
// "Linear solver").

#include <memory>
#include <vector>

#include "solvers/linear_solver.hpp"

namespace openmss::solvers {

class SupernodalLinearSolver final : public LinearSolver {
 public:
  SupernodalLinearSolver();
  ~SupernodalLinearSolver() override;
  SupernodalLinearSolver(const SupernodalLinearSolver&) = delete;
  SupernodalLinearSolver& operator=(const SupernodalLinearSolver&) = delete;

  void analyze(const Eigen::SparseMatrix<double>& pattern) override;
  bool factor(const Eigen::SparseMatrix<double>& matrix) override;
  void solve(Eigen::VectorXd& x) override;
  const char* name() const override { return "supernodal LU"; }

  // Entries of the L and U factors of the last factorisation.
  long factorNonZeros() const;

 private:
  bool samePattern(const Eigen::SparseMatrix<double>& m) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<int> columnStart_, rowIndex_;  // the analysed pattern
  bool factored_ = false;
  Eigen::VectorXd work_;
};

}  // namespace openmss::solvers

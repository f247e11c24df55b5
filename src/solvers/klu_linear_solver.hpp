#pragma once
// Sparse LU by SuiteSparse KLU (block triangular form, AMD ordering, left-looking LU with
// partial pivoting), the solver for large Newton matrices. The symbolic analysis is done once
// per pattern; later factorisations reuse the pivot sequence of the last full one
// (klu_refactor) while it stays numerically sound, and pivot afresh otherwise.

#include <vector>

#include "solvers/linear_solver.hpp"

namespace openmss::solvers {

class KluLinearSolver final : public LinearSolver {
 public:
  KluLinearSolver();
  ~KluLinearSolver() override;
  KluLinearSolver(const KluLinearSolver&) = delete;
  KluLinearSolver& operator=(const KluLinearSolver&) = delete;

  void analyze(const Eigen::SparseMatrix<double>& pattern) override;
  bool factor(const Eigen::SparseMatrix<double>& matrix) override;
  void solve(Eigen::VectorXd& x) override;
  const char* name() const override { return "KLU"; }

  // Factorisations with fresh pivoting and with the previous pivot sequence.
  int fullFactorizations() const { return full_; }
  int refactorizations() const { return refactor_; }
  // Symbolic analyses (orderings) taken.
  int analyses() const { return analyses_; }
  // Entries of the L and U factors of the last factorisation (the fill; a solve reads each once).
  long factorNonZeros() const;
  // The floating-point operations of a factorisation as the last analysis predicts them
  // (AMD's count on the whole matrix, or on the diagonal blocks with the block triangular form;
  // 0 before an analysis or with COLAMD).
  double predictedFlops() const;

  // KLU's ordering choices, applied at the next analyze(): fill-reducing ordering AMD (0) or
  // COLAMD (1), block triangular form first, the partial-pivoting tolerance (a diagonal entry is
  // kept as pivot when at least this fraction of the column's largest). No block triangular
  // form by default: its maximum transversal took 0.47 G instructions per analysis of the
  // 1000-link chain's Newton matrix and about 3.5 s at 10,000 links (it grows like N^2 on
  // these saddle-point matrices), while the factors are as large without it (docs/performance.md,
  // "KLU without the block triangular form").
  struct Options {
    int ordering = 0;
    bool btf = false;
    double pivotTolerance = 1e-3;
  };
  void setOptions(const Options& options);

 private:
  bool samePattern(const Eigen::SparseMatrix<double>& m) const;
  bool fullFactor(const Eigen::SparseMatrix<double>& m);
  void release();

  struct Impl;
  Impl* impl_;
  std::vector<int> columnStart_, rowIndex_;  // the analysed pattern
  bool factored_ = false;
  double rcondAtFullFactor_ = 0.0;
  int full_ = 0, refactor_ = 0, analyses_ = 0;
};

}  // namespace openmss::solvers

#pragma once
// Sparse LU by SuiteSparse KLU (block triangular form, AMD ordering, left-looking LU with
// partial pivoting), the solver for large Newton matrices. The symbolic analysis is done once
// per pattern; later factorisations reuse the pivot sequence of the last full one
// (klu_refactor) while it stays numerically sound, and pivot afresh otherwise.

#include <vector>

#include "solvers/linear_solver.hpp"
#include "solvers/pivot_order.hpp"

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
  // The last analysis's maximum transversal stopped at Options::maxWork (blocks coarser).
  bool transversalStopped() const;
  // Entries of the L and U factors of the last factorisation (the fill; a solve reads each once).
  long factorNonZeros() const;
  // The floating-point operations of a factorisation as the last analysis predicts them
  // (AMD's count on the diagonal blocks of the BTF form; 0 before an analysis or with COLAMD).
  double predictedFlops() const;

  // KLU's ordering choices, applied at the next analyze(): fill-reducing ordering AMD (0) or
  // COLAMD (1), block triangular form (BTF) first, the partial-pivoting tolerance (a diagonal
  // entry is kept as pivot when at least this fraction of the column's largest), and the work
  // BTF's maximum transversal may do, in units of the matrix's entries (0: no limit). Its search
  // for a zero-free diagonal runs along the chains (about N^2 work on the planar chains'
  // patterns: 216 entries' worth per entry at 1000 links, 0.47 G instructions per analysis,
  // about 3.5 s at 10,000), while on the models measured that finish it below the limit (A02,
  // the 100-link chains: 0.8-22) the work is what it was. Stopped at the limit, BTF completes
  // the permutation and finds the blocks of that: still block triangular, so still exact, only
  // coarser (docs/performance.md, "KLU's block triangular form, bounded").
  struct Options {
    int ordering = 0;
    bool btf = true;
    double pivotTolerance = 1e-3;
    double maxWork = 30.0;
  };
  void setOptions(const Options& options);
  // The options of a pivot order (solvers/pivot_order.hpp): Default is Options{}.
  static Options optionsFor(PivotOrder order);

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

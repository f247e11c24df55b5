#pragma once
// The sparse Newton matrix's solver: KLU, or the supernodal LU when KLU's own analysis of the
// pattern predicts a heavy factorisation. The choice is made once per pattern from the
// pattern alone (never from values, timings or threads), so a run is as deterministic as
// before (docs/theory.md, §9a, "Linear solver").

#include <vector>

#include "solvers/klu_linear_solver.hpp"
#include "solvers/supernodal_linear_solver.hpp"

namespace openmss::solvers {

class SparseLinearSolver final : public LinearSolver {
 public:
  // Patterns whose factorisation KLU's AMD analysis predicts to cost at least this many
  // floating-point operations go to the supernodal LU. Measured on the 1000-sphere pile's
  // Newton matrices (docs/performance.md, "One factorisation of the pile's Newton matrix"):
  // at a prediction of 1.4e7 KLU's refactorisation (same pattern, old pivots) takes 4 ms and
  // the supernodal LU 10 ms, at 3.6e8 KLU 50 ms and the supernodal LU 25 ms; the chains and
  // piles up to 100 spheres predict at most 7e6 and keep KLU, bit for bit.
  static constexpr double kSupernodalFlops = 1e8;

  void analyze(const Eigen::SparseMatrix<double>& pattern) override;
  bool factor(const Eigen::SparseMatrix<double>& matrix) override;
  void solve(Eigen::VectorXd& x) override;
  const char* name() const override { return active_->name(); }

  // The threshold of the next analyses (tests force either solver with 0 or infinity).
  void setSupernodalFlops(double flops) { supernodalFlops_ = flops; }
  // KLU's options for the next analyses (MultistepSettings::pivotOrder).
  void setKluOptions(const KluLinearSolver::Options& options) { klu_.setOptions(options); }

  bool supernodal() const { return active_ == &supernodal_; }
  // KLU's prediction for the last analysed pattern (0 before any).
  double predictedFlops() const { return predictedFlops_; }
  // Patterns analysed so far.
  long analyses() const { return analyses_; }
  // Factorisations with fresh pivoting (KLU's full ones and every supernodal one) and KLU's
  // refactorisations on the previous pivot sequence (the .msg's counts, docs/performance.md).
  long fullFactorizations() const { return klu_.fullFactorizations() + supernodalFactorizations_; }
  long refactorizations() const { return klu_.refactorizations(); }

 private:
  bool samePattern(const Eigen::SparseMatrix<double>& m) const;

  KluLinearSolver klu_;
  SupernodalLinearSolver supernodal_;
  LinearSolver* active_ = &klu_;
  std::vector<int> columnStart_, rowIndex_;  // the analysed pattern
  double predictedFlops_ = 0.0;
  double supernodalFlops_ = kSupernodalFlops;
  long analyses_ = 0;
  long supernodalFactorizations_ = 0;
};

}  // namespace openmss::solvers

#include "solvers/sparse_linear_solver.hpp"

#include <algorithm>

namespace openmss::solvers {

void SparseLinearSolver::analyze(const Eigen::SparseMatrix<double>& pattern) {
  const int n = static_cast<int>(pattern.cols());
  columnStart_.assign(pattern.outerIndexPtr(), pattern.outerIndexPtr() + n + 1);
  rowIndex_.assign(pattern.innerIndexPtr(), pattern.innerIndexPtr() + columnStart_[n]);
  ++analyses_;
  // KLU's analysis (BTF, then AMD per block) is needed for KLU anyway and costs a few per cent
  // of a heavy factorisation; its flop estimate counts the diagonal blocks, which is all that
  // either solver factorises with fill.
  klu_.analyze(pattern);
  predictedFlops_ = klu_.predictedFlops();
  if (predictedFlops_ >= supernodalFlops_) {
    active_ = &supernodal_;
    supernodal_.analyze(pattern);
  } else {
    active_ = &klu_;
  }
}

bool SparseLinearSolver::samePattern(const Eigen::SparseMatrix<double>& m) const {
  const int n = static_cast<int>(m.cols());
  if (!m.isCompressed() || n + 1 != static_cast<int>(columnStart_.size())) return false;
  if (!std::equal(columnStart_.begin(), columnStart_.end(), m.outerIndexPtr())) return false;
  return std::equal(rowIndex_.begin(), rowIndex_.end(), m.innerIndexPtr());
}

bool SparseLinearSolver::factor(const Eigen::SparseMatrix<double>& m) {
  if (!samePattern(m)) analyze(m);
  if (active_ == &supernodal_) ++supernodalFactorizations_;
  return active_->factor(m);
}

void SparseLinearSolver::solve(Eigen::VectorXd& x) { active_->solve(x); }

}  // namespace openmss::solvers

#include "solvers/supernodal_linear_solver.hpp"

#include <amd.h>

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace openmss::solvers {
namespace {

using Matrix = Eigen::SparseMatrix<double>;

// Eigen's ordering interface over SuiteSparse's AMD of the pattern of A + Aᵀ (amd_order forms
// A + Aᵀ itself and ignores the diagonal). Eigen's own AMDOrdering, tried on the pile's
// matrices, gave several times KLU's fill (docs/performance.md, "One factorisation of the
// pile's Newton matrix"). Deterministic: AMD has no randomness and no threads.
struct SymmetricAmdOrdering {
  using PermutationType = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;
  template <typename MatrixType>
  void operator()(const MatrixType& a, PermutationType& permutation) {
    Matrix pattern = a;
    pattern.makeCompressed();
    const int n = static_cast<int>(pattern.cols());
    std::vector<int> order(static_cast<size_t>(n));  // order[k]: the k-th column to eliminate
    permutation.resize(n);
    if (amd_order(n, pattern.outerIndexPtr(), pattern.innerIndexPtr(), order.data(), nullptr,
                  nullptr) != AMD_OK) {
      permutation.setIdentity();
      return;
    }
    // Eigen's permutation maps an old index to its new position.
    for (int k = 0; k < n; ++k) permutation.indices()(order[k]) = k;
  }
};

}  // namespace

struct SupernodalLinearSolver::Impl {
  Eigen::SparseLU<Matrix, SymmetricAmdOrdering> lu;
};

SupernodalLinearSolver::SupernodalLinearSolver() : impl_(std::make_unique<Impl>()) {
  // The diagonal is kept as pivot when it is at least this fraction of its column's largest
  // entry: KLU's default tolerance (klu_linear_solver.hpp), which keeps AMD's symmetric
  // ordering on the structurally symmetric Newton matrix.
  impl_->lu.setPivotThreshold(1e-3);
}

SupernodalLinearSolver::~SupernodalLinearSolver() = default;

long SupernodalLinearSolver::factorNonZeros() const {
  return factored_ ? static_cast<long>(impl_->lu.nnzL() + impl_->lu.nnzU()) : 0;
}

void SupernodalLinearSolver::analyze(const Eigen::SparseMatrix<double>& pattern) {
  factored_ = false;
  const int n = static_cast<int>(pattern.cols());
  columnStart_.assign(pattern.outerIndexPtr(), pattern.outerIndexPtr() + n + 1);
  rowIndex_.assign(pattern.innerIndexPtr(), pattern.innerIndexPtr() + columnStart_[n]);
  impl_->lu.analyzePattern(pattern);
}

bool SupernodalLinearSolver::samePattern(const Eigen::SparseMatrix<double>& m) const {
  const int n = static_cast<int>(m.cols());
  if (!m.isCompressed() || n + 1 != static_cast<int>(columnStart_.size())) return false;
  if (!std::equal(columnStart_.begin(), columnStart_.end(), m.outerIndexPtr())) return false;
  return std::equal(rowIndex_.begin(), rowIndex_.end(), m.innerIndexPtr());
}

bool SupernodalLinearSolver::factor(const Eigen::SparseMatrix<double>& m) {
  if (!samePattern(m)) analyze(m);
  impl_->lu.factorize(m);
  factored_ = impl_->lu.info() == Eigen::Success;
  return factored_;
}

void SupernodalLinearSolver::solve(Eigen::VectorXd& x) {
  if (!factored_) {
    x.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  work_ = x;
  x = impl_->lu.solve(work_);  // (into x from a copy: the solve must not read what it writes)
}

}  // namespace openmss::solvers

#include "solvers/klu_linear_solver.hpp"

#include <klu.h>

#include <algorithm>
#include <limits>

namespace openmss::solvers {

struct KluLinearSolver::Impl {
  klu_common common{};
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
};

KluLinearSolver::KluLinearSolver() : impl_(new Impl) {
  klu_defaults(&impl_->common);
  setOptions(Options{});
}

KluLinearSolver::~KluLinearSolver() {
  release();
  delete impl_;
}

long KluLinearSolver::factorNonZeros() const {
  return impl_->numeric ? static_cast<long>(impl_->numeric->lnz) + impl_->numeric->unz : 0;
}

bool KluLinearSolver::transversalStopped() const {
  return impl_->symbolic && impl_->common.btf && impl_->common.work < 0.0;  // KLU's flag: -1
}

double KluLinearSolver::predictedFlops() const {
  return impl_->symbolic && impl_->symbolic->ordering == 0 ? impl_->symbolic->est_flops : 0.0;
}

void KluLinearSolver::setOptions(const Options& options) {
  impl_->common.ordering = options.ordering;
  impl_->common.btf = options.btf ? 1 : 0;
  impl_->common.tol = options.pivotTolerance;
  impl_->common.maxwork = options.maxWork;
  columnStart_.clear();  // the next factor() analyses anew
  rowIndex_.clear();
}

KluLinearSolver::Options KluLinearSolver::optionsFor(PivotOrder order) {
  Options o;
  if (order == PivotOrder::NoBtf) o.btf = false;
  if (order == PivotOrder::Colamd) o.ordering = 1;
  return o;
}

void KluLinearSolver::release() {
  if (impl_->numeric) klu_free_numeric(&impl_->numeric, &impl_->common);
  if (impl_->symbolic) klu_free_symbolic(&impl_->symbolic, &impl_->common);
  factored_ = false;
}

void KluLinearSolver::analyze(const Eigen::SparseMatrix<double>& pattern) {
  release();
  const int n = static_cast<int>(pattern.cols());
  const int* outer = pattern.outerIndexPtr();
  const int* inner = pattern.innerIndexPtr();
  columnStart_.assign(outer, outer + n + 1);
  rowIndex_.assign(inner, inner + columnStart_[n]);
  impl_->symbolic = klu_analyze(n, columnStart_.data(), rowIndex_.data(), &impl_->common);
  ++analyses_;
}

bool KluLinearSolver::samePattern(const Eigen::SparseMatrix<double>& m) const {
  const int n = static_cast<int>(m.cols());
  if (!m.isCompressed() || n + 1 != static_cast<int>(columnStart_.size())) return false;
  if (!std::equal(columnStart_.begin(), columnStart_.end(), m.outerIndexPtr())) return false;
  return std::equal(rowIndex_.begin(), rowIndex_.end(), m.innerIndexPtr());
}

bool KluLinearSolver::fullFactor(const Eigen::SparseMatrix<double>& m) {
  if (impl_->numeric) klu_free_numeric(&impl_->numeric, &impl_->common);
  impl_->numeric = klu_factor(columnStart_.data(), rowIndex_.data(),
                              const_cast<double*>(m.valuePtr()), impl_->symbolic, &impl_->common);
  ++full_;
  if (!impl_->numeric) return false;
  klu_rcond(impl_->symbolic, impl_->numeric, &impl_->common);
  rcondAtFullFactor_ = impl_->common.rcond;
  return true;
}

bool KluLinearSolver::factor(const Eigen::SparseMatrix<double>& m) {
  if (!samePattern(m)) analyze(m);
  factored_ = false;
  if (!impl_->symbolic) return false;
  bool ok = false;
  if (impl_->numeric &&
      klu_refactor(columnStart_.data(), rowIndex_.data(), const_cast<double*>(m.valuePtr()),
                   impl_->symbolic, impl_->numeric, &impl_->common)) {
    ++refactor_;
    // The old pivot sequence may have become poor for the new values: when the cheap
    // reciprocal condition estimate (smallest over largest |U_ii|) falls far below the one of
    // the last full factorisation, pivot afresh.
    ok = klu_rcond(impl_->symbolic, impl_->numeric, &impl_->common) &&
         impl_->common.rcond >= 1e-3 * rcondAtFullFactor_ && impl_->common.rcond > 0.0;
  }
  if (!ok) ok = fullFactor(m);
  factored_ = ok;
  return ok;
}

void KluLinearSolver::solve(Eigen::VectorXd& x) {
  if (!factored_) {
    x.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  const int n = static_cast<int>(x.size());
  klu_solve(impl_->symbolic, impl_->numeric, n, 1, x.data(), &impl_->common);
}

}  // namespace openmss::solvers

#include "mechanics/saddle_point_solver.hpp"

#include <klu.h>

#include <algorithm>
#include <cmath>

namespace openmss::mechanics {

struct SaddlePointSolver::Klu {
  klu_common common{};
  klu_symbolic* symbolic = nullptr;
  klu_numeric* numeric = nullptr;
  void freeNumeric() {
    if (numeric) klu_free_numeric(&numeric, &common);
  }
  void freeAll() {
    freeNumeric();
    if (symbolic) klu_free_symbolic(&symbolic, &common);
  }
};

SaddlePointSolver::SaddlePointSolver() : klu_(new Klu) {
  klu_defaults(&klu_->common);
  klu_->common.tol = kPivotTolerance;
}

SaddlePointSolver::~SaddlePointSolver() {
  klu_->freeAll();
  delete klu_;
}

bool SaddlePointSolver::factorFresh() {
  klu_->freeNumeric();
  klu_->numeric = klu_factor(outer_.data(), inner_.data(), kkt_.valuePtr(), klu_->symbolic,
                             &klu_->common);
  ++fullFactorizations_;
  if (!klu_->numeric || !klu_rcond(klu_->symbolic, klu_->numeric, &klu_->common)) return false;
  rcondAtFresh_ = klu_->common.rcond;
  return rcondAtFresh_ > 0.0;
}

bool SaddlePointSolver::factor(const SparseMatrix& h, const SparseMatrix& c) {
  n_ = static_cast<int>(h.rows());
  m_ = static_cast<int>(c.rows());
  const int size = n_ + m_;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(h.nonZeros() + 2 * c.nonZeros()));
  for (int j = 0; j < h.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(h, j); it; ++it)
      entries.emplace_back(it.row(), j, it.value());
  for (int j = 0; j < c.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(c, j); it; ++it) {
      entries.emplace_back(n_ + it.row(), j, it.value());
      entries.emplace_back(j, n_ + it.row(), it.value());
    }
  kkt_.resize(size, size);
  kkt_.setFromTriplets(entries.begin(), entries.end());
  kkt_.makeCompressed();
  kktNorm_ = 0.0;
  for (int j = 0; j < kkt_.outerSize(); ++j) {
    double column = 0.0;  // the 1-norm of K^T is the infinity norm of K (K is symmetric)
    for (SparseMatrix::InnerIterator it(kkt_, j); it; ++it) column += std::abs(it.value());
    kktNorm_ = std::max(kktNorm_, column);
  }
  factored_ = false;
  if (size == 0) return factored_ = true;
  const bool samePattern =
      klu_->symbolic && outer_.size() == static_cast<size_t>(size + 1) &&
      std::equal(outer_.begin(), outer_.end(), kkt_.outerIndexPtr()) &&
      inner_.size() == static_cast<size_t>(kkt_.nonZeros()) &&
      std::equal(inner_.begin(), inner_.end(), kkt_.innerIndexPtr());
  if (!samePattern) {
    klu_->freeAll();
    outer_.assign(kkt_.outerIndexPtr(), kkt_.outerIndexPtr() + size + 1);
    inner_.assign(kkt_.innerIndexPtr(), kkt_.innerIndexPtr() + kkt_.nonZeros());
    klu_->symbolic = klu_analyze(size, outer_.data(), inner_.data(), &klu_->common);
    ++analyses_;
    if (!klu_->symbolic) return false;
  }
  // The last pivot sequence while KLU's condition estimate (smallest over largest |U_ii|) stays
  // within 1e-3 of the last fresh factorisation's, as the Newton matrices do (docs/theory.md
  // §9a, "Linear solver"); fresh pivots otherwise.
  if (klu_->numeric && klu_refactor(outer_.data(), inner_.data(), kkt_.valuePtr(), klu_->symbolic,
                                    klu_->numeric, &klu_->common)) {
    factored_ = klu_rcond(klu_->symbolic, klu_->numeric, &klu_->common) &&
                klu_->common.rcond > 0.0 && klu_->common.rcond >= 1e-3 * rcondAtFresh_;
  }
  if (!factored_) factored_ = factorFresh();
  return factored_;
}

bool SaddlePointSolver::solveOnce(const Eigen::VectorXd& b, Eigen::VectorXd& s) {
  s = b;
  klu_solve(klu_->symbolic, klu_->numeric, static_cast<int>(s.size()), 1, s.data(),
            &klu_->common);
  if (!s.allFinite()) return false;
  const double residual = (kkt_ * s - b).cwiseAbs().maxCoeff();
  const double scale = kktNorm_ * s.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff();
  return residual <= kResidualTolerance * std::max(scale, 1e-300);
}

bool SaddlePointSolver::solve(const Eigen::VectorXd& f, const Eigen::VectorXd& g,
                              Eigen::VectorXd& x, Eigen::VectorXd& z) {
  if (!factored_) return false;
  Eigen::VectorXd b(n_ + m_);
  b << f, g;
  if (b.size() == 0) {
    x.resize(0);
    z.resize(0);
    return true;
  }
  Eigen::VectorXd s;
  // A pivot sequence reused from an earlier output step can have grown poor without KLU's
  // condition estimate noticing: pivot afresh once before calling the matrix singular.
  if (!solveOnce(b, s) && !(factorFresh() && solveOnce(b, s))) {
    factored_ = false;
    return false;
  }
  x = s.head(n_);
  z = s.tail(m_);
  return true;
}

}  // namespace openmss::mechanics

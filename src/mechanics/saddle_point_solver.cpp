#include "mechanics/saddle_point_solver.hpp"

#include <algorithm>
#include <cmath>

namespace openmss::mechanics {

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
      analyses_ > 0 && outer_.size() == static_cast<size_t>(size + 1) &&
      std::equal(outer_.begin(), outer_.end(), kkt_.outerIndexPtr()) &&
      inner_.size() == static_cast<size_t>(kkt_.nonZeros()) &&
      std::equal(inner_.begin(), inner_.end(), kkt_.innerIndexPtr());
  if (!samePattern) {
    lu_.analyzePattern(kkt_);
    outer_.assign(kkt_.outerIndexPtr(), kkt_.outerIndexPtr() + size + 1);
    inner_.assign(kkt_.innerIndexPtr(), kkt_.innerIndexPtr() + kkt_.nonZeros());
    ++analyses_;
  }
  lu_.factorize(kkt_);
  factored_ = lu_.info() == Eigen::Success;
  return factored_;
}

bool SaddlePointSolver::solve(const Eigen::VectorXd& f, const Eigen::VectorXd& g,
                              Eigen::VectorXd& x, Eigen::VectorXd& z) const {
  if (!factored_) return false;
  Eigen::VectorXd b(n_ + m_);
  b << f, g;
  if (b.size() == 0) {
    x.resize(0);
    z.resize(0);
    return true;
  }
  const Eigen::VectorXd s = lu_.solve(b);
  if (!s.allFinite()) return false;
  const double residual = (kkt_ * s - b).cwiseAbs().maxCoeff();
  const double scale = kktNorm_ * s.cwiseAbs().maxCoeff() + b.cwiseAbs().maxCoeff();
  if (residual > kResidualTolerance * std::max(scale, 1e-300)) return false;
  x = s.head(n_);
  z = s.tail(m_);
  return true;
}

}  // namespace openmss::mechanics

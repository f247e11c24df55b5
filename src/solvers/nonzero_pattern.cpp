#include "solvers/nonzero_pattern.hpp"

#include <algorithm>

namespace openmss::solvers {

const Eigen::SparseMatrix<double>& NonzeroPattern::select(const Eigen::SparseMatrix<double>& full,
                                                          bool* grew) {
  const int cols = static_cast<int>(full.cols());
  const int nnz = static_cast<int>(full.nonZeros());
  const int* outer = full.outerIndexPtr();
  const int* inner = full.innerIndexPtr();
  const double* value = full.valuePtr();
  const bool sameStructure = static_cast<int>(outer_.size()) == cols + 1 &&
                             static_cast<int>(inner_.size()) == nnz &&
                             std::equal(outer_.begin(), outer_.end(), outer) &&
                             std::equal(inner_.begin(), inner_.end(), inner);
  bool changed = !sameStructure;
  if (!sameStructure) {
    outer_.assign(outer, outer + cols + 1);
    inner_.assign(inner, inner + nnz);
    kept_.assign(static_cast<size_t>(nnz), 0);
  }
  if (!sameStructure) growths_ = 0;
  bool added = false;
  for (int k = 0; k < nnz; ++k) {
    if (!kept_[static_cast<size_t>(k)] && value[k] != 0.0) {
      kept_[static_cast<size_t>(k)] = 1;
      added = true;
    }
  }
  if (added && sameStructure && ++growths_ >= kMaxGrowths) std::fill(kept_.begin(), kept_.end(), 1);
  changed = changed || added;
  if (changed) {
    // (A column left empty means a matrix singular in its values as well: the factorisation
    // reports it as it would on the full structure.)
    source_.clear();
    std::vector<int> columnStart(static_cast<size_t>(cols) + 1, 0);
    for (int c = 0; c < cols; ++c) {
      for (int k = outer[c]; k < outer[c + 1]; ++k)
        if (kept_[static_cast<size_t>(k)]) source_.push_back(k);
      columnStart[static_cast<size_t>(c) + 1] = static_cast<int>(source_.size());
    }
    selected_.resize(full.rows(), cols);
    selected_.resizeNonZeros(static_cast<Eigen::Index>(source_.size()));
    std::copy(columnStart.begin(), columnStart.end(), selected_.outerIndexPtr());
    for (size_t j = 0; j < source_.size(); ++j) selected_.innerIndexPtr()[j] = inner[source_[j]];
  }
  double* out = selected_.valuePtr();
  for (size_t j = 0; j < source_.size(); ++j) out[j] = value[source_[j]];
  if (grew != nullptr) *grew = changed;
  return selected_;
}

}  // namespace openmss::solvers

#include "mechanics/sparse_constraint_jacobian.hpp"

#include <cmath>

#include <SuiteSparseQR.hpp>

namespace openmss::mechanics {

SparseMatrix sparseConstraintJacobian(const MultibodySystem& system, const double* y,
                                      const std::vector<int>& rows,
                                      const std::vector<const ConstraintEquation*>& extra) {
  const int n = 6 * system.layout().bodies;
  const int m = static_cast<int>(rows.size() + extra.size());
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<size_t>(m) * 12);
  std::vector<int> cols;
  std::vector<double> vals;
  for (int r = 0; r < m; ++r) {
    if (r < static_cast<int>(rows.size()))
      system.constraintRowEntries(rows[r], y, cols, vals);
    else
      system.constraintRowEntries(*extra[r - rows.size()], y, cols, vals);
    // Explicit zeros are kept: the pattern then depends on the model only, not on the pose,
    // and the symbolic analysis of the solves can be reused from step to step.
    for (size_t i = 0; i < cols.size(); ++i) entries.emplace_back(r, cols[i], vals[i]);
  }
  SparseMatrix c(m, n);
  c.setFromTriplets(entries.begin(), entries.end());
  c.makeCompressed();
  return c;
}

bool findDependentRows(const SparseMatrix& c, double relativeTolerance,
                       std::vector<bool>& dependent) {
  const int m = static_cast<int>(c.rows());
  dependent.assign(m, false);
  if (m == 0) return true;
  // Row norms, and the coordinates some row touches (SparseQR needs every row of C^T nonempty;
  // the others play no part in the rank).
  std::vector<double> norm(m, 0.0);
  std::vector<int> coordinate(c.cols(), -1);
  for (int j = 0; j < c.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(c, j); it; ++it) norm[it.row()] += it.value() * it.value();
  for (double& v : norm) v = std::sqrt(v);
  int used = 0;
  for (int j = 0; j < c.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(c, j); it; ++it)
      if (it.value() != 0.0 && norm[it.row()] > 0.0) {
        coordinate[j] = used++;
        break;
      }
  // C^T with unit columns: an absolute threshold on the orthogonal component is then the
  // relative test. Zero rows of C are dependent (as in the dense test) and left out.
  std::vector<int> column(m, -1);
  int live = 0;
  for (int r = 0; r < m; ++r) {
    if (norm[r] > 0.0) column[r] = live++;
    else dependent[r] = true;
  }
  if (live == 0) return true;
  // cholmod's compressed-column C^T: column = equation, row = coordinate.
  std::vector<std::vector<std::pair<int, double>>> byEquation(live);
  for (int j = 0; j < c.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(c, j); it; ++it)
      if (it.value() != 0.0 && column[it.row()] >= 0)
        byEquation[column[it.row()]].emplace_back(coordinate[j], it.value() / norm[it.row()]);
  size_t nnz = 0;
  for (const auto& e : byEquation) nnz += e.size();
  cholmod_common cc;
  cholmod_l_start(&cc);
  cholmod_sparse* ct =
      cholmod_l_allocate_sparse(used, live, nnz, /*sorted=*/1, /*packed=*/1, /*stype=*/0,
                                CHOLMOD_REAL, &cc);
  auto* p = static_cast<SuiteSparse_long*>(ct->p);
  auto* i = static_cast<SuiteSparse_long*>(ct->i);
  auto* x = static_cast<double*>(ct->x);
  SuiteSparse_long k = 0;
  for (int e = 0; e < live; ++e) {
    p[e] = k;
    for (const auto& [row, value] : byEquation[e]) {  // rows increase with the columns of C
      i[k] = row;
      x[k++] = value;
    }
  }
  p[live] = k;
  // Fixed ordering: the equations are factored in their order (a column is dead only against
  // earlier ones); the multifrontal fronts keep each step local, O(N) for chains and trees.
  SuiteSparseQR_factorization<double>* qr =
      SuiteSparseQR_factorize<double>(SPQR_ORDERING_FIXED, relativeTolerance, ct, &cc);
  const bool ok = qr != nullptr && cc.status == CHOLMOD_OK;
  std::vector<bool> liveEquation(live, true);
  if (ok && qr->Rmap != nullptr) {
    // Column j of R is column Q1fill[j] of C^T; it is dead when its rank slot is past the rank.
    for (SuiteSparse_long j = 0; j < live; ++j) {
      const SuiteSparse_long original = qr->Q1fill ? qr->Q1fill[j] : j;
      if (qr->Rmap[j] >= qr->rank) liveEquation[original] = false;
    }
  }
  SuiteSparseQR_free<double>(&qr, &cc);
  cholmod_l_free_sparse(&ct, &cc);
  cholmod_l_finish(&cc);
  if (!ok) return false;
  for (int r = 0; r < m; ++r)
    if (column[r] >= 0 && !liveEquation[column[r]]) dependent[r] = true;
  return true;
}

}  // namespace openmss::mechanics

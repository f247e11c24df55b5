#pragma once
// The constraint Jacobian C = dPhi/d(delta r, delta pi) as a sparse matrix, and the search for
// its dependent rows (docs/theory.md §7, "sparse set-up"). An equation reads at most
// ConstraintEquation::kMaxMarkers markers, so a row of C has at most 6 * kMaxMarkers nonzeros
// however many bodies the model has; C of an N-link chain is O(N) in memory and work.

#include <vector>

#include <Eigen/SparseCore>

#include "mechanics/multibody_system.hpp"

namespace openmss::mechanics {

using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major, int indices

// C over `rows` (equation indices, in that order), then one row per equation of `extra`
// (equations outside the DAE, e.g. joint initial conditions); 6 columns per moving body.
SparseMatrix sparseConstraintJacobian(const MultibodySystem& system, const double* y,
                                      const std::vector<int>& rows,
                                      const std::vector<const ConstraintEquation*>& extra = {});

// Row i of c is dependent when its component orthogonal to the earlier independent rows is at
// most `relativeTolerance` times its own norm (a zero row is dependent): the test the dense
// Gram-Schmidt of removeRedundantConstraints makes, so earlier rows are the ones kept.
// Computed by SuiteSparseQR (multifrontal Householder QR) of the row-normalised C^T with its
// columns (the equations) in their given order: the Householder step of column i leaves
// exactly that orthogonal component, and SPQR's rank detection (Heath's method) drops a column
// whose component is at most the tolerance. False if the factorisation fails (the caller then
// takes the dense path).
bool findDependentRows(const SparseMatrix& c, double relativeTolerance,
                       std::vector<bool>& dependent);

}  // namespace openmss::mechanics

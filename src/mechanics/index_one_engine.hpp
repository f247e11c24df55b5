#pragma once
// Internal to mechanics/: the engine of IndexOneDynamics (mechanics/index_one_dynamics.hpp), the
// block-sparse Schur complement of the KKT matrix shared by the evaluation and the projections.
// Defined in index_one_engine.cpp; only index_one_dynamics.cpp includes this header.

#include <Eigen/Dense>
#include <utility>
#include <vector>

#include "mechanics/constraint_rows.hpp"
#include "mechanics/index_one_dynamics.hpp"

namespace openmss::mechanics {

// The Schur complement S = C M^-1 C^T of the KKT matrix and its Cholesky factor, both in dense
// blocks (docs/theory.md §9f). The rows of C are grouped into blocks of equations that touch
// the same set of moving bodies (the five equations of a revolute joint form one block), so S is
// block-sparse with one nonzero block per pair of blocks sharing a body; the blocks are ordered
// by approximate minimum degree on this block graph and the fill is found once. Every numeric
// step then runs over precomputed offsets: no search, no allocation, small dense kernels.
struct IndexOneDynamics::Engine {
  explicit Engine(const MultibodySystem& system);

  // One (block, body) pair: the block's `rows` rows of C restricted to the body's 6 columns
  // (dense, row-major rows x 6: each row's six entries contiguous, as ConstraintRows delivers
  // them, so filling it is a copy of 6-entry segments) at `offset` in cDense and in w
  // (W = C M^-1, same shape).
  struct Incidence {
    int block = 0, body = 0, offset = 0, rows = 0;
  };
  // S_ij += W_p C_q^T into the block at `target` (column-major, rows(i) x rows(j)), i >= j;
  // `assign`: the first contribution to its block (overwrites instead of adding).
  struct Contribution {
    int p = 0, q = 0, target = 0;
    bool assign = false;
  };
  // L_ik -= L_ij L_kj^T (i >= k) within column j: sources are off-diagonal blocks of column j.
  struct Update {
    int source = 0, sourceRows = 0, other = 0, otherRows = 0, target = 0;
  };

  // C at the state y (entries in the order of rows.columns()) -> W, S and its factor. False
  // when S is singular or not finite. The positions of y are remembered (factoredAt).
  bool factor(const double* values, const Eigen::VectorXd& y);
  // Whether the factorisation is of C at exactly the positions (r, e) of y.
  bool factoredAt(const Eigen::VectorXd& y) const;
  // x <- S^-1 x (x in block order).
  void solve(double* x) const;
  // out (6 per body) = -M^-1 C^T x, with the C of the last factorisation.
  void correction(const double* x, Eigen::VectorXd& out) const;
  // max_r |(C u - nu)_r| with C in `values` (rows' order) and u from y; residual in block order.
  double velocityResidual(const double* values, const double* nu, const Eigen::VectorXd& y,
                          double* residual, double* scale) const;

  const MultibodySystem& system;
  ConstraintRows rows;
  int nb = 0, m = 0;
  bool baselineAccelerations = false;  // functions read accelerations or reactions
  bool massInvertible = true;          // every body has m > 0 and a positive-definite inertia
  std::vector<double> inverseMass;
  std::vector<Eigen::Matrix3d> inverseInertia;

  // Blocks in elimination order: rows blockStart[j] .. blockStart[j + 1] - 1 of the permuted
  // vector; permutedRow[pos] is the row (index into rows) at that position.
  std::vector<int> blockStart, permutedRow, positionOf;
  std::vector<Incidence> incidences;
  // Segment s of rows.values (entries 6 s .. 6 s + 5: one row, one body) -> index into cDense.
  std::vector<int> segmentTarget;
  // Segment s of rows.values -> index in y of its body's (v, w), six consecutive entries in
  // the order of C's columns (state_layout.hpp: kW = kV + 3).
  std::vector<int> segmentVelocity;
  std::vector<Contribution> contributions;
  // Factor storage: column j has its diagonal block (full, column-major) at diagOffset[j] and
  // the off-diagonal blocks offRow[s], offOffset[s] for s in offStart[j] .. offStart[j + 1] - 1.
  std::vector<int> diagOffset, offStart, offRow, offOffset;
  std::vector<int> updateStart;  // updates of column j: updateStart[j] .. updateStart[j + 1] - 1
  std::vector<Update> updates;
  std::vector<double> cDense, w, factorValues, sDiagonal, inverseDiagonal;
  // Per row of C: the translational and rotational parts of S's diagonal (see kPivotTolerance).
  std::vector<double> translationalPart, rotationalPart;
  std::vector<std::pair<int, int>> fillBlocks;  // (offset, entries) of blocks S has zero
  bool factored = false;
  int droppedRows = 0;                  // rows of C found dependent by the last factorisation
  std::vector<double> factorPositions;  // r and e of every body at the last factorisation
  // Tests run the kernels with the block size at run time too (the path of blocks of more
  // than 6 rows, which the bundled models do not have): 0 selects it in withSize.
  bool runtimeSizeKernels = false;
  int kernelSize(int rowsOfBlock) const { return runtimeSizeKernels ? 0 : rowsOfBlock; }

  // Scratch of one evaluation or projection (no allocation after the first call).
  std::vector<double> values, gamma, phi, nu, x;
  Eigen::VectorXd forces, delta;  // Q; M^-1 C^T times a multiplier vector
};

}  // namespace openmss::mechanics

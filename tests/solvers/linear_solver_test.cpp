// KLU against dense LU with partial pivoting on the same sparse systems: the solutions agree to
// round-off, refactorisation with new values on the analysed pattern stays exact, a new pattern
// is analysed anew, and a singular matrix yields NaNs (a failed Newton attempt), not garbage.

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "solvers/dense_linear_solver.hpp"
#include "solvers/klu_linear_solver.hpp"

namespace openmss::solvers {
namespace {

// A nonsymmetric band-plus-scatter matrix like a Newton matrix: a saddle-point-like block with
// zero diagonal entries (which need pivoting) and random couplings.
Eigen::SparseMatrix<double> randomSystem(int n, std::mt19937& rng, double zeroDiagonalShare) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    const bool zeroDiagonal = i >= n - static_cast<int>(zeroDiagonalShare * n);
    if (!zeroDiagonal) t.emplace_back(i, i, 4.0 + u(rng));
    for (int k = 1; k <= 2; ++k)
      if (i + k < n) {
        t.emplace_back(i, i + k, u(rng));
        t.emplace_back(i + k, i, u(rng) + (zeroDiagonal ? 2.0 : 0.0));
      }
    t.emplace_back(i, (i * 7 + 3) % n, 0.5 * u(rng));
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  return a;
}

double relativeDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / (1.0 + b.cwiseAbs().maxCoeff());
}

TEST(LinearSolver, KluEqualsDenseLu) {
  std::mt19937 rng(1);
  for (int n : {1, 5, 60, 400}) {
    const Eigen::SparseMatrix<double> a = randomSystem(n, rng, 0.2);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    KluLinearSolver klu;
    DenseLinearSolver dense;
    klu.analyze(a);
    dense.analyze(a);
    ASSERT_TRUE(klu.factor(a)) << n;
    ASSERT_TRUE(dense.factor(a)) << n;
    Eigen::VectorXd xk = b, xd = b;
    klu.solve(xk);
    dense.solve(xd);
    // Both are backward stable; this matrix is well conditioned (diagonal dominance in most
    // rows), so the solutions agree to a few hundred ulps.
    EXPECT_LE(relativeDifference(xk, xd), 1e-12) << n;
    // Backward error: the residual is round-off times |A| |x| (entries of order 1 to 5, a few
    // per row; x reaches a few hundred where the zero-diagonal rows make A less well
    // conditioned), so 1e-13 (1 + |x|) per row with a margin of ten.
    EXPECT_LE((a * xk - b).cwiseAbs().maxCoeff(), 1e-12 * (1.0 + xk.cwiseAbs().maxCoeff())) << n;
  }
}

// BTF's maximum transversal stopped at its work limit (as on the large planar chains,
// docs/performance.md "KLU's block triangular form, bounded") leaves a coarser block triangular
// form, not an approximate one: the solve is exact as before.
TEST(LinearSolver, KluWithTheTransversalStoppedSolvesExactly) {
  // Column j < n-1 holds rows j and j+1, the last column row 0 only: a greedy matching gives
  // column j row j and leaves the last column an augmenting path through all n columns (the
  // chains' case in miniature). Its one perfect matching is the cycle (values 1), so it is
  // nonsingular and well conditioned; the diagonal entries (0.5) mix the unknowns.
  const int n = 400;
  std::vector<Eigen::Triplet<double>> t;
  for (int j = 0; j + 1 < n; ++j) {
    t.emplace_back(j, j, 0.5);
    t.emplace_back(j + 1, j, 1.0);
  }
  t.emplace_back(0, n - 1, 1.0);
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(t.begin(), t.end());
  a.makeCompressed();
  const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
  KluLinearSolver full, stopped;
  KluLinearSolver::Options tight;
  tight.maxWork = 0.1;  // the path needs about n steps, 1/2 of the entries' count
  stopped.setOptions(tight);
  full.analyze(a);
  stopped.analyze(a);
  EXPECT_FALSE(full.transversalStopped());
  ASSERT_TRUE(stopped.transversalStopped());
  ASSERT_TRUE(full.factor(a));
  ASSERT_TRUE(stopped.factor(a));
  Eigen::VectorXd xf = b, xs = b;
  full.solve(xf);
  stopped.solve(xs);
  // Both backward stable: the residual is round-off times |A| |x| (as in KluEqualsDenseLu).
  EXPECT_LE((a * xs - b).cwiseAbs().maxCoeff(), 1e-12 * (1.0 + xs.cwiseAbs().maxCoeff()));
  EXPECT_LE(relativeDifference(xs, xf), 1e-12);
}

TEST(LinearSolver, KluRefactorsOnTheAnalysedPattern) {
  std::mt19937 rng(2);
  const int n = 200;
  Eigen::SparseMatrix<double> a = randomSystem(n, rng, 0.1);
  KluLinearSolver klu;
  klu.analyze(a);
  ASSERT_TRUE(klu.factor(a));
  EXPECT_EQ(klu.fullFactorizations(), 1);
  // New values on the same pattern (as from one Newton matrix to the next): refactored with
  // the old pivots, and exact.
  std::uniform_real_distribution<double> u(0.9, 1.1);
  for (int round = 0; round < 3; ++round) {
    for (int k = 0; k < a.nonZeros(); ++k) a.valuePtr()[k] *= u(rng);
    ASSERT_TRUE(klu.factor(a));
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    Eigen::VectorXd x = b;
    klu.solve(x);
    DenseLinearSolver dense;
    dense.analyze(a);
    dense.factor(a);
    Eigen::VectorXd xd = b;
    dense.solve(xd);
    EXPECT_LE(relativeDifference(x, xd), 1e-12);
  }
  EXPECT_GE(klu.refactorizations(), 3);
  // A different pattern is analysed anew rather than misread.
  const Eigen::SparseMatrix<double> other = randomSystem(n + 3, rng, 0.1);
  ASSERT_TRUE(klu.factor(other));
  Eigen::VectorXd x = Eigen::VectorXd::Ones(n + 3);
  klu.solve(x);
  EXPECT_LE((other * x - Eigen::VectorXd::Ones(n + 3)).cwiseAbs().maxCoeff(),
            1e-12 * (1.0 + x.cwiseAbs().maxCoeff()));
}

TEST(LinearSolver, SingularMatrixGivesNaN) {
  Eigen::SparseMatrix<double> a(3, 3);
  a.insert(0, 0) = 1.0;
  a.insert(1, 1) = 0.0;
  a.insert(2, 2) = 2.0;
  a.insert(1, 0) = 3.0;
  a.makeCompressed();
  KluLinearSolver klu;
  klu.analyze(a);
  EXPECT_FALSE(klu.factor(a));
  Eigen::VectorXd x = Eigen::VectorXd::Ones(3);
  klu.solve(x);
  EXPECT_TRUE(std::isnan(x(0)));
}

}  // namespace
}  // namespace openmss::solvers

// The supernodal LU against KLU on the same sparse systems, and the rule that picks between
// them (docs/theory.md §9a, "Linear solver"): a chain-like banded pattern stays with KLU, a
// three-dimensional grid of coupled blocks (the contact graph of a pile: heavy fill) goes to the
// supernodal LU, and either way the solution equals KLU's to round-off.

#include "solvers/sparse_linear_solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "solvers/klu_linear_solver.hpp"
#include "solvers/supernodal_linear_solver.hpp"

namespace openmss::solvers {
namespace {

using Matrix = Eigen::SparseMatrix<double>;

// k x k x k nodes of `d` unknowns each, every node coupled to its six neighbours through its
// first three unknowns (a pile's translations), unsymmetric values; the last unknown of every
// fifth node has a zero diagonal (a constraint-like row that needs pivoting).
Matrix gridSystem(int k, int d, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  auto index = [&](int x, int y, int z, int a) { return ((x * k + y) * k + z) * d + a; };
  for (int x = 0; x < k; ++x)
    for (int y = 0; y < k; ++y)
      for (int z = 0; z < k; ++z) {
        const bool zeroLast = index(x, y, z, 0) % (5 * d) == 0;
        for (int a = 0; a < d; ++a)
          for (int b = 0; b < d; ++b) {
            const bool diagonal = a == b;
            if (diagonal && zeroLast && a == d - 1) continue;
            t.emplace_back(index(x, y, z, a), index(x, y, z, b), u(rng) + (diagonal ? 8.0 : 0.0));
          }
        const int next[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        for (const auto& s : next) {
          const int X = x + s[0], Y = y + s[1], Z = z + s[2];
          if (X >= k || Y >= k || Z >= k) continue;
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
              t.emplace_back(index(x, y, z, a), index(X, Y, Z, b), u(rng));
              t.emplace_back(index(X, Y, Z, a), index(x, y, z, b), u(rng));
            }
        }
      }
  const int n = k * k * k * d;
  Matrix m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  m.makeCompressed();
  return m;
}

// A chain: blocks of `d` unknowns, each coupled to the next one (a revolute chain's pattern).
Matrix chainSystem(int links, int d, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Triplet<double>> t;
  for (int l = 0; l < links; ++l)
    for (int a = 0; a < d; ++a) {
      for (int b = 0; b < d; ++b) t.emplace_back(l * d + a, l * d + b, u(rng) + (a == b ? 8 : 0));
      if (l + 1 < links)
        for (int b = 0; b < 3; ++b) {
          t.emplace_back(l * d + a, (l + 1) * d + b, u(rng));
          t.emplace_back((l + 1) * d + b, l * d + a, u(rng));
        }
    }
  Matrix m(links * d, links * d);
  m.setFromTriplets(t.begin(), t.end());
  m.makeCompressed();
  return m;
}

Eigen::VectorXd solveWith(LinearSolver& solver, const Matrix& a, const Eigen::VectorXd& b) {
  EXPECT_TRUE(solver.factor(a));
  Eigen::VectorXd x = b;
  solver.solve(x);
  return x;
}

double relativeDifference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() / (1.0 + b.cwiseAbs().maxCoeff());
}

TEST(SparseLinearSolver, SupernodalEqualsKluOnAFilledGrid) {
  std::mt19937 rng(7);
  for (const int k : {2, 5, 8}) {
    Matrix a = gridSystem(k, 6, rng);
    const Eigen::VectorXd b = Eigen::VectorXd::Random(a.rows());
    KluLinearSolver klu;
    SupernodalLinearSolver supernodal;
    const Eigen::VectorXd xk = solveWith(klu, a, b);
    const Eigen::VectorXd xs = solveWith(supernodal, a, b);
    // Both backward stable on a matrix dominated by its diagonal blocks (|diagonal| 7-9
    // against at most 6 x 1 + 3 x 6 off it in a row): condition of order 10, so the solutions
    // agree to a few hundred ulps of |x|.
    EXPECT_LE(relativeDifference(xs, xk), 1e-12) << k;
    EXPECT_LE((a * xs - b).cwiseAbs().maxCoeff(), 1e-12 * (1.0 + xs.cwiseAbs().maxCoeff())) << k;
    // Fill: AMD on A + Aᵀ with the diagonal kept as pivot, as KLU's: equal to within 10 %.
    EXPECT_LE(static_cast<double>(supernodal.factorNonZeros()),
              1.1 * static_cast<double>(klu.factorNonZeros()))
        << k;
    // New values on the same pattern (the next Newton matrix) are factorised without a new
    // analysis and stay exact; the same values again give the same bits.
    for (int e = 0; e < a.nonZeros(); ++e) a.valuePtr()[e] *= 1.0 + 0.1 * std::sin(e);
    const Eigen::VectorXd again = solveWith(supernodal, a, b);
    EXPECT_LE(relativeDifference(again, solveWith(klu, a, b)), 1e-12) << k;
    const Eigen::VectorXd twice = solveWith(supernodal, a, b);
    EXPECT_EQ(0, std::memcmp(again.data(), twice.data(), sizeof(double) * again.size())) << k;
  }
}

TEST(SparseLinearSolver, ChainsStayWithKluAndFilledPatternsGoSupernodal) {
  std::mt19937 rng(8);
  SparseLinearSolver solver;
  // A 1000-link chain of 19-unknown links: KLU's analysis predicts little work (no fill
  // beyond the blocks), far below kSupernodalFlops.
  const Matrix chain = chainSystem(1000, 19, rng);
  const Eigen::VectorXd bc = Eigen::VectorXd::Random(chain.rows());
  const Eigen::VectorXd xc = solveWith(solver, chain, bc);
  EXPECT_FALSE(solver.supernodal());
  EXPECT_STREQ(solver.name(), "KLU");
  EXPECT_LT(solver.predictedFlops(), SparseLinearSolver::kSupernodalFlops);
  KluLinearSolver klu;
  EXPECT_EQ(0,
            std::memcmp(xc.data(), solveWith(klu, chain, bc).data(), sizeof(double) * xc.size()));
  // A 12 x 12 x 12 grid of 6-unknown nodes (a landed 1000-sphere pile's contact graph in
  // miniature): KLU predicts over 1e8 flops, the supernodal LU takes it, same solution.
  const Matrix grid = gridSystem(12, 6, rng);
  const Eigen::VectorXd bg = Eigen::VectorXd::Random(grid.rows());
  const Eigen::VectorXd xg = solveWith(solver, grid, bg);
  EXPECT_TRUE(solver.supernodal());
  EXPECT_STREQ(solver.name(), "supernodal LU");
  EXPECT_GE(solver.predictedFlops(), SparseLinearSolver::kSupernodalFlops);
  EXPECT_LE(relativeDifference(xg, solveWith(klu, grid, bg)), 1e-12);
  // Back to the chain's pattern: KLU again, bit for bit as before.
  EXPECT_EQ(
      0, std::memcmp(xc.data(), solveWith(solver, chain, bc).data(), sizeof(double) * xc.size()));
  EXPECT_FALSE(solver.supernodal());
}

TEST(SparseLinearSolver, SupernodalSingularMatrixGivesNaN) {
  Matrix a(3, 3);
  a.insert(0, 0) = 1.0;
  a.insert(1, 1) = 0.0;
  a.insert(2, 2) = 2.0;
  a.insert(1, 0) = 3.0;
  a.makeCompressed();
  SupernodalLinearSolver supernodal;
  EXPECT_FALSE(supernodal.factor(a));
  Eigen::VectorXd x = Eigen::VectorXd::Ones(3);
  supernodal.solve(x);
  EXPECT_TRUE(std::isnan(x(0)));
}

}  // namespace
}  // namespace openmss::solvers

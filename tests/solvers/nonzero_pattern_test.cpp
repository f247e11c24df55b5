// The pattern the BDF family factorises (solvers/nonzero_pattern.hpp, docs/theory.md §9a): the
// entries of the structural Newton matrix that have been nonzero, growing only. The selection
// must hold exactly those entries with the current values, keep an entry that turns zero
// again, start over when the structure changes, and give KLU the same solution as the full
// structure (to round-off) with fewer entries in L + U.

#include "solvers/nonzero_pattern.hpp"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "solvers/klu_linear_solver.hpp"

namespace openmss::solvers {
namespace {

using Matrix = Eigen::SparseMatrix<double>;

// A block-tridiagonal structure (blocks of 6, as a chain of bodies) whose every third
// off-diagonal entry holds an exact zero; the diagonal is dominant.
Matrix structure(int blocks, std::mt19937& rng, bool zeroSome) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int d = 6, n = blocks * d;
  std::vector<Eigen::Triplet<double>> t;
  int count = 0;
  for (int b = 0; b < blocks; ++b)
    for (int nb = std::max(0, b - 1); nb <= std::min(blocks - 1, b + 1); ++nb)
      for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j) {
          const int r = b * d + i, c = nb * d + j;
          double v = r == c ? 20.0 + u(rng) : u(rng);
          if (zeroSome && r != c && ++count % 3 == 0) v = 0.0;
          t.emplace_back(r, c, v);
        }
  Matrix m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  m.makeCompressed();
  return m;
}

long nonzeros(const Matrix& m) {
  long k = 0;
  for (Eigen::Index e = 0; e < m.nonZeros(); ++e) k += m.valuePtr()[e] != 0.0;
  return k;
}

TEST(NonzeroPattern, SelectsTheNonzerosAndSolvesAsTheFullStructure) {
  std::mt19937 rng(7);
  const Matrix full = structure(40, rng, true);
  NonzeroPattern pattern;
  bool grew = false;
  const Matrix& selected = pattern.select(full, &grew);
  EXPECT_TRUE(grew);
  EXPECT_EQ(selected.nonZeros(), nonzeros(full));
  EXPECT_LT(selected.nonZeros(), full.nonZeros());
  EXPECT_EQ((Matrix(selected) - full).norm(), 0.0);  // the same matrix, zeros left out

  Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(full.rows(), -1.0, 2.0), x1 = b, x2 = b;
  KluLinearSolver onFull, onSelected;
  ASSERT_TRUE(onFull.factor(full));
  ASSERT_TRUE(onSelected.factor(selected));
  onFull.solve(x1);
  onSelected.solve(x2);
  // Diagonally dominant (condition ~2): the two pivot orders agree to a few ulps of |x|.
  EXPECT_LT((x1 - x2).cwiseAbs().maxCoeff(), 1e-13 * (1.0 + x1.cwiseAbs().maxCoeff()));
  EXPECT_LT(onSelected.factorNonZeros(), onFull.factorNonZeros());
}

TEST(NonzeroPattern, GrowsOnlyAndStartsOverOnANewStructure) {
  std::mt19937 rng(11);
  Matrix full = structure(10, rng, true);
  NonzeroPattern pattern;
  bool grew = false;
  const long first = pattern.select(full, &grew).nonZeros();
  // The same values again: no growth, nothing to analyse.
  EXPECT_EQ(pattern.select(full, &grew).nonZeros(), first);
  EXPECT_FALSE(grew);
  // One kept entry turns zero, one left-out entry turns nonzero: the selection keeps the first
  // (holding 0.0) and gains the second.
  int keptIndex = -1, zeroIndex = -1;
  for (int e = 0; e < full.nonZeros(); ++e) {
    if (full.valuePtr()[e] != 0.0 && keptIndex < 0 && full.innerIndexPtr()[e] != 0) keptIndex = e;
    if (full.valuePtr()[e] == 0.0 && zeroIndex < 0) zeroIndex = e;
  }
  ASSERT_GE(keptIndex, 0);
  ASSERT_GE(zeroIndex, 0);
  full.valuePtr()[keptIndex] = 0.0;
  full.valuePtr()[zeroIndex] = 0.5;
  const Matrix& grown = pattern.select(full, &grew);
  EXPECT_TRUE(grew);
  EXPECT_EQ(grown.nonZeros(), first + 1);
  EXPECT_EQ((Matrix(grown) - full).norm(), 0.0);
  // A different structure (fewer blocks): the selection starts from its nonzeros alone.
  const Matrix other = structure(8, rng, true);
  const Matrix& fresh = pattern.select(other, &grew);
  EXPECT_TRUE(grew);
  EXPECT_EQ(fresh.nonZeros(), nonzeros(other));
  EXPECT_EQ((Matrix(fresh) - other).norm(), 0.0);
}

}  // namespace
}  // namespace openmss::solvers

// BdfIntegrator's fused passes (solvers/bdf_vector_passes.hpp) against the Eigen vector
// expressions they replace, one pass per expression: every entry must agree to the last bit,
// signed zeros, infinities and NaNs included (docs/performance.md, "GSTIFF's cost per step,
// cheaper"). Odd lengths exercise the vector loops' scalar tails.

#include "solvers/bdf_vector_passes.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace openmss::solvers::bdf {
namespace {

// Bitwise equality (NaN payloads included), with the first differing entry named.
void expectSameBits(const Eigen::VectorXd& a, const Eigen::VectorXd& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (Eigen::Index i = 0; i < a.size(); ++i)
    ASSERT_EQ(std::bit_cast<std::uint64_t>(a(i)), std::bit_cast<std::uint64_t>(b(i)))
        << what << ", entry " << i << ": " << a(i) << " vs " << b(i);
}

// Random entries of mixed magnitude and sign, with a few zeros of both signs and, when asked,
// an infinity and a NaN.
Eigen::VectorXd randomVector(Eigen::Index n, std::mt19937& rng, bool special) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> e(-30, 30);
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i) v(i) = std::ldexp(u(rng), e(rng));
  v(0) = 0.0;
  if (n > 3) v(3) = -0.0;
  if (special && n > 7) {
    v(5) = std::numeric_limits<double>::infinity();
    v(7) = std::numeric_limits<double>::quiet_NaN();
  }
  return v;
}

TEST(BdfVectorPasses, CombineIsTheAxpySequence) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> w(-2.0, 2.0);
  for (Eigen::Index n : {1, 2, 7, 64, 1901}) {
    for (int m = 1; m <= 8; ++m) {
      std::vector<Eigen::VectorXd> src;
      std::vector<const double*> ptr;
      double weights[8];
      for (int j = 0; j < m; ++j) {
        src.push_back(randomVector(n, rng, j == 1));
        weights[j] = j == 2 ? -0.0 : w(rng);
      }
      for (const Eigen::VectorXd& s : src) ptr.push_back(s.data());
      // The predictor's and the corrector history's form: setZero, then += w_j y_j.
      Eigen::VectorXd expected = Eigen::VectorXd::Zero(n);
      for (int j = 0; j < m; ++j) expected += weights[j] * src[static_cast<size_t>(j)];
      Eigen::VectorXd got(n);
      combineFromZero(got.data(), ptr.data(), weights, m, n);
      expectSameBits(got, expected,
                     "from zero, n " + std::to_string(n) + ", m " + std::to_string(m));
      // GSTIFF's re-sampled history: v = w_0 y_0, then += w_j y_j.
      expected = weights[0] * src[0];
      for (int j = 1; j < m; ++j) expected += weights[j] * src[static_cast<size_t>(j)];
      combine(got.data(), ptr.data(), weights, m, n);
      expectSameBits(got, expected, "plain, n " + std::to_string(n) + ", m " + std::to_string(m));
    }
  }
}

TEST(BdfVectorPasses, CorrectorChangeIsTheSeparatePasses) {
  std::mt19937 rng(9);
  using Later = CorrectorUpdate::Later;
  for (Eigen::Index n : {1, 9, 1901}) {
    for (bool rescale : {false, true}) {
      for (Later later : {Later::None, Later::Assign, Later::Add}) {
        const Eigen::VectorXd dy0 = randomVector(n, rng, true), col = randomVector(n, rng, false),
                              y0 = randomVector(n, rng, false), base = randomVector(n, rng, false),
                              later0 = randomVector(n, rng, false).cwiseAbs();
        CorrectorUpdate u;
        u.rescale = rescale;
        u.cjFactor = rescale ? 0.8731 : 1.0;
        u.cj = 1234.5;
        u.later = later;
        // The passes as the corrector made them before the fusion.
        Eigen::VectorXd dy = dy0.cwiseProduct(col);
        if (rescale) dy *= u.cjFactor;
        const Eigen::VectorXd y = y0 - dy;
        const Eigen::VectorXd yp = u.cj * y + base;
        Eigen::VectorXd changes = later0;
        if (later == Later::Assign) changes = Eigen::VectorXd::Zero(n) + dy.cwiseAbs();
        if (later == Later::Add) changes += dy.cwiseAbs();
        Eigen::VectorXd dyGot = dy0, yGot = y0, ypGot(n), changesGot = later0;
        applyCorrectorChange(u, dyGot.data(), col.data(), yGot.data(), base.data(), ypGot.data(),
                             changesGot.data(), n);
        const std::string what = "n " + std::to_string(n) + (rescale ? ", rescaled" : "") +
                                 ", later " + std::to_string(static_cast<int>(later));
        expectSameBits(dyGot, dy, what + ": change");
        expectSameBits(yGot, y, what + ": y");
        expectSameBits(ypGot, yp, what + ": y'");
        expectSameBits(changesGot, changes, what + ": later changes");
      }
    }
  }
}

}  // namespace
}  // namespace openmss::solvers::bdf

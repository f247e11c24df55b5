// The element-local Newton matrix (mechanics/local_newton_matrix.hpp) against the two
// independent evaluations of the same matrix: the dense forward-AD matrix (one residual pass per
// column) and the compressed colouring of the whole residual. Both differentiate the residual
// itself, so agreement to round-off says the hand-written body blocks, the local passes over the
// constraint equations and the force/user remainder add up to dG/dy + cj dG/dy' entry by entry.
// The residual's analytic constraint forces are held to central differences as every equation
// is (support/newton_matrix_check.hpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>

#include "language/reader.hpp"
#include "mechanics/jacobian_pattern.hpp"
#include "mechanics/local_newton_matrix.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "support/newton_matrix_check.hpp"
#include "support/random_state.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;

model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "local.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// A spatial chain with one joint of each kind the analytic gradients cover and of several they
// do not (spherical: Point; translational, cylindrical, universal, planar, fixed: Dot and Along;
// revolute with a rotation MOTION; translational with a translation MOTION; a COUPLER), plus
// force elements and user equations for the compressed remainder.
std::string mixedChain(bool withForces) {
  std::ostringstream s;
  s << "mixed\nUNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
       "PART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0\nMARKER/11, PART=1, QP=0,0,0\n";
  const char* joints[] = {"REVOLUTE", "SPHERICAL", "TRANSLATIONAL", "CYLINDRICAL",
                          "UNIVERSAL", "REVOLUTE", "PLANAR",   "TRANSLATIONAL"};
  const int links = 8;
  for (int i = 0; i < links; ++i) {
    const int p = i + 2;
    s << "PART/" << p << ", MASS=" << 1.0 + 0.1 * i << ", CM=" << 10 * p
      << ", IP=0.05,0.1,0.12\n"
      << "MARKER/" << 10 * p << ", PART=" << p << ", QP=" << i + 0.5 << ",0,0\n"
      << "MARKER/" << 10 * p + 1 << ", PART=" << p << ", QP=" << i << ",0,0"
      << (std::string(joints[i]) == "UNIVERSAL" ? ", REULER=0D,90D,0D" : "") << "\n"
      << "MARKER/" << 10 * p + 2 << ", PART=" << p << ", QP=" << i + 1 << ",0,0\n";
    const int parentTip = i == 0 ? 10 : 10 * (p - 1) + 2;
    s << "JOINT/" << p << ", " << joints[i] << ", I=" << 10 * p + 1 << ", J=" << parentTip
      << "\n";
    if (withForces && i >= 2)
      s << "SPRINGDAMPER/" << p << ", TRANSLATIONAL, I=" << 10 * p << ", J=" << 10 * (p - 2)
        << ", K=50, C=0.5, LENGTH=2\n";
  }
  s << "MOTION/1, JOINT=2, FUNCTION=0.3*SIN(2*TIME)\n"
    << "MOTION/2, JOINT=9, FUNCTION=0.1*TIME\n";
  if (withForces)
    s << "SFORCE/1, TRANSLATION, I=72, J=10, FUNCTION=-10*(DM(72,10)-3)-0.2*VR(72,10)\n"
      << "VARIABLE/1, FUNCTION=DX(52,10)\n"
      << "DIFF/1, FUNCTION=VARVAL(1)-DIF(1), IC=0\n"
      << "SFORCE/2, ROTATION, I=91, J=82, FUNCTION=-DIF(1)\n";
  s << "ACCGRAV/JGRAV=-9.80665\nEND\n";
  return s.str();
}

// Largest |a - b| over the pattern, relative to 1 + the largest |entry| of the row.
double largestDifference(const Eigen::SparseMatrix<double>& a, const Eigen::MatrixXd& b) {
  Eigen::VectorXd scale = Eigen::VectorXd::Ones(b.rows());
  for (int r = 0; r < b.rows(); ++r) scale(r) += b.row(r).cwiseAbs().maxCoeff();
  const Eigen::MatrixXd da(a);
  double worst = 0.0;
  for (int r = 0; r < b.rows(); ++r)
    for (int c = 0; c < b.cols(); ++c)
      worst = std::max(worst, std::abs(da(r, c) - b(r, c)) / scale(r));
  return worst;
}

struct Evaluation {
  Eigen::SparseMatrix<double> local, coloured;
  Eigen::MatrixXd dense;
  bool usedLocal = false;
};

Evaluation evaluate(const MultibodySystem& s, const JacobianPattern& pattern, double t,
                    const Eigen::VectorXd& y, const Eigen::VectorXd& yp, double cj) {
  Evaluation e;
  SparseJacobianWork work;
  e.local = pattern.matrix();
  s.newtonMatrixSparse(t, y, yp, cj, pattern, e.local, work);
  e.usedLocal = work.local && work.local->usable();
  SparseJacobianWork whole;
  whole.elementLocal = false;
  e.coloured = pattern.matrix();
  s.newtonMatrixSparse(t, y, yp, cj, pattern, e.coloured, whole);
  s.newtonMatrix(t, y, yp, cj, e.dense);
  return e;
}

// Round-off of sums of a few dozen products of order-one numbers, times the row scale.
constexpr double kRoundOff = 1e-12;

TEST(LocalNewtonMatrix, MatchesDenseAndColouredOnEveryJointKindWithForces) {
  for (bool withForces : {false, true}) {
    const model::Model m = build(mixedChain(withForces));
    const MultibodySystem s(m);
    const JacobianPattern pattern = newtonMatrixPattern(s);
    std::mt19937 rng(17);
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::VectorXd y = testing::randomState(s, rng, testing::RandomMu::Yes);
      const Eigen::VectorXd yp = Eigen::VectorXd::Random(s.layout().size());
      const Evaluation e = evaluate(s, pattern, 0.3 + trial, y, yp, 37.0);
      EXPECT_TRUE(e.usedLocal) << "forces " << withForces;
      EXPECT_LT(largestDifference(e.local, e.dense), kRoundOff) << "trial " << trial;
      EXPECT_LT(largestDifference(e.local, Eigen::MatrixXd(e.coloured)), kRoundOff);
      // And the residual's own matrix against central differences (analytic C^T lambda).
      if (trial == 0) testing::checkNewtonMatrix(s, 0.3, y, yp, 37.0, "mixed chain");
    }
  }
}

// Euler parameters off the unit sphere (as inside a Newton iteration): the quadratic rotation
// matrix is then not orthogonal, and the analytic gradients must still be the residual's.
TEST(LocalNewtonMatrix, ExactOffTheUnitSphere) {
  const model::Model m = build(mixedChain(true));
  const MultibodySystem s(m);
  const JacobianPattern pattern = newtonMatrixPattern(s);
  std::mt19937 rng(5);
  Eigen::VectorXd y = testing::randomState(s, rng, testing::RandomMu::Yes);
  for (int b = 0; b < s.layout().bodies; ++b)
    y.segment<4>(s.layout().body(b) + L::kE) *= 1.0 + 0.03 * (b + 1);
  const Eigen::VectorXd yp = Eigen::VectorXd::Random(s.layout().size());
  const Evaluation e = evaluate(s, pattern, 0.1, y, yp, 5.0);
  EXPECT_TRUE(e.usedLocal);
  EXPECT_LT(largestDifference(e.local, e.dense), kRoundOff);
  testing::checkNewtonMatrix(s, 0.1, y, yp, 5.0, "off the unit sphere");
}

// A removed (redundant) equation: its row is lambda = 0 and it loads no body.
TEST(LocalNewtonMatrix, InactiveEquations) {
  const model::Model m = build(mixedChain(false));
  MultibodySystem s(m);
  s.constraints().equations()[1].active = false;
  s.constraints().equations()[7].active = false;
  const JacobianPattern pattern = newtonMatrixPattern(s);
  std::mt19937 rng(9);
  const Eigen::VectorXd y = testing::randomState(s, rng);
  const Eigen::VectorXd yp = Eigen::VectorXd::Random(s.layout().size());
  const Evaluation e = evaluate(s, pattern, 0.0, y, yp, 11.0);
  EXPECT_TRUE(e.usedLocal);
  EXPECT_LT(largestDifference(e.local, e.dense), kRoundOff);
}

// A repaired pattern (dense rows) is not planned element by element: the whole residual is
// coloured, and the numbers are the same.
TEST(LocalNewtonMatrix, DenseRowsFallBackToColouring) {
  const model::Model m = build(mixedChain(true));
  const MultibodySystem s(m);
  JacobianPattern pattern = newtonMatrixPattern(s);
  makeRowsDense(pattern, {s.layout().body(2) + L::kV});
  std::mt19937 rng(4);
  const Eigen::VectorXd y = testing::randomState(s, rng);
  const Eigen::VectorXd yp = Eigen::VectorXd::Random(s.layout().size());
  const Evaluation e = evaluate(s, pattern, 0.0, y, yp, 11.0);
  EXPECT_FALSE(e.usedLocal);
  EXPECT_LT(largestDifference(e.local, e.dense), kRoundOff);
}

}  // namespace
}  // namespace openmss::mechanics

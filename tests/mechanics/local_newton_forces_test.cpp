// The state-local force elements' entries of the element-local Newton matrix
// (src/mechanics/local_newton_forces.cpp: one multi-direction AD pass per SPRINGDAMPER,
// BUSHING, FIELD, BEAM) against three independent evaluations of the same matrix: the dense
// forward-AD matrix of the whole residual, the compressed colouring of the whole residual, and
// central differences of the residual; and, with only such elements, bit for bit against the
// coloured passes they replace (each direction of the multi-direction dual does the Dual's
// operations, and the sums run in the residual's order: docs/theory.md, "Element-local Newton
// matrix").

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

#include "common/parallel_for.hpp"
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
  language::readDatasetText(text, "forces.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// Three parts, a revolute to ground and a spherical between two of them (constraint rows in the
// same matrix), and every state-local element kind between two moving parts and between a part
// and ground: translational and rotational SPRINGDAMPERs, a BUSHING, a FIELD with full
// unsymmetric matrices, a BEAM. With `coloured`, an SFORCE and a VARIABLE and DIFF too, which
// stay on the coloured passes, so that both paths write into one matrix.
std::string model(bool coloured) {
  std::string s =
      "local force elements\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "MARKER/11, PART=1, QP=0,0,-1, REULER=20D,0,0\n"
      "PART/2, MASS=2, CM=20, IP=0.3,0.4,0.5\n"
      "MARKER/20, PART=2, QP=0.2,0.1,0.3\n"
      "MARKER/21, PART=2, QP=1,0.1,0\n"
      "MARKER/22, PART=2, QP=0,0,0.5, REULER=10D,5D,0\n"
      "MARKER/24, PART=2, QP=0,0,0\n"
      "MARKER/25, PART=2, QP=1,0.2,0\n"
      "PART/3, MASS=3, CM=30, IP=0.5,0.6,0.7, QG=1.5,0,0\n"
      "MARKER/30, PART=3\n"
      "MARKER/31, PART=3, QP=0.1,0.2,0.4\n"
      "MARKER/32, PART=3, QP=-0.5,0,0, REULER=0,15D,5D\n"
      "MARKER/33, PART=3, QP=1,0.1,0\n"
      "PART/4, MASS=1.5, CM=40, IP=0.2,0.3,0.25, QG=2.5,0.2,0\n"
      "MARKER/40, PART=4\n"
      "MARKER/41, PART=4, QP=0.1,-0.2,0.3, REULER=30D,0,10D\n"
      "MARKER/42, PART=4, QP=-0.1,0,0\n"
      "JOINT/1, REVOLUTE, I=24, J=10\n"
      "JOINT/2, SPHERICAL, I=32, J=21\n"
      "SPRINGDAMPER/1, TRANSLATIONAL, I=31, J=20, K=40, C=3, LENGTH=1.2, FORCE=2\n"
      "SPRINGDAMPER/2, ROTATIONAL, I=41, J=11, KT=20, CT=1.5, ANGLE=0.2, TORQUE=0.5\n"
      "SPRINGDAMPER/3, ROTATIONAL, I=40, J=33, KT=8, CT=0.7\n"
      "SPRINGDAMPER/4, TRANSLATIONAL, I=40, J=10, K=15, C=0.4, LENGTH=2\n"
      "BUSHING/1, I=41, J=33, K=100,200,300, C=1,2,3, KT=10,20,30, CT=0.1,0.2,0.3,"
      " FORCE=1,2,3, TORQUE=0.1,0.2,0.3\n"
      "FIELD/1, I=31, J=22,"
      " KMATRIX=50,1,2,3,4,5, 1.5,60,2,3,4,5, 2,1,70,3,4,5, 3,2,1,40,0.5,0.6,"
      " 0.4,2,1,0.3,45,0.7, 0.5,2,1,0.3,0.2,55,"
      " CRATIO=0.01, LENGTH=1,0.1,0.2,0.05,0.02,0.01, FORCE=1,2,3,0.4,0.5,0.6\n"
      "BEAM/1, I=42, J=25, LENGTH=1.4, AREA=0.01, IXX=2e-5, IYY=1e-5, IZZ=1.5e-5,"
      " EMODULUS=1e6, GMODULUS=4e5, ASY=1.2, ASZ=1.1,"
      " CMATRIX=0.1, 0,0.2, 0,0,0.3, 0,0,0,0.01, 0,0,0,0,0.02, 0,0.01,0,0,0,0.03\n";
  if (coloured)
    s += "SFORCE/1, TRANSLATION, I=41, J=21, FUNCTION=-5*(DM(41,21)-0.4)-0.3*VR(41,21)\n"
         "VARIABLE/1, FUNCTION=DX(40,10)\n"
         "DIFF/1, FUNCTION=VARVAL(1)-DIF(1), IC=0\n"
         "SFORCE/2, ROTATION, I=30, J=20, FUNCTION=-DIF(1)\n";
  return s + "ACCGRAV/JGRAV=-9.80665\nEND\n";
}

// Largest |a - b| relative to 1 + the largest |entry| of b's row.
double largestDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  double worst = 0.0;
  for (int r = 0; r < b.rows(); ++r) {
    const double scale = 1.0 + b.row(r).cwiseAbs().maxCoeff();
    worst = std::max(worst, (a.row(r) - b.row(r)).cwiseAbs().maxCoeff() / scale);
  }
  return worst;
}

struct Matrices {
  Eigen::MatrixXd local, colouredForces, whole, dense;
  int localElements = 0, localElementsWithoutLocalForces = -1;
};

Matrices evaluate(const MultibodySystem& s, double t, const Eigen::VectorXd& y,
                  const Eigen::VectorXd& yp, double cj) {
  const JacobianPattern pattern = newtonMatrixPattern(s);
  Matrices out;
  Eigen::SparseMatrix<double> a = pattern.matrix();
  SparseJacobianWork local;
  s.newtonMatrixSparse(t, y, yp, cj, pattern, a, local);
  EXPECT_TRUE(local.local && local.local->usable());
  out.localElements = local.local ? local.local->stateLocalForceElements() : 0;
  out.local = Eigen::MatrixXd(a);
  SparseJacobianWork colouredForces;  // every force element on the coloured passes
  colouredForces.forceElementsLocal = false;
  s.newtonMatrixSparse(t, y, yp, cj, pattern, a, colouredForces);
  out.localElementsWithoutLocalForces = colouredForces.local->stateLocalForceElements();
  out.colouredForces = Eigen::MatrixXd(a);
  SparseJacobianWork whole;  // the whole residual coloured
  whole.elementLocal = false;
  s.newtonMatrixSparse(t, y, yp, cj, pattern, a, whole);
  out.whole = Eigen::MatrixXd(a);
  s.newtonMatrix(t, y, yp, cj, out.dense);
  return out;
}

// Round-off of sums of a few dozen products, relative to the row scale (entries reach ~1e3:
// stiffnesses times lever arms).
constexpr double kRoundOff = 1e-12;
// Central differences: 1e-6 as tests/support/newton_matrix_check.hpp, relative to the row scale.
constexpr double kDifferences = 1e-6;

TEST(LocalNewtonForces, MatchesDenseColouredAndDifferencesWithBothPaths) {
  const model::Model m = build(model(true));
  const MultibodySystem s(m);
  std::mt19937 rng(23);
  for (int trial = 0; trial < 2; ++trial) {
    Eigen::VectorXd y = testing::randomState(s, rng, testing::RandomMu::Yes);
    if (trial == 1)  // off the unit sphere, as inside a Newton iteration
      for (int b = 0; b < s.layout().bodies; ++b)
        y.segment<4>(s.layout().body(b) + L::kE) *= 1.0 + 0.04 * (b + 1);
    const Eigen::VectorXd yp = Eigen::VectorXd::Random(s.layout().size());
    const double t = 0.4, cj = 29.0;
    const Matrices e = evaluate(s, t, y, yp, cj);
    EXPECT_EQ(e.localElements, 7);  // four SPRINGDAMPERs, BUSHING, FIELD, BEAM
    EXPECT_EQ(e.localElementsWithoutLocalForces, 0);
    EXPECT_LT(largestDifference(e.local, e.dense), kRoundOff) << "trial " << trial;
    EXPECT_LT(largestDifference(e.local, e.whole), kRoundOff) << "trial " << trial;
    EXPECT_LT(largestDifference(e.local, e.colouredForces), kRoundOff) << "trial " << trial;
    EXPECT_LT(largestDifference(e.local, testing::centralDifferenceMatrix(s, t, y, yp, cj)),
              kDifferences)
        << "trial " << trial;
  }
}

// With state-local elements only, every entry is the coloured passes' to the bit (the same
// operations per direction, summed in the same order).
TEST(LocalNewtonForces, BitIdenticalToTheColouredPassesItReplaces) {
  const model::Model m = build(model(false));
  const MultibodySystem s(m);
  std::mt19937 rng(31);
  const Eigen::VectorXd y = testing::randomState(s, rng, testing::RandomMu::Yes);
  const Eigen::VectorXd yp = Eigen::VectorXd::Random(s.layout().size());
  const Matrices e = evaluate(s, 0.0, y, yp, 13.0);
  EXPECT_EQ(e.localElements, 7);
  int nonzero = 0;
  for (int r = 0; r < e.local.rows(); ++r)
    for (int c = 0; c < e.local.cols(); ++c) {
      EXPECT_EQ(e.local(r, c), e.colouredForces(r, c)) << "row " << r << " column " << c;
      nonzero += e.local(r, c) != 0.0 ? 1 : 0;
    }
  EXPECT_GT(nonzero, 500);  // compares something: the three bodies' coupled blocks
  EXPECT_LT(largestDifference(e.local, testing::centralDifferenceMatrix(s, 0.0, y, yp, 13.0)),
            kDifferences);
}

// model(false) with its seven force elements repeated `copies` times (ids + 10 k): enough of
// them for their passes to run on the thread pool (local_newton_forces.cpp).
std::string manyElements(int copies) {
  std::istringstream in(model(false));
  std::string line, head, elements;
  while (std::getline(in, line)) {
    const bool element = line.starts_with("SPRINGDAMPER/") || line.starts_with("BUSHING/") ||
                         line.starts_with("FIELD/") || line.starts_with("BEAM/");
    if (element) elements += line + "\n";
    if (line.starts_with("ACCGRAV")) break;
    head += line + "\n";
  }
  for (int k = 1; k < copies; ++k) {
    std::istringstream again(elements);
    while (std::getline(again, line)) {
      const size_t slash = line.find('/'), comma = line.find(',');
      head += line.substr(0, slash + 1) +
              std::to_string(std::stoi(line.substr(slash + 1, comma - slash - 1)) + 10 * k) +
              line.substr(comma) + "\n";
    }
  }
  return head + "ACCGRAV/JGRAV=-9.80665\nEND\n";
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// On the thread pool: one thread and two give the same matrix to the bit (the sign of zeros
// included), and both are the coloured passes' (serial) to the bit: the passes write their own
// terms and one loop sums them in element order (docs/architecture.md, "Threads").
TEST(LocalNewtonForces, BitIdenticalForOneAndTwoThreadsOnThePool) {
  const model::Model m = build(manyElements(6));
  const MultibodySystem s(m);
  std::mt19937 rng(37);
  const Eigen::VectorXd y = testing::randomState(s, rng, testing::RandomMu::Yes);
  const Eigen::VectorXd yp = Eigen::VectorXd::Random(s.layout().size());
  const JacobianPattern pattern = newtonMatrixPattern(s);
  Eigen::MatrixXd byThreads[2];
  for (int threads : {1, 2}) {
    setThreadCountForTesting(threads);
    Eigen::SparseMatrix<double> a = pattern.matrix();
    SparseJacobianWork work;
    s.newtonMatrixSparse(0.0, y, yp, 13.0, pattern, a, work);
    ASSERT_TRUE(work.local && work.local->usable());
    EXPECT_EQ(work.local->stateLocalForceElements(), 42);
    EXPECT_TRUE(work.local->forceElementsOnThePool());  // 42 >= the threshold, 32
    byThreads[threads - 1] = Eigen::MatrixXd(a);
  }
  setThreadCountForTesting(0);
  const Matrices e = evaluate(s, 0.0, y, yp, 13.0);
  int nonzero = 0;
  for (int r = 0; r < e.local.rows(); ++r)
    for (int c = 0; c < e.local.cols(); ++c) {
      EXPECT_TRUE(sameBits(byThreads[0](r, c), byThreads[1](r, c))) << r << ", " << c;
      EXPECT_TRUE(sameBits(byThreads[0](r, c), e.colouredForces(r, c))) << r << ", " << c;
      nonzero += byThreads[0](r, c) != 0.0 ? 1 : 0;
    }
  EXPECT_GT(nonzero, 500);
  EXPECT_LT(largestDifference(byThreads[1], testing::centralDifferenceMatrix(s, 0.0, y, yp, 13.0)),
            kDifferences);
}

}  // namespace
}  // namespace openmss::mechanics

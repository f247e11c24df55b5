// The sparse SI2 Newton matrix (analysis/multibody_dae_si2.hpp, docs/theory.md §9a) against two
// independent evaluations: the exact dense forward-AD matrix of the index-3 equations (the SI2
// matrix's upper-left block at eta = 0 is that matrix) and fourth-order central differences of
// the SI2 residual itself (every column, every row, with eta and the state off the solution).
// Then the sparse (KLU) paths of DSTIFF and GSTIFF,SI2 against their dense (LU) paths.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <sstream>
#include <string>

#include "analysis/multibody_dae_si2.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"
#include "solvers/bdf_integrator.hpp"
#include "solvers/ida_integrator.hpp"
#include "support/dense_only_problem.hpp"
#include "support/link_chain.hpp"
#include "support/random_state.hpp"

namespace openmss::analysis {
namespace {

using mechanics::MultibodySystem;
using L = mechanics::StateLayout;

model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "si2_sparse.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// A spatial chain with every joint kind (revolute, spherical, translational, cylindrical,
// universal, planar; Point, Dot and Along equations), a rotation and a translation MOTION, and
// force elements and user equations reading distant markers.
std::string mixedChain() {
  std::ostringstream s;
  s << "mixed\nUNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
       "PART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0\nMARKER/11, PART=1, QP=0,0,0\n";
  openmss::testing::writeLinkChain(s,
                                   {"REVOLUTE", "SPHERICAL", "TRANSLATIONAL", "CYLINDRICAL",
                                    "UNIVERSAL", "REVOLUTE", "PLANAR", "TRANSLATIONAL"},
                                   0.1, "0.05,0.1,0.12", 50, 0.5);
  s << "MOTION/1, JOINT=2, FUNCTION=0.3*SIN(2*TIME)\n"
    << "MOTION/2, JOINT=9, FUNCTION=0.1*TIME\n"
    << "SFORCE/1, TRANSLATION, I=72, J=10, FUNCTION=-10*(DM(72,10)-3)-0.2*VR(72,10)\n"
    << "VARIABLE/1, FUNCTION=DX(52,10)\n"
    << "DIFF/1, FUNCTION=VARVAL(1)-DIF(1), IC=0\n"
    << "SFORCE/2, ROTATION, I=91, J=82, FUNCTION=-DIF(1)\n"
    << "ACCGRAV/JGRAV=-9.80665\nEND\n";
  return s.str();
}

// A state off the solution: random positions, velocities, multipliers and mu (random_state.hpp),
// eta of order 0.1 and y' random.
struct OffSolution {
  Eigen::VectorXd y, yp;
};
OffSolution offSolution(const MultibodySystem& s, const MultibodyDaeSi2& dae, unsigned seed) {
  std::mt19937 rng(seed);
  const int n = dae.baseSize(), m = dae.size();
  OffSolution o;
  o.y = Eigen::VectorXd::Zero(m);
  o.y.head(n) = testing::randomState(s, rng, testing::RandomMu::Yes);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = n; k < m; ++k) o.y(k) = 0.1 * u(rng);
  o.yp = Eigen::VectorXd::Zero(m);
  for (int i = 0; i < m; ++i) o.yp(i) = u(rng);
  return o;
}

// Largest |a - b| / (1 + largest |b| of the row) over the matrix; the worst entries are
// printed when it exceeds `report`.
double largestRowRelative(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b, double report = 1.0) {
  double worst = 0.0;
  int printed = 0;
  for (int r = 0; r < b.rows(); ++r) {
    const double scale = 1.0 + b.row(r).cwiseAbs().maxCoeff();
    for (int c = 0; c < b.cols(); ++c) {
      const double d = std::abs(a(r, c) - b(r, c)) / scale;
      if (d > report && printed++ < 20)
        std::printf("  row %d column %d: %.10g vs %.10g\n", r, c, a(r, c), b(r, c));
      worst = std::max(worst, d);
    }
  }
  return worst;
}

// dG/dy + cj dG/dy' by fourth-order central differences, (-G(2h) + 8 G(h) - 8 G(-h) + G(-2h))
// / 12 h along (e_c, cj e_c). With h = 2e-4 (1 + |y_c|) the truncation error is h^4 |G^(5)| / 30:
// the constraint geometry is a polynomial of degree at most 4 in any one Euler parameter (two
// quadratic rotation matrices) and in the positions, so only the rotation MOTION's angle and
// the force elements (springs of length 2, stiffness 50: |G^(5)| ~ 50 5! / 2^5) contribute, at
// about 1e-11 of the row; round-off is about 2 eps |G| / h, 1e-12 of the row.
Eigen::MatrixXd fourthOrderDifferences(MultibodyDaeSi2& dae, double t, const Eigen::VectorXd& y,
                                       const Eigen::VectorXd& yp, double cj) {
  const int m = dae.size();
  Eigen::MatrixXd fd(m, m);
  Eigen::VectorXd g[4];
  const double steps[4] = {2.0, 1.0, -1.0, -2.0};
  for (int c = 0; c < m; ++c) {
    const double h = 2e-4 * (1.0 + std::abs(y(c)));
    for (int k = 0; k < 4; ++k) {
      Eigen::VectorXd yk = y, pk = yp;
      yk(c) += steps[k] * h;
      if (dae.differential(c)) pk(c) += steps[k] * cj * h;
      dae.residual(t, yk, pk, g[k]);
    }
    fd.col(c) = (-g[0] + 8.0 * g[1] - 8.0 * g[2] + g[3]) / (12.0 * h);
  }
  return fd;
}

// The sparse matrix through the DaeProblem interface, as the integrators take it.
Eigen::MatrixXd sparseMatrix(MultibodyDaeSi2& dae, double t, const Eigen::VectorXd& y,
                             const Eigen::VectorXd& yp, double cj) {
  Eigen::SparseMatrix<double> a = *dae.pattern();
  dae.newtonMatrixSparse(t, y, yp, cj, a);
  EXPECT_TRUE(dae.lastElementLocal());
  return Eigen::MatrixXd(a);
}

TEST(Si2SparseNewtonMatrix, MatchesFourthOrderDifferencesOnEveryJointKind) {
  const model::Model model = build(mixedChain());
  const MultibodySystem s(model);
  MultibodyDaeSi2 dae(s);
  for (unsigned seed : {3u, 8u}) {
    const OffSolution o = offSolution(s, dae, seed);
    const double t = 0.3 + seed, cj = 37.0;
    const Eigen::MatrixXd sparse = sparseMatrix(dae, t, o.y, o.yp, cj);
    const Eigen::MatrixXd fd = fourthOrderDifferences(dae, t, o.y, o.yp, cj);
    const double worst = largestRowRelative(sparse, fd, 1e-10);
    std::printf("[si2] mixed chain (%d unknowns, seed %u): sparse vs 4th-order differences %.2e\n",
                dae.size(), seed, worst);
    EXPECT_LT(worst, 1e-10);
    // The earlier dense matrix (stabilisation terms by second-order differences, step 1e-6):
    // good to about 1e-8 (1 + |entry|).
    Eigen::MatrixXd byDifferences;
    dae.newtonMatrixByDifferences(t, o.y, o.yp, cj, byDifferences);
    EXPECT_LT(largestRowRelative(sparse, byDifferences), 1e-6);
    EXPECT_EQ(dae.patternRepairs(), 0);
  }
}

// At eta = 0 the SI2 matrix's upper-left block is the index-3 Newton matrix, which the dense
// forward-AD evaluation gives exactly: equal to round-off.
TEST(Si2SparseNewtonMatrix, UpperLeftBlockIsTheIndexThreeMatrixAtZeroEta) {
  const model::Model model = build(mixedChain());
  const MultibodySystem s(model);
  MultibodyDaeSi2 dae(s);
  OffSolution o = offSolution(s, dae, 5u);
  const int n = dae.baseSize();
  o.y.tail(dae.size() - n).setZero();
  const Eigen::MatrixXd sparse = sparseMatrix(dae, 0.7, o.y, o.yp, 11.0);
  Eigen::MatrixXd exact;
  s.newtonMatrix(0.7, o.y.head(n), o.yp.head(n), 11.0, exact);
  const double worst = largestRowRelative(sparse.topLeftCorner(n, n), exact);
  std::printf("[si2] upper-left block vs the I3 forward-AD matrix: %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);
}

// Euler parameters off the unit sphere (inside a Newton iteration) and removed equations (their
// rows lambda_k = 0 and eta_k = 0, no load on any body).
TEST(Si2SparseNewtonMatrix, OffTheUnitSphereAndWithRemovedEquations) {
  const model::Model model = build(mixedChain());
  MultibodySystem s(model);
  s.constraints().equations()[1].active = false;
  s.constraints().equations()[7].active = false;
  MultibodyDaeSi2 dae(s);
  OffSolution o = offSolution(s, dae, 12u);
  for (int b = 0; b < s.layout().bodies; ++b)
    o.y.segment<4>(s.layout().body(b) + L::kE) *= 1.0 + 0.03 * (b + 1);
  const Eigen::MatrixXd sparse = sparseMatrix(dae, 0.2, o.y, o.yp, 5.0);
  const Eigen::MatrixXd fd = fourthOrderDifferences(dae, 0.2, o.y, o.yp, 5.0);
  const double worst = largestRowRelative(sparse, fd, 1e-10);
  std::printf("[si2] off the unit sphere, two equations removed: %.2e\n", worst);
  EXPECT_LT(worst, 1e-10);
}

// A planar chain of revolute links, consistent at t = 0 (positions, velocities, accelerations).
struct Chain {
  model::Model model;
  std::unique_ptr<MultibodySystem> system;
  Eigen::VectorXd y, yp;
  explicit Chain(int links) {
    std::ostringstream s;
    s << "chain\nUNITS/FORCE=NEWTON, MASS=KILOGRAM, LENGTH=METER, TIME=SECOND\n"
         "PART/1, GROUND\nMARKER/10, PART=1, QP=0,0,0\n";
    for (int i = 0; i < links; ++i) {
      const int p = i + 2;
      s << "PART/" << p << ", MASS=1, CM=" << 10 * p << ", IP=0.01,0.1,0.1\n"
        << "MARKER/" << 10 * p << ", PART=" << p << ", QP=" << i + 0.5 << ",0,0\n"
        << "MARKER/" << 10 * p + 1 << ", PART=" << p << ", QP=" << i << ",0,0\n"
        << "MARKER/" << 10 * p + 2 << ", PART=" << p << ", QP=" << i + 1 << ",0,0\n"
        << "JOINT/" << p << ", REVOLUTE, I=" << 10 * p + 1
        << ", J=" << (i == 0 ? 10 : 10 * (p - 1) + 2) << "\n";
    }
    s << "ACCGRAV/JGRAV=-9.80665\nEND\n";
    model = build(s.str());
    system = std::make_unique<MultibodySystem>(model);
    const int n = system->layout().size();
    Eigen::VectorXd base = system->initialState(), basePrime = Eigen::VectorXd::Zero(n);
    mechanics::removeRedundantConstraints(*system, base);
    EXPECT_TRUE(mechanics::assemblePositions(*system, 0.0, base, 1e-12, 25).converged);
    mechanics::solveVelocities(*system, 0.0, base);
    EXPECT_TRUE(mechanics::solveAccelerations(*system, 0.0, base, basePrime));
    const int m = n + system->layout().constraintEquations;
    y = Eigen::VectorXd::Zero(m);
    yp = Eigen::VectorXd::Zero(m);
    y.head(n) = base;
    yp.head(n) = basePrime;
  }
};

// Largest difference over the unknowns under error control (SI2: positions and velocities). IDA
// tests convergence in its weighted norm, where the multipliers weigh nothing (their tolerance is
// 1e20, ida_integrator.cpp): they are converged only as far as the controlled unknowns need, and
// round-off moves them further than the controlled ones.
double controlledDifference(const MultibodyDaeSi2& dae, const Eigen::VectorXd& a,
                            const Eigen::VectorXd& b) {
  double worst = 0.0;
  for (int i = 0; i < dae.size(); ++i)
    if (dae.errorControlled(i)) worst = std::max(worst, std::abs(a(i) - b(i)));
  return worst;
}

// Both paths converge every corrector far below the tolerance; they differ by round-off
// amplified over the steps (the I3 KLU-vs-LU test finds the same order), far below ERROR.
TEST(Si2SparseIntegration, DstiffKluPathFollowsTheDenseLuPath) {
  Chain chain(8);
  MultibodyDaeSi2 sparseDae(*chain.system);
  sparseDae.checkEveryMatrix(true);  // the no-repair assertion below covers every matrix
  openmss::testing::DenseOnlyProblem denseDae(sparseDae);
  ASSERT_GE(sparseDae.size(), solvers::BdfIntegrator::kSparseThreshold);
  solvers::MultistepSettings settings;
  settings.error = 1e-6;
  settings.hmax = 0.01;
  solvers::IdaIntegrator sparse(sparseDae, settings), dense(denseDae, settings);
  sparse.start(0.0, chain.y, chain.yp);
  dense.start(0.0, chain.y, chain.yp);
  for (double tout = 0.05; tout <= 0.3 + 1e-12; tout += 0.05) {
    ASSERT_TRUE(sparse.advanceTo(tout)) << sparse.failure().reason;
    ASSERT_TRUE(dense.advanceTo(tout)) << dense.failure().reason;
  }
  EXPECT_EQ(sparseDae.patternRepairs(), 0);
  const double difference = controlledDifference(sparseDae, sparse.y(), dense.y());
  std::printf("[si2] DSTIFF 8-link chain, KLU vs dense LU after 0.3 s: %.2e (steps %ld vs %ld)\n",
              difference, sparse.statistics().steps, dense.statistics().steps);
  EXPECT_LE(difference, 1e-7);
}

TEST(Si2SparseIntegration, GstiffSi2KluPathFollowsTheDenseLuPath) {
  Chain chain(8);
  MultibodyDaeSi2 sparseDae(*chain.system);
  openmss::testing::DenseOnlyProblem denseDae(sparseDae);
  solvers::MultistepSettings settings;
  settings.error = 1e-6;
  settings.hmax = 0.01;
  solvers::BdfIntegrator sparse(sparseDae, settings), dense(denseDae, settings);
  sparse.start(0.0, chain.y, chain.yp);
  dense.start(0.0, chain.y, chain.yp);
  EXPECT_STREQ(sparse.linearSolverName(), "KLU");
  EXPECT_STREQ(dense.linearSolverName(), "dense LU");
  for (double tout = 0.05; tout <= 0.3 + 1e-12; tout += 0.05) {
    ASSERT_TRUE(sparse.advanceTo(tout)) << sparse.failure().reason;
    ASSERT_TRUE(dense.advanceTo(tout)) << dense.failure().reason;
  }
  const double difference = controlledDifference(sparseDae, sparse.y(), dense.y());
  std::printf(
      "[si2] GSTIFF,SI2 8-link chain, KLU vs dense LU after 0.3 s: %.2e (steps %ld vs %ld)\n",
      difference, sparse.statistics().steps, dense.statistics().steps);
  EXPECT_LE(difference, 1e-7);
}

}  // namespace
}  // namespace openmss::analysis

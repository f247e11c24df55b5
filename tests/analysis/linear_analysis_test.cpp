// Linearization (src/analysis/linearization.cpp) and eigenvalues (eigen_analysis.cpp) against
// closed forms. Tolerance 1e-8 relative on eigenvalues: every derivative is exact (forward-mode
// AD), so the only errors are the round-off of the eigen solvers (~1e-14 for these 2x2 and 4x4
// problems) and of the operating point (positions assembled to 1e-12, multipliers solved
// directly); 1e-8 is the brief's requirement and leaves a margin of 1e4. The stiffness and
// damping matrices are checked against central differences of the projected residual.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>

#include "analysis/eigen_analysis.hpp"
#include "analysis/linearization.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/pose.hpp"
#include "model/model_builder.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

struct Loaded {
  model::Model model;
  std::unique_ptr<mechanics::MultibodySystem> system;
  Eigen::VectorXd y, yp;
};

void load(const std::string& text, Loaded& out) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "linear.adm", ds, d);
  ASSERT_TRUE(model::buildModel(ds, out.model, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  out.system = std::make_unique<mechanics::MultibodySystem>(out.model);
  out.y = out.system->initialState();
  out.yp = Eigen::VectorXd::Zero(out.y.size());
  mechanics::removeRedundantConstraints(*out.system, out.y);
  ASSERT_TRUE(mechanics::assemblePositions(*out.system, 0.0, out.y, 1e-13, 25).converged);
  mechanics::solveVelocities(*out.system, 0.0, out.y);
  ASSERT_TRUE(mechanics::solveAccelerations(*out.system, 0.0, out.y, out.yp));
}

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Every expected eigenvalue matches a computed one to `tol` relative (and the counts agree).
void expectEigenvalues(const std::vector<EigenMode>& modes,
                       const std::vector<std::complex<double>>& expected, double tol) {
  ASSERT_EQ(modes.size(), expected.size());
  for (const auto& e : expected) {
    double best = 1e300;
    for (const auto& m : modes) best = std::min(best, std::abs(m.value - e) / std::abs(e));
    std::printf("  expected %.15g %+.15gi: nearest computed differs by %.3e (relative)\n", e.real(),
                e.imag(), best);
    EXPECT_LT(best, tol);
  }
}

// A mass m on a translational joint along z with a SPRINGDAMPER (k, c) at its free length.
std::string springMass(double m, double k, double c) {
  return "spring mass\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "PART/2, MASS=" +
         num(m) +
         ", CM=20, IP=1,1,1, QG=0,0,-1\nMARKER/20, PART=2\n"
         "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
         "SPRINGDAMPER/1, TRANSLATIONAL, I=20, J=10, K=" +
         num(k) + ", C=" + num(c) + ", LENGTH=1\nEND\n";
}

TEST(Linear, DampedSpringMassEigenvalues) {
  const double m = 2.0, k = 100.0, c = 3.0;
  Loaded l;
  load(springMass(m, k, c), l);
  LinearSystem lin;
  std::string why;
  ASSERT_TRUE(linearize(*l.system, 0.0, l.y, l.yp, {}, lin, &why)) << why;
  ASSERT_EQ(lin.degreesOfFreedom, 1);
  const double sigma = -c / (2 * m), omega = std::sqrt(k / m - sigma * sigma);
  expectEigenvalues(eigenModes(lin), {{sigma, omega}, {sigma, -omega}}, 1e-8);
  const auto modes = eigenModes(lin);
  EXPECT_NEAR(modes[0].dampingRatio, c / (2 * std::sqrt(k * m)), 1e-10);
  EXPECT_NEAR(modes[0].naturalFrequency, std::sqrt(k / m) / (2 * M_PI), 1e-10);
  // The mode shape is a translation of PART/2 along z only.
  EXPECT_NEAR(std::abs(modes[0].shape(2)), 1.0, 1e-12);
  for (int i : {0, 1, 3, 4, 5}) EXPECT_NEAR(std::abs(modes[0].shape(i)), 0.0, 1e-12);
}

// STATEMAT basis: the part coordinates. For this 1-DOF system the state is (Z, VZ) of PART/2
// and A = [[0, 1], [-k/m, -c/m]] exactly.
TEST(Linear, SpringMassStateMatrixInPartCoordinates) {
  const double m = 2.0, k = 100.0, c = 3.0;
  Loaded l;
  load(springMass(m, k, c), l);
  LinearSystem lin;
  LinearizationRequest req;
  req.basis = LinearBasis::PartCoordinates;
  ASSERT_TRUE(linearize(*l.system, 0.0, l.y, l.yp, req, lin, nullptr));
  ASSERT_EQ(lin.a.rows(), 2);
  Eigen::Matrix2d expected;
  expected << 0, 1, -k / m, -c / m;
  std::printf("A =\n%.17g %.17g\n%.17g %.17g\n", lin.a(0, 0), lin.a(0, 1), lin.a(1, 0),
              lin.a(1, 1));
  EXPECT_LT((lin.a - expected).cwiseAbs().maxCoeff(), 1e-12 * (k / m));
  EXPECT_EQ(lin.stateNames[0], "PART/2 Z");
  EXPECT_EQ(lin.stateNames[1], "PART/2 VZ");
  EXPECT_EQ(lin.b.cols(), 0);
  EXPECT_EQ(lin.c.rows(), 0);
}

// Double pendulum: link i of mass mi, length Li, CM at its middle, inertia Ii about the CM
// (axis z), hanging along -y from revolutes about z; gravity g along -y. In the absolute link
// angles (theta1, theta2), linearised about the hanging equilibrium:
//   M = [[I1 + m1 a1^2 + m2 L1^2, m2 L1 a2], [m2 L1 a2, I2 + m2 a2^2]],  ai = Li / 2,
//   K = diag((m1 a1 + m2 L1) g, m2 a2 g)
// (kinetic energy of link 2's CM: velocity L1 theta1' + a2 theta2' at the equilibrium;
// potential -m1 g a1 cos theta1 - m2 g (L1 cos theta1 + a2 cos theta2)). Eigenvalues
// +-i omega, omega^2 the generalised eigenvalues of (K, M). The whole stiffness comes from the
// reaction forces' geometric term d(C^T lambda)/dq.
const double kM1 = 2.0, kL1 = 1.2, kI1 = 0.3, kM2 = 1.5, kL2 = 0.8, kI2 = 0.1, kG = 9.81;

std::string doublePendulum() {
  return "double pendulum\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "PART/2, MASS=" +
         num(kM1) + ", CM=20, IP=" + num(kI1) + "," + num(kI1) + "," + num(kI1) +
         "\nMARKER/20, PART=2, QP=0," + num(-kL1 / 2) +
         ",0\n"
         "MARKER/21, PART=2\nMARKER/22, PART=2, QP=0," +
         num(-kL1) +
         ",0\n"
         "PART/3, MASS=" +
         num(kM2) + ", CM=30, IP=" + num(kI2) + "," + num(kI2) + "," + num(kI2) +
         "\nMARKER/30, PART=3, QP=0," + num(-kL1 - kL2 / 2) +
         ",0\n"
         "MARKER/31, PART=3, QP=0," +
         num(-kL1) +
         ",0\n"
         "JOINT/1, REVOLUTE, I=21, J=10\nJOINT/2, REVOLUTE, I=31, J=22\n"
         "ACCGRAV/ JGRAV=" +
         num(-kG) + "\nEND\n";
}

std::vector<std::complex<double>> doublePendulumEigenvalues() {
  const double a1 = kL1 / 2, a2 = kL2 / 2;
  Eigen::Matrix2d m, k;
  m << kI1 + kM1 * a1 * a1 + kM2 * kL1 * kL1, kM2 * kL1 * a2,  //
      kM2 * kL1 * a2, kI2 + kM2 * a2 * a2;
  k << (kM1 * a1 + kM2 * kL1) * kG, 0, 0, kM2 * a2 * kG;
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> s(k, m);
  std::vector<std::complex<double>> out;
  for (int i = 0; i < 2; ++i) {
    const double w = std::sqrt(s.eigenvalues()(i));
    out.push_back({0.0, w});
    out.push_back({0.0, -w});
  }
  return out;
}

TEST(Linear, DoublePendulumAboutItsStableEquilibrium) {
  Loaded l;
  load(doublePendulum(), l);
  LinearSystem lin;
  std::string why;
  ASSERT_TRUE(linearize(*l.system, 0.0, l.y, l.yp, {}, lin, &why)) << why;
  ASSERT_EQ(lin.degreesOfFreedom, 2);
  const auto modes = eigenModes(lin);
  expectEigenvalues(modes, doublePendulumEigenvalues(), 1e-8);
  for (const auto& mode : modes) EXPECT_LT(std::abs(mode.dampingRatio), 1e-10);
  // The same in part coordinates (state matrices): the eigenvalues do not depend on the basis.
  LinearizationRequest req;
  req.basis = LinearBasis::PartCoordinates;
  LinearSystem parts;
  ASSERT_TRUE(linearize(*l.system, 0.0, l.y, l.yp, req, parts, &why)) << why;
  expectEigenvalues(eigenModes(parts), doublePendulumEigenvalues(), 1e-8);
}

// Stiffness and damping against central differences of the projected balance equations with
// the multipliers held: the positions move along each basis direction by +-h (body
// corrections), the velocities likewise. The pendulum is given a spring-damper and initial
// speeds so that the velocity terms (damping and gyroscopic) are not zero.
TEST(Linear, StiffnessAndDampingMatchCentralDifferences) {
  Loaded l;
  std::string text = doublePendulum();
  text.insert(text.find("END"),
              "MARKER/11, PART=1, QP=0.3,-2,0\nSPRINGDAMPER/1, TRANSLATIONAL, I=30, J=11, "
              "K=40, C=1.5, LENGTH=0.5\n");
  text.insert(text.find("IP=" + num(kI2)), "WZ=0.7, ");
  load(text, l);
  LinearSystem lin;
  std::string why;
  ASSERT_TRUE(linearize(*l.system, 0.0, l.y, l.yp, {}, lin, &why)) << why;
  const StateLayout& lay = l.system->layout();
  const int nb = lay.bodies, n = lin.degreesOfFreedom;
  std::vector<Eigen::Matrix3d> axes(nb);
  for (int b = 0; b < nb; ++b) axes[b] = toEigen(mechanics::bodyPose(lay, b, l.y.data()).a);
  auto projected = [&](const Eigen::VectorXd& y) {
    Eigen::VectorXd r(lay.size());
    l.system->residual(0.0, y.data(), l.yp.data(), r.data());
    Eigen::VectorXd g(6 * nb);
    for (int b = 0; b < nb; ++b) {
      g.segment<3>(6 * b) = r.segment<3>(lay.body(b) + StateLayout::kV);
      g.segment<3>(6 * b + 3) = axes[b] * r.segment<3>(lay.body(b) + StateLayout::kW);
    }
    return Eigen::VectorXd(lin.positionBasis.transpose() * g);
  };
  const double h = 1e-6;
  double worstK = 0, worstC = 0;
  for (int j = 0; j < n; ++j) {
    Eigen::VectorXd body(6 * nb);  // ground rotation -> body-axes rotation for the correction
    for (int b = 0; b < nb; ++b) {
      body.segment<3>(6 * b) = lin.positionBasis.col(j).segment<3>(6 * b);
      body.segment<3>(6 * b + 3) =
          axes[b].transpose() * lin.positionBasis.col(j).segment<3>(6 * b + 3);
    }
    Eigen::VectorXd plus = l.y, minus = l.y;
    mechanics::applyBodyCorrection(lay, h * body, plus);
    mechanics::applyBodyCorrection(lay, -h * body, minus);
    const Eigen::VectorXd kFd = (projected(plus) - projected(minus)) / (2 * h);
    Eigen::VectorXd vPlus = l.y, vMinus = l.y;
    for (int b = 0; b < nb; ++b) {
      const int o = lay.body(b);
      vPlus.segment<3>(o + StateLayout::kV) += h * body.segment<3>(6 * b);
      vMinus.segment<3>(o + StateLayout::kV) -= h * body.segment<3>(6 * b);
      vPlus.segment<3>(o + StateLayout::kW) += h * body.segment<3>(6 * b + 3);
      vMinus.segment<3>(o + StateLayout::kW) -= h * body.segment<3>(6 * b + 3);
    }
    const Eigen::VectorXd cFd = (projected(vPlus) - projected(vMinus)) / (2 * h);
    worstK = std::max(worstK, (kFd - lin.stiffness.col(j)).cwiseAbs().maxCoeff() /
                                  lin.stiffness.cwiseAbs().maxCoeff());
    worstC = std::max(worstC, (cFd - lin.damping.col(j)).cwiseAbs().maxCoeff() /
                                  lin.damping.cwiseAbs().maxCoeff());
  }
  std::printf("largest relative difference from central differences: K %.3e, C %.3e\n", worstK,
              worstC);
  EXPECT_LT(worstK, 1e-6);
  EXPECT_LT(worstC, 1e-6);
  EXPECT_GT(lin.damping.cwiseAbs().maxCoeff(), 0.1);  // the test exercises the damping terms
}

// A DIFF state driven by the mechanism, y' = -2 y + z: it joins the first-order form after the
// mechanical states, A = [[0, 1, 0], [-k/m, -c/m, 0], [1, 0, -2]] in the part coordinates.
TEST(Linear, DiffStateJoinsTheFirstOrderForm) {
  const double m = 2.0, k = 100.0, c = 3.0;
  std::string text = springMass(m, k, c);
  text.insert(text.find("END"), "DIFF/1, IC=0, FUNCTION=-2*DIF(1)+DZ(20,10)\n");
  Loaded l;
  load(text, l);
  LinearSystem lin;
  LinearizationRequest req;
  req.basis = LinearBasis::PartCoordinates;
  std::string why;
  ASSERT_TRUE(linearize(*l.system, 0.0, l.y, l.yp, req, lin, &why)) << why;
  ASSERT_EQ(lin.a.rows(), 3);
  Eigen::Matrix3d expected;
  expected << 0, 1, 0, -k / m, -c / m, 0, 1, 0, -2;
  EXPECT_LT((lin.a - expected).cwiseAbs().maxCoeff(), 1e-12 * (k / m)) << lin.a;
  EXPECT_EQ(lin.stateNames[2], "DIFF/1");
}

TEST(Linear, ZeroDegreeOfFreedomModelIsRefused) {
  Loaded l;
  load(
      "fixed\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\nJOINT/1, FIXED, I=20, J=10\nEND\n",
      l);
  LinearSystem lin;
  std::string why;
  EXPECT_FALSE(linearize(*l.system, 0.0, l.y, l.yp, {}, lin, &why));
  EXPECT_NE(why.find("no degree of freedom"), std::string::npos) << why;
}

}  // namespace
}  // namespace openmss::analysis

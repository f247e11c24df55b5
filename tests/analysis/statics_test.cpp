// Static equilibrium (src/analysis/statics.cpp) against closed forms. Tolerance 1e-8 on
// positions and forces: Newton converges quadratically and the runs ask for ERROR = 1e-12 and
// IMBALANCE = 1e-10, so the solver's own error is ~1e-12; 1e-8 leaves room for the round-off of
// the closed forms, which are themselves solved to ~1e-15 here. The static Jacobian is checked
// against central differences.

#include "analysis/statics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"

namespace openmss::analysis {
namespace {

using mechanics::StateLayout;

struct Loaded {
  model::Model model;
  std::unique_ptr<mechanics::MultibodySystem> system;
  Eigen::VectorXd y;
};

void load(const std::string& text, Loaded& out) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "statics.adm", ds, d);
  ASSERT_TRUE(model::buildModel(ds, out.model, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  out.system = std::make_unique<mechanics::MultibodySystem>(out.model);
  out.y = out.system->initialState();
  mechanics::removeRedundantConstraints(*out.system, out.y);
  ASSERT_TRUE(mechanics::assemblePositions(*out.system, 0.0, out.y, 1e-12, 25).converged);
}

model::EquilibriumSettings tight() {
  model::EquilibriumSettings s;
  s.error = 1e-12;
  s.imbalance = 1e-10;
  return s;
}

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

Eigen::Vector3d bodyPosition(const Loaded& l, int body) {
  return l.y.segment<3>(l.system->layout().body(body));
}

// (a) A mass on a vertical translational joint hangs from a spring written as an SFORCE:
// the spring stretches by m g / k.
TEST(Statics, HangingMassStretchesTheSpringByMgOverK) {
  const double m = 2.0, g = 9.81, k = 100.0, l0 = 1.0;
  Loaded l;
  load(
      "hanging mass\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1\n"
      "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,-1\nMARKER/20, PART=2\n"
      "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
      "SFORCE/1, TRANSLATION, I=20, J=11, FUNCTION=-100*(DM(20,11)-1)\n"
      "ACCGRAV/ KGRAV=-9.81\nEND\n",
      l);
  const EquilibriumResult r = solveStaticEquilibrium(*l.system, 0.0, l.y, tight());
  ASSERT_EQ(r.status, EquilibriumResult::Status::Converged);
  const Eigen::Vector3d p = bodyPosition(l, 0);
  std::printf("hanging mass: z = %.15f, closed form %.15f\n", p.z(), -(l0 + m * g / k));
  EXPECT_NEAR(p.z(), -(l0 + m * g / k), 1e-8);
  EXPECT_NEAR(p.x(), 0.0, 1e-12);
  EXPECT_TRUE(r.neutral.empty());
  EXPECT_TRUE(r.unstable.empty());
}

// (b) A pendulum (CM at distance L from a revolute about z) with a torsion spring written
// through DX/DY: T = -kt (theta - theta0), theta the angle of the rod from -y. Equilibrium:
// kt (theta - theta0) + m g L sin(theta) = 0, solved here by Newton on the scalar equation.
// It starts horizontal, where the gravity stiffness is zero (a singular first Jacobian).
TEST(Statics, PendulumWithATorsionSpringFindsItsClosedFormAngle) {
  const double m = 1.0, g = 9.81, len = 1.0, kt = 20.0, theta0 = std::numbers::pi / 2;
  Loaded l;
  load(
      "torsion pendulum\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=1,0,0\n"
      "MARKER/21, PART=2, QP=0,0,0\nJOINT/1, REVOLUTE, I=21, J=10\n"
      "SFORCE/1, ROTATION, I=21, J=10, FUNCTION=-20*(ATAN2(DX(20,10),-DY(20,10))-PI/2)\n"
      "ACCGRAV/ JGRAV=-9.81\nEND\n",
      l);
  double theta = theta0;
  for (int i = 0; i < 50; ++i)
    theta -= (kt * (theta - theta0) + m * g * len * std::sin(theta)) /
             (kt + m * g * len * std::cos(theta));
  const EquilibriumResult r = solveStaticEquilibrium(*l.system, 0.0, l.y, tight());
  ASSERT_EQ(r.status, EquilibriumResult::Status::Converged);
  const Eigen::Vector3d p = bodyPosition(l, 0);
  const double found = std::atan2(p.x(), -p.y());
  std::printf("torsion pendulum: theta = %.15f, closed form %.15f, %d iterations\n", found, theta,
              r.iterations);
  EXPECT_NEAR(found, theta, 1e-8);
  EXPECT_NEAR(p.norm(), len, 1e-10);
  // The revolute carries the weight: its reaction on the pendulum is +m g along y.
  Eigen::Vector3d f, t;
  l.system->elementReaction(false, 0, l.model.markerIndex.at(21), l.y.data(), f, t);
  EXPECT_NEAR(f.y(), m * g, 1e-8);
  EXPECT_NEAR(f.x(), 0.0, 1e-8);
}

// (c) A point mass held by two inclined springs from A = (-1, 0, 0) and B = (1, 0, 0) under
// gravity -y. The equilibrium P = (0.3, -0.8, 0) is chosen first and the stiffnesses derived
// from it by hand: with u = T/|d| the tension per length, the force balance gives
// 1.3 uA = 0.7 uB and 0.8 (uA + uB) = m g, so uA = 7 m g / 16 and uB = 13 m g / 16, and
// k = T / (|d| - L0). The solver starts from (0, -0.5, 0). The body's three rotations are free
// and unloaded (the springs act at the CM): neutral directions, reported. (Its z translation is
// not: the tensioned springs resist it, as a string does.)
TEST(Statics, PointMassOnTwoInclinedSpringsMatchesTheHandSolution) {
  const double m = 1.5, g = 9.81, l0 = 0.5;
  const Eigen::Vector3d p(0.3, -0.8, 0.0), a(-1, 0, 0), b(1, 0, 0);
  const double da = (p - a).norm(), db = (p - b).norm();
  const double ka = (7 * m * g / 16) * da / (da - l0), kb = (13 * m * g / 16) * db / (db - l0);
  Loaded l;
  load(
      "two springs\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1, QP=-1,0,0\n"
      "MARKER/11, PART=1, QP=1,0,0\n"
      "PART/2, MASS=1.5, CM=20, IP=0.1,0.1,0.1, QG=0,-0.5,0\nMARKER/20, PART=2\n"
      "SFORCE/1, TRANSLATION, I=20, J=10, FUNCTION=-" +
          num(ka) +
          "*(DM(20,10)-0.5)\n"
          "SFORCE/2, TRANSLATION, I=20, J=11, FUNCTION=-" +
          num(kb) +
          "*(DM(20,11)-0.5)\n"
          "ACCGRAV/ JGRAV=-9.81\nEND\n",
      l);
  const EquilibriumResult r = solveStaticEquilibrium(*l.system, 0.0, l.y, tight());
  ASSERT_EQ(r.status, EquilibriumResult::Status::Converged);
  const Eigen::Vector3d q = bodyPosition(l, 0);
  std::printf("two springs: (%.15f, %.15f), %d iterations, %zu neutral directions\n", q.x(), q.y(),
              r.iterations, r.neutral.size());
  EXPECT_NEAR((q - p).norm(), 0.0, 1e-8);
  EXPECT_EQ(r.neutral.size(), 3u);  // the three rotations
  EXPECT_TRUE(r.unstable.empty());
}

// (d) A wheel on a revolute with a constant torque and nothing to resist it has no static
// equilibrium: reported (naming the part and the axis) after a few iterations, not MAXIT.
TEST(Statics, AnUnbalancedFreeRotationIsReportedNotIteratedOn) {
  Loaded l;
  load(
      "driven wheel\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\nMARKER/21, PART=2, QP=0.5,0,0\n"
      "JOINT/1, REVOLUTE, I=20, J=10\n"
      "SFORCE/1, ROTATION, I=20, J=10, FUNCTION=5\nACCGRAV/ JGRAV=-9.81\nEND\n",
      l);
  model::EquilibriumSettings s = tight();
  s.maxit = 100;
  const EquilibriumResult r = solveStaticEquilibrium(*l.system, 0.0, l.y, s);
  ASSERT_EQ(r.status, EquilibriumResult::Status::Unbalanced);
  ASSERT_TRUE(r.unbalanced.has_value());
  EXPECT_LT(r.iterations, 5);
  EXPECT_TRUE(r.unbalanced->rotation);
  EXPECT_NEAR(std::abs(r.unbalanced->axis.z()), 1.0, 1e-9);
  // Generalised load along the free rotation: the torque, in the scaled units (torque / length
  // with the characteristic length 0.5 of the marker offset).
  EXPECT_NEAR(std::abs(r.unbalanced->load), 5.0 / 0.5, 1e-9);
  EXPECT_EQ(r.unbalanced->describe(l.model),
            "rotation of PART/2 about the ground-axes direction (0, 0, 1)");
}

TEST(Statics, AnUnrestrainedSliderUnderGravityIsReportedAsATranslation) {
  Loaded l;
  load(
      "falling slider\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=2, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
      "JOINT/1, TRANSLATIONAL, I=20, J=10\nACCGRAV/ KGRAV=-9.81\nEND\n",
      l);
  const EquilibriumResult r = solveStaticEquilibrium(*l.system, 0.0, l.y, tight());
  ASSERT_EQ(r.status, EquilibriumResult::Status::Unbalanced);
  EXPECT_FALSE(r.unbalanced->rotation);
  EXPECT_NEAR(std::abs(r.unbalanced->load), 2 * 9.81, 1e-9);
  EXPECT_EQ(r.unbalanced->describe(l.model),
            "translation of PART/2 along the ground-axes direction (0, 0, 1)");
}

// The inverted pendulum is an equilibrium, an unstable one: found and flagged.
TEST(Statics, AnInvertedPendulumIsFlaggedUnstable) {
  Loaded l;
  load(
      "inverted pendulum\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=0,1,0\n"
      "MARKER/21, PART=2, QP=0,0,0\nJOINT/1, REVOLUTE, I=21, J=10\nACCGRAV/ JGRAV=-9.81\nEND\n",
      l);
  const EquilibriumResult r = solveStaticEquilibrium(*l.system, 0.0, l.y, tight());
  ASSERT_EQ(r.status, EquilibriumResult::Status::Converged);
  ASSERT_EQ(r.unstable.size(), 1u);
  EXPECT_TRUE(r.unstable[0].rotation);
  EXPECT_NEAR(bodyPosition(l, 0).y(), 1.0, 1e-12);
}

// The slider-crank of test (e): crank r = 1 about z at the origin driven by a MOTION
// theta = t, rod l = 3, slider on x, spring from the slider to (10, 0, 0) with k = 50, L0 = 5.
const char* kSliderCrank =
    "slider crank\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=4,0,0, REULER=90D,90D,0D\nMARKER/12, PART=1, QP=10,0,0\n"
    "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=0.5,0,0\n"
    "MARKER/21, PART=2\nMARKER/22, PART=2, QP=1,0,0\n"
    "PART/3, MASS=1, CM=30, IP=0.1,0.1,0.1\nMARKER/30, PART=3, QP=2.5,0,0\n"
    "MARKER/31, PART=3, QP=1,0,0\nMARKER/32, PART=3, QP=4,0,0\n"
    "PART/4, MASS=1, CM=40, IP=0.1,0.1,0.1\nMARKER/40, PART=4, QP=4,0,0\n"
    "MARKER/41, PART=4, QP=4,0,0, REULER=90D,90D,0D\nMARKER/42, PART=4, QP=4,0,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\nJOINT/2, REVOLUTE, I=31, J=22\n"
    "JOINT/3, REVOLUTE, I=42, J=32\nJOINT/4, TRANSLATIONAL, I=41, J=11\n"
    "MOTION/1, JOINT=1, ROTATION, FUNCTION=TIME\n"
    "SFORCE/1, TRANSLATION, I=40, J=12, FUNCTION=-50*(DM(40,12)-5)\n";

// Virtual work: tau dtheta + F dx = 0 with x = r cos(theta) + sqrt(l^2 - r^2 sin^2(theta)) and
// F = k (L0 - (10 - x) + ...) the spring force on the slider along +x.
double drivingTorque(double theta, double* slider) {
  const double r = 1.0, len = 3.0, k = 50.0, l0 = 5.0;
  const double s = std::sqrt(len * len - r * r * std::sin(theta) * std::sin(theta));
  const double x = r * std::cos(theta) + s;
  const double dxdtheta = -r * std::sin(theta) - r * r * std::sin(theta) * std::cos(theta) / s;
  const double force = k * ((10.0 - x) - l0);  // stretched spring pulls the slider to +x
  if (slider) *slider = x;
  return -force * dxdtheta;
}

TEST(Statics, QuasiStaticSliderCrankTorqueMatchesVirtualWork) {
  Loaded l;
  load(std::string(kSliderCrank) + "END\n", l);
  for (double t : {0.3, 1.0, 2.0, 2.8, 4.0, 5.5}) {
    ASSERT_TRUE(mechanics::assemblePositions(*l.system, t, l.y, 1e-12, 25).converged);
    const EquilibriumResult r = solveStaticEquilibrium(*l.system, t, l.y, tight());
    ASSERT_EQ(r.status, EquilibriumResult::Status::Converged) << t;
    Eigen::Vector3d f, torque;
    l.system->elementReaction(true, 0, l.model.markerIndex.at(21), l.y.data(), f, torque);
    double x = 0.0;
    const double expected = drivingTorque(t, &x);
    std::printf("crank %.2f rad: motion torque %.12f, virtual work %.12f\n", t, torque.z(),
                expected);
    EXPECT_NEAR(bodyPosition(l, 2).x(), x, 1e-10);
    EXPECT_NEAR(torque.z(), expected, 1e-8 * (1.0 + std::abs(expected)));
  }
}

// Every entry of the static Jacobian against central differences of the static residual, at a
// state away from equilibrium with nonzero multipliers (rotations applied as body-axes turns).
TEST(Statics, JacobianMatchesCentralDifferences) {
  Loaded l;
  load(std::string(kSliderCrank) + "ACCGRAV/ JGRAV=-9.81, IGRAV=1.5\nEND\n", l);
  ASSERT_TRUE(mechanics::assemblePositions(*l.system, 0.7, l.y, 1e-12, 25).converged);
  Eigen::VectorXd y = l.y;
  // Perturb positions off the constraint manifold and give the multipliers values.
  std::vector<int> rows;
  Eigen::MatrixXd jac;
  staticJacobian(*l.system, 0.7, y, jac, &rows);
  Eigen::VectorXd bump(jac.cols());
  for (int i = 0; i < bump.size(); ++i) bump(i) = 0.01 * std::sin(1.7 * i + 0.3);
  for (int i = 6 * 3; i < bump.size(); ++i) bump(i) = 10.0 * std::cos(0.9 * i);
  applyStaticCorrection(*l.system, rows, bump, y);
  staticJacobian(*l.system, 0.7, y, jac, &rows);
  const double h = 1e-6;
  double worst = 0.0;
  for (int c = 0; c < jac.cols(); ++c) {
    Eigen::VectorXd dir = Eigen::VectorXd::Zero(jac.cols());
    dir(c) = h;
    Eigen::VectorXd yp = y, ym = y, gp, gm;
    applyStaticCorrection(*l.system, rows, dir, yp);
    applyStaticCorrection(*l.system, rows, -dir, ym);
    staticResidual(*l.system, 0.7, yp, gp);
    staticResidual(*l.system, 0.7, ym, gm);
    const Eigen::VectorXd fd = (gp - gm) / (2 * h);
    for (int r = 0; r < jac.rows(); ++r) {
      const double err = std::abs(fd(r) - jac(r, c)) / (1.0 + std::abs(jac(r, c)));
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-6) << "row " << r << " column " << c << ": AD " << jac(r, c) << ", FD "
                           << fd(r);
    }
  }
  std::printf("static Jacobian vs central differences: worst relative difference %.2e\n", worst);
}

}  // namespace
}  // namespace openmss::analysis

// COUPLER and GEAR (docs/theory.md §5b) and the joints' initial conditions (§7): the coupled
// equation's row, Newton matrix and rates against central differences on random states, the
// degrees of freedom (rank and Gruebler), and closed forms through the kinematic solver: a
// coupler's linear relation, a spur pair's ratio -R1/R2 over several turns, a rack and pinion's
// s = R theta; a pendulum held at IC=30D,2 and a cylindrical joint at ICTRAN/ICROT.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "support/newton_matrix_check.hpp"
#include "language/reader.hpp"
#include "mechanics/expression_run_state.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "support/constraint_derivative_check.hpp"
#include "support/random_state.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;
using testing::turned;
using testing::randomState;

constexpr double kPi = std::numbers::pi;

model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "coupling.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// Rows, Newton matrix and rates of every equation against central differences.
void checkDerivatives(const MultibodySystem& s, const model::Model& m) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 3; ++trial)
    testing::checkConstraintRows(s, m, randomState(s, rng), 0.3);
  // Newton matrix against differences of the residual.
  const int n = s.layout().size();
  const Eigen::VectorXd y = randomState(s, rng);
  const Eigen::VectorXd yp = Eigen::VectorXd::Random(n);
  testing::checkNewtonMatrix(s, 0.2, y, yp, 21.0, "coupling");
  // Rates along the motion (every body moving with its velocity).
  testing::checkConstraintRates(s, m, y, 0.0, testing::MotionRates::Skip);
}

// Kinematic march: predict, assemble, velocities, accelerations at each time. Each assembled
// state is accepted: the coupled angles' whole turns are committed in a run state
// (mechanics/expression_run_state.hpp), as the analysis drivers do.
template <class Check>
void march(MultibodySystem& s, double tEnd, double dt, Check check) {
  ExpressionRunState run(s.model());
  run.trackCoupledAngles(s.constraints());
  s.setRunState(&run);
  Eigen::VectorXd y = s.initialState(), yp;
  removeRedundantConstraints(s, y);
  for (double t = 0.0; t <= tEnd + 1e-12; t += dt) {
    if (t > 0.0) {
      for (int b = 0; b < s.layout().bodies; ++b) {
        const int o = s.layout().body(b);
        y.segment<7>(o) += dt * yp.segment<7>(o);
        y.segment<4>(o + L::kE).normalize();
      }
    }
    const auto a = assemblePositions(s, t, y, 1e-13, 30);
    ASSERT_TRUE(a.converged) << "t = " << t;
    solveVelocities(s, t, y);
    ASSERT_TRUE(solveAccelerations(s, t, y, yp));
    check(t, y, yp);
    run.commitCoupledAngles(s, y);
  }
  s.setRunState(nullptr);
}

// Rotation of body b about ground z (its x axis's angle), and its angular velocity.
double bodyAngle(const MultibodySystem& s, int b, const Eigen::VectorXd& y) {
  const Eigen::Matrix3d a = toEigen(bodyPose(s.layout(), b, y.data()).a);
  return std::atan2(a(1, 0), a(0, 0));
}
double bodyRate(const MultibodySystem& s, int b, const Eigen::VectorXd& y) {
  return toEigen(bodyPose(s.layout(), b, y.data()).wg)(2);
}
double wrapped(double a) { return std::remainder(a, 2 * kPi); }

// Two arms on revolute joints about ground z (at x = 0 and x = 1) and a slider along ground x.
const char* kThreeJoints =
    "coupler\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=1,0,0\n"
    "MARKER/12, PART=1, QP=0,2,0, ZP=1,2,0\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2, QP=0.3,0,0\n"
    "MARKER/21, PART=2\n"
    "PART/3, MASS=1, CM=30, IP=1,1,1\n"
    "MARKER/30, PART=3, QP=1.2,0.1,0\n"
    "MARKER/31, PART=3, QP=1,0,0\n"
    "PART/4, MASS=2, CM=40, IP=1,1,1\n"
    "MARKER/40, PART=4, QP=0.5,2,0.1\n"
    "MARKER/41, PART=4, QP=0,2,0, ZP=1,2,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "JOINT/2, REVOLUTE, I=31, J=11\n"
    "JOINT/3, TRANSLATIONAL, I=41, J=12\n";

TEST(Coupler, TwoJointsFollowTheLinearRelation) {
  const model::Model m = build(std::string(kThreeJoints) +
                               "COUPLER/1, JOINTS=1,2, TYPE=R,R, SCALES=2\n"
                               "MOTION/1, JOINT=1, FUNCTION=1.5*TIME\nEND\n");
  MultibodySystem s(m);
  ASSERT_EQ(m.couplers.size(), 1u);
  EXPECT_EQ(m.couplers[0].scales, (std::vector<double>{1.0, 2.0}));  // SCALES=r2, r1 = 1
  // theta1 + 2 theta2 = 0: arm 2 turns at -0.75 rad/s; 1.5 * 6 = 9 rad, beyond a turn.
  march(s, 6.0, 0.05, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd&) {
    EXPECT_NEAR(wrapped(bodyAngle(s, 1, y) + 0.75 * t), 0.0, 1e-10) << t;
    EXPECT_NEAR(bodyRate(s, 1, y), -0.75, 1e-10) << t;
  });
}

TEST(Coupler, ThreeJointsDerivativesAndDegreesOfFreedom) {
  const model::Model m =
      build(std::string(kThreeJoints) + "COUPLER/1, JOINTS=1,2,3, TYPE=R,R,T, SCALES=0.5,-0.25\n"
                                        "END\n");
  ASSERT_EQ(m.couplers[0].scales, (std::vector<double>{1.0, 0.5, -0.25}));
  MultibodySystem s(m);
  ASSERT_EQ(s.constraints().size(), 16);
  const Eigen::VectorXd y = s.initialState();
  for (int k = 0; k < s.constraints().size(); ++k)
    EXPECT_NEAR(s.constraintValue(k, 0.0, y.data()), 0.0, 1e-14) << s.constraints().describe(k, m);
  const auto red = removeRedundantConstraints(s, y);
  EXPECT_TRUE(red.removed.empty());
  EXPECT_EQ(18 - red.rank, 2);
  EXPECT_EQ(ConstraintSet::grueblerCount(m), 2);
  checkDerivatives(s, m);
}

TEST(Coupler, ThreeJointsClosedForm) {
  // theta1 + 0.5 theta2 - 0.25 s3 = 0 with theta1 = t and s3 = 0.4 sin t (slider along x).
  const model::Model m = build(std::string(kThreeJoints) +
                               "COUPLER/1, JOINTS=1,2,3, TYPE=R,R,T, SCALES=0.5,-0.25\n"
                               "MOTION/1, JOINT=1, FUNCTION=TIME\n"
                               "MOTION/2, JOINT=3, FUNCTION=0.4*SIN(TIME)\nEND\n");
  MultibodySystem s(m);
  march(s, 3.0, 0.05, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd&) {
    const double theta2 = (0.25 * 0.4 * std::sin(t) - t) / 0.5;
    EXPECT_NEAR(wrapped(bodyAngle(s, 1, y) - theta2), 0.0, 1e-10) << t;
    EXPECT_NEAR(bodyRate(s, 1, y), (0.1 * std::cos(t) - 1.0) / 0.5, 1e-10) << t;
  });
}

// Gear 1 (radius 0.1) about ground z at the origin, gear 2 (radius 0.2) at x = 0.3; contact at
// x = 0.1 with the common velocity along ground y.
const char* kSpur =
    "spur gears\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=0.3,0,0\n"
    "MARKER/12, PART=1, QP=0.1,0,0, ZP=0.1,1,0\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2, QP=0.01,0.02,0\n"
    "MARKER/21, PART=2\n"
    "PART/3, MASS=2, CM=30, IP=1,1,2\n"
    "MARKER/30, PART=3, QP=0.3,0.01,0.02\n"
    "MARKER/31, PART=3, QP=0.3,0,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "JOINT/2, REVOLUTE, I=31, J=11\n"
    "GEAR/1, JOINTS=1,2, CV=12\n";

TEST(Gear, SpurPairTurnsAtTheRatioOfTheRadii) {
  const model::Model m = build(std::string(kSpur) + "MOTION/1, JOINT=1, FUNCTION=2*TIME\nEND\n");
  MultibodySystem s(m);
  // External gears turn opposite ways: theta2 = -(R1/R2) theta1 = -theta1/2; 10 rad at t = 5.
  march(s, 5.0, 0.05, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    EXPECT_NEAR(wrapped(bodyAngle(s, 1, y) + t), 0.0, 1e-10) << t;
    EXPECT_NEAR(bodyRate(s, 1, y), -1.0, 1e-10) << t;
    EXPECT_NEAR(yp(s.layout().body(1) + L::kW + 2), 0.0, 1e-9) << t;
  });
}

TEST(Gear, SpurPairDerivativesAndDegreesOfFreedom) {
  const model::Model m = build(std::string(kSpur) + "END\n");
  MultibodySystem s(m);
  ASSERT_EQ(s.constraints().size(), 11);
  const auto red = removeRedundantConstraints(s, s.initialState());
  EXPECT_TRUE(red.removed.empty());
  EXPECT_EQ(12 - red.rank, 1);
  EXPECT_EQ(ConstraintSet::grueblerCount(m), 1);
  EXPECT_EQ(s.constraints().describe(10, m), "GEAR/1 equation common velocity along Zcv");
  checkDerivatives(s, m);
}

// Pinion of radius 0.1 about ground z; a rack sliding along ground x below it; contact at
// (0, -0.1, 0), common velocity along x.
const char* kRack =
    "rack and pinion\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=0,-0.1,0, ZP=1,-0.1,0\n"
    "MARKER/12, PART=1, QP=0,-0.1,0, ZP=1,-0.1,0\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2, QP=0.01,0.02,0\n"
    "MARKER/21, PART=2\n"
    "PART/3, MASS=3, CM=30, IP=1,1,1\n"
    "MARKER/30, PART=3, QP=0.2,-0.15,0\n"
    "MARKER/31, PART=3, QP=0,-0.1,0, ZP=1,-0.1,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "JOINT/2, TRANSLATIONAL, I=31, J=11\n"
    "GEAR/1, JOINTS=1,2, CV=12\n";

TEST(Gear, RackAdvancesTheRadiusPerRadian) {
  const model::Model m =
      build(std::string(kRack) + "MOTION/1, JOINT=1, FUNCTION=3*SIN(TIME)\nEND\n");
  MultibodySystem s(m);
  march(s, 4.0, 0.05, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    const int o = s.layout().body(1);
    // s = R theta: the pinion's point at (0, -R) moves along +x when it turns about +z.
    EXPECT_NEAR(y(o + L::kR) - 0.2, 0.1 * 3 * std::sin(t), 1e-10) << t;
    EXPECT_NEAR(y(o + L::kV), 0.3 * std::cos(t), 1e-10) << t;
    EXPECT_NEAR(yp(o + L::kV), -0.3 * std::sin(t), 1e-9) << t;
  });
}

TEST(Gear, RackDerivativesAndDegreesOfFreedom) {
  const model::Model m = build(std::string(kRack) + "END\n");
  MultibodySystem s(m);
  const auto red = removeRedundantConstraints(s, s.initialState());
  EXPECT_TRUE(red.removed.empty());
  EXPECT_EQ(12 - red.rank, 1);
  EXPECT_EQ(ConstraintSet::grueblerCount(m), 1);
  checkDerivatives(s, m);
}

TEST(Coupling, DataSetErrorsAreReported) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(std::string(kThreeJoints) +
                                "COUPLER/1, JOINTS=1,3, TYPE=R,R, SCALES=2\n"
                                "COUPLER/2, JOINTS=1,2,3, SCALES=2\n"
                                "GEAR/3, JOINTS=1,9, CV=10\nEND\n",
                            "bad.adm", ds, d);
  model::Model m;
  EXPECT_FALSE(model::buildModel(ds, m, d));
  std::string all;
  for (const auto& x : d.all()) all += format(x) + "\n";
  EXPECT_NE(all.find("COUPLER/1"), std::string::npos) << all;
  EXPECT_NE(all.find("has no rotation to couple"), std::string::npos) << all;
  EXPECT_NE(all.find("SCALES needs 2 or 3 values"), std::string::npos) << all;
  EXPECT_NE(all.find("joint 9 does not exist"), std::string::npos) << all;
}

// A pendulum: a rod along x from a revolute joint about ground z.
TEST(JointInitialConditions, PendulumStartsAtTheGivenAngleAndRate) {
  const model::Model m = build(
      "pendulum\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\n"
      "MARKER/20, PART=2, QP=0.5,0,0\n"
      "MARKER/21, PART=2\n"
      "JOINT/1, REVOLUTE, I=21, J=10, IC=30D,2\n"
      "ACCGRAV/JGRAV=-9.81\nEND\n");
  MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState();
  removeRedundantConstraints(s, y);
  AssemblyOptions o;
  o.tolerance = 1e-13;
  o.honourExact = true;
  o.holdJointInitialConditions = true;
  const AssemblyResult r = assemblePositions(s, 0.0, y, o);
  ASSERT_TRUE(r.converged);
  solveVelocities(s, 0.0, y, true);
  const int b = s.layout().body(0);
  EXPECT_NEAR(bodyAngle(s, 0, y), kPi / 6, 1e-12);
  EXPECT_NEAR(y(b + L::kR), 0.5 * std::cos(kPi / 6), 1e-12);
  EXPECT_NEAR(y(b + L::kR + 1), 0.5 * std::sin(kPi / 6), 1e-12);
  EXPECT_NEAR(bodyRate(s, 0, y), 2.0, 1e-12);
  EXPECT_NEAR(y(b + L::kV), -0.5 * std::sin(kPi / 6) * 2.0, 1e-12);
  EXPECT_NEAR(y(b + L::kV + 1), 0.5 * std::cos(kPi / 6) * 2.0, 1e-12);
  // Without the option the data set's configuration is kept (the equations are not in the DAE).
  Eigen::VectorXd y0 = s.initialState();
  ASSERT_TRUE(assemblePositions(s, 0.0, y0, 1e-13, 25).converged);
  solveVelocities(s, 0.0, y0);
  EXPECT_NEAR(bodyAngle(s, 0, y0), 0.0, 1e-14);
  EXPECT_NEAR(bodyRate(s, 0, y0), 0.0, 1e-14);
  EXPECT_EQ(s.constraints().size(), 5);
}

TEST(JointInitialConditions, CylindricalJointTakesTranslationAndRotation) {
  const model::Model m = build(
      "sleeve\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1, QP=0,0,0, ZP=1,0,0\n"
      "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\n"
      "MARKER/20, PART=2, QP=0.2,0,0.3\n"
      "MARKER/21, PART=2, QP=0,0,0, ZP=1,0,0\n"
      "JOINT/1, CYLINDRICAL, I=21, J=10, ICTRAN=0.25,-0.5, ICROT=-40D,3\nEND\n");
  MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState();
  AssemblyOptions o;
  o.tolerance = 1e-13;
  o.holdJointInitialConditions = true;
  ASSERT_TRUE(assemblePositions(s, 0.0, y, o).converged);
  solveVelocities(s, 0.0, y, true);
  const auto ics = ConstraintSet::jointInitialConditions(m);
  ASSERT_EQ(ics.size(), 2u);
  EXPECT_NEAR(s.geometryValue(ics[0].equation, y.data()), -40.0 * kPi / 180, 1e-12);
  EXPECT_NEAR(s.geometryValue(ics[1].equation, y.data()), 0.25, 1e-12);
  const BodyPose<double> p = bodyPose(s.layout(), 0, y.data());
  EXPECT_NEAR(toEigen(p.wg)(0), 3.0, 1e-12);  // zJ is ground x
  // The marker at the axis slides at -0.5 along x: the CM's x velocity (w x r has no x part).
  EXPECT_NEAR(toEigen(p.v)(0), -0.5, 1e-12);
}

}  // namespace
}  // namespace openmss::mechanics

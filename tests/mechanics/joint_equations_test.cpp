// Every joint type, joint primitive and marker-pair motion, each on one part against ground:
// constraint rows against central differences of the constraint values (virtual
// displacements), the Newton matrix against central differences of the residual, the
// constraint rates against differences along the motion, the equations' values at the data
// set's configuration (zero: the markers are placed to satisfy them) and the degrees of
// freedom (6 - rank of C there).

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "support/newton_matrix_check.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "support/constraint_derivative_check.hpp"
#include "support/random_state.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;
using testing::turned;
Eigen::VectorXd randomState(const MultibodySystem& s, std::mt19937& rng) {
  return testing::randomState(s, rng, testing::RandomMu::Yes);
}


struct Case {
  const char* name;
  const char* element;  // statements between I=21 (part 2) and J=10 (ground)
  int equations;
  int dof;
};

// Part 2's BCS is ground's, so marker 21 written with marker 10's QP and REULER coincides with
// it; the body frame (the CM marker's) is placed generically. Cases whose equations need zI
// perpendicular to zJ (UNIVERSAL, PERPENDICULAR) turn theta by 90 degrees: zI.zJ =
// cos(theta_I - theta_J) for equal psi.
std::string dataSet(const Case& c) {
  const std::string name = c.name;
  const bool perpendicular = name == "UNIVERSAL" || name == "PERPENDICULAR";
  std::string text =
      "joint test\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1, QP=0.3,-0.2,0.5, REULER=0.4,0.7,-0.2\n"
      "PART/2, MASS=2, CM=20, IP=1,2,3\n"
      "MARKER/20, PART=2, QP=0.2,0.1,-0.3, REULER=0.3,0.2,0.1\n";
  if (perpendicular)
    text += "MARKER/21, PART=2, QP=0.3,-0.2,0.5, REULER=0.4,2.2707963267948966,-0.2\n";
  else if (name == "RACKPIN")  // the pinion's x axis along the rack's z axis, z along xJ
    text +=
        "MARKER/21, PART=2, QP=0.3,-0.2,0.5, ZP=1.261873480440066,0.04170005265827717,"
        "0.37201370319014587, XP=0.55087018385001429,-0.79336378336138735,1.2648421872844886\n";
  else
    text += "MARKER/21, PART=2, QP=0.3,-0.2,0.5, REULER=0.4,0.7,-0.2\n";
  text += std::string(c.element) + "\nEND\n";
  return text;
}

model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "joint.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

class JointEquations : public ::testing::TestWithParam<Case> {};

TEST_P(JointEquations, HoldAtTheDataSetAndGiveTheirDegreesOfFreedom) {
  const model::Model m = build(dataSet(GetParam()));
  MultibodySystem s(m);
  ASSERT_EQ(s.constraints().size(), GetParam().equations);
  const Eigen::VectorXd y = s.initialState();
  for (int k = 0; k < s.constraints().size(); ++k)
    EXPECT_NEAR(s.constraintValue(k, 0.0, y.data()), 0.0, 1e-14) << s.constraints().describe(k, m);
  const auto red = removeRedundantConstraints(s, y);
  EXPECT_EQ(6 - red.rank, GetParam().dof);
  EXPECT_TRUE(red.removed.empty());
  EXPECT_EQ(ConstraintSet::grueblerCount(m), GetParam().dof);
}

TEST_P(JointEquations, RowsAreVirtualDisplacementDerivatives) {
  const model::Model m = build(dataSet(GetParam()));
  const MultibodySystem s(m);
  std::mt19937 rng(11);
  for (int trial = 0; trial < 3; ++trial)
    testing::checkConstraintRows(s, m, randomState(s, rng), 0.3);
}

TEST_P(JointEquations, NewtonMatrixMatchesCentralDifferences) {
  const model::Model m = build(dataSet(GetParam()));
  const MultibodySystem s(m);
  std::mt19937 rng(7);
  const int n = s.layout().size();
  const Eigen::VectorXd y = randomState(s, rng);
  Eigen::VectorXd yp = Eigen::VectorXd::Random(n);
  testing::checkNewtonMatrix(s, 0.123, y, yp, 37.0, "joint equations");
}

TEST_P(JointEquations, RatesMatchDifferencesAlongTheMotion) {
  const model::Model m = build(dataSet(GetParam()));
  const MultibodySystem s(m);
  std::mt19937 rng(5);
  const Eigen::VectorXd y = randomState(s, rng);
  // Time is held fixed: the differences see the geometry only, as the rates do.
  testing::checkConstraintRates(s, m, y, 0.5);
}

const Case kCases[] = {
    {"REVOLUTE", "JOINT/1, REVOLUTE, I=21, J=10", 5, 1},
    {"SPHERICAL", "JOINT/1, SPHERICAL, I=21, J=10", 3, 3},
    {"UNIVERSAL", "JOINT/1, UNIVERSAL, I=21, J=10", 4, 2},
    {"HOOKE", "JOINT/1, HOOKE, I=21, J=10", 4, 2},
    {"TRANSLATIONAL", "JOINT/1, TRANSLATIONAL, I=21, J=10", 5, 1},
    {"CYLINDRICAL", "JOINT/1, CYLINDRICAL, I=21, J=10", 4, 2},
    {"FIXED", "JOINT/1, FIXED, I=21, J=10", 6, 0},
    {"CONVEL", "JOINT/1, CONVEL, I=21, J=10", 4, 2},
    {"PLANAR", "JOINT/1, PLANAR, I=21, J=10", 3, 3},
    {"RACKPIN", "JOINT/1, RACKPIN, PD=0.8, I=21, J=10", 1, 5},
    {"SCREW", "JOINT/1, SCREW, PITCH=0.05, I=21, J=10", 1, 5},
    {"SCREW_LEFT", "JOINT/1, SCREW, PITCH=-0.3, I=21, J=10", 1, 5},
    {"ATPOINT", "JPRIM/1, ATPOINT, I=21, J=10", 3, 3},
    {"INLINE", "JPRIM/1, INLINE, I=21, J=10", 2, 4},
    {"INPLANE", "JPRIM/1, INPLANE, I=21, J=10", 1, 5},
    {"ORIENTATION", "JPRIM/1, ORIENTATION, I=21, J=10", 3, 3},
    {"PARALLEL_AXES", "JPRIM/1, PARALLEL_AXES, I=21, J=10", 2, 4},
    {"PERPENDICULAR", "JPRIM/1, PERPENDICULAR, I=21, J=10", 1, 5},
    {"MOTION_REVOLUTE", "JOINT/1, REVOLUTE, I=21, J=10\nMOTION/1, JOINT=1, FUNCTION=0.3*TIME**2", 6,
     0},
    {"MOTION_TRANSLATIONAL",
     "JOINT/1, TRANSLATIONAL, I=21, J=10\nMOTION/1, JOINT=1, FUNCTION=0.2*SIN(TIME)", 6, 0},
    {"MOTION_X", "MOTION/1, I=21, J=10, X, FUNCTION=0.2*SIN(TIME)", 1, 5},
    {"MOTION_Y", "MOTION/1, I=21, J=10, Y, FUNCTION=0.2*SIN(TIME)", 1, 5},
    {"MOTION_Z", "MOTION/1, I=21, J=10, Z, FUNCTION=0.2*SIN(TIME)", 1, 5},
    {"MOTION_B1", "MOTION/1, I=21, J=10, B1, FUNCTION=0.2*SIN(TIME)", 1, 5},
    {"MOTION_B2", "MOTION/1, I=21, J=10, B2, FUNCTION=0.2*SIN(TIME)", 1, 5},
    {"MOTION_B3", "MOTION/1, I=21, J=10, B3, FUNCTION=0.2*SIN(TIME)", 1, 5},
    {"MOTION_VELOCITY", "MOTION/1, I=21, J=10, B3, VELOCITY, FUNCTION=COS(TIME)", 1, 5},
    {"MOTION_ACCELERATION", "MOTION/1, I=21, J=10, Z, ACCELERATION, ICVEL=0.5, FUNCTION=COS(TIME)",
     1, 5},
};

INSTANTIATE_TEST_SUITE_P(AllKinds, JointEquations, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& param) {
                           return std::string(param.param.name);
                         });

}  // namespace
}  // namespace openmss::mechanics

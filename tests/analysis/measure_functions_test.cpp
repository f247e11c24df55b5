// Request functions against independent computations at a solved state: FX..TM (the net
// force on a marker) against the joint read-back JOINT(...) and Newton's second law, ORIENT
// body-fixed sequences against angles built by hand, INCANG against the law of cosines.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "analysis/request_values.hpp"
#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "model/model_builder.hpp"

namespace openmss::analysis {
namespace {

// A pendulum released horizontally: CM 2 m from the pivot, m = 3, g = 9.81.
const char* kDataSet =
    "measure functions\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "MARKER/11, PART=1, QP=0,-1,0\n"
    "PART/2, MASS=3, CM=20, IP=0.5,0.5,0.5\n"
    "MARKER/20, PART=2, QP=2,0,0, REULER=20D,30D,40D\n"
    "MARKER/21, PART=2, QP=0,0,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "ACCGRAV/ JGRAV=-9.81\n"
    "REQUEST/1, F2=FX(21)\\F3=FY(21)\\F4=FZ(21)\\F6=JOINT(1,0,2,0)\\F7=JOINT(1,0,3,0)\\"
    "F8=JOINT(1,0,4,0)\n"
    "REQUEST/2, F2=ORIENT(1,1,20,10)\\F3=ORIENT(1,2,20,10)\\F4=ORIENT(1,3,20,10)\\"
    "F6=ORIENT(6,1,20,10)\\F7=ORIENT(6,2,20,10)\\F8=ORIENT(6,3,20,10)\n"
    "REQUEST/3, F2=INCANG(11,10,20)\\F3=FM(21,10)\\F4=TM(21)\n"
    "END\n";

struct Solved {
  model::Model model;
  std::unique_ptr<mechanics::MultibodySystem> system;
  Eigen::VectorXd y, yp;
};

std::unique_ptr<Solved> solve() {
  auto s = std::make_unique<Solved>();
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(kDataSet, "m.adm", ds, d);
  EXPECT_TRUE(model::buildModel(ds, s->model, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  s->system = std::make_unique<mechanics::MultibodySystem>(s->model);
  s->y = s->system->initialState();
  mechanics::assemblePositions(*s->system, 0.0, s->y, 1e-12, 25);
  mechanics::solveVelocities(*s->system, 0.0, s->y);
  EXPECT_TRUE(mechanics::solveAccelerations(*s->system, 0.0, s->y, s->yp));
  return s;
}

TEST(MeasureFunctions, NetForceOnTheJointMarkerIsTheJointReaction) {
  const auto s = solve();
  const auto c = requestColumns(*s->system, s->model.requests[0], 0.0, s->y, s->yp);
  for (int k = 1; k <= 3; ++k) EXPECT_NEAR(c[k], c[k + 4], 1e-12) << k;
  // Newton's second law for the released pendulum: the pivot force on the pendulum is
  // m (a - g); with J = I + m L^2 about the pivot, a_y = -m g L^2 / J.
  const double m = 3, g = 9.81, l = 2, j = 0.5 + m * l * l;
  EXPECT_NEAR(c[2], m * (-m * g * l * l / j + g), 1e-10);
  EXPECT_NEAR(c[1], 0.0, 1e-10);  // no centripetal force at rest
}

TEST(MeasureFunctions, OrientSequencesMatchAnglesBuiltByHand) {
  const auto s = solve();
  const auto c = requestColumns(*s->system, s->model.requests[1], 0.0, s->y, s->yp);
  const double d = std::numbers::pi / 180;
  const Eigen::Matrix3d a = (Eigen::AngleAxisd(20 * d, Eigen::Vector3d::UnitZ()) *
                             Eigen::AngleAxisd(30 * d, Eigen::Vector3d::UnitX()) *
                             Eigen::AngleAxisd(40 * d, Eigen::Vector3d::UnitZ()))
                                .toRotationMatrix();
  // Rebuild the same matrix from each reported sequence.
  const Eigen::Matrix3d xyz = (Eigen::AngleAxisd(c[1], Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(c[2], Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(c[3], Eigen::Vector3d::UnitZ()))
                                  .toRotationMatrix();
  const Eigen::Matrix3d zyx = (Eigen::AngleAxisd(c[5], Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(c[6], Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(c[7], Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
  EXPECT_TRUE(xyz.isApprox(a, 1e-12));
  EXPECT_TRUE(zyx.isApprox(a, 1e-12));
}

TEST(MeasureFunctions, IncludedAngleAndMagnitudes) {
  const auto s = solve();
  const auto c = requestColumns(*s->system, s->model.requests[2], 0.0, s->y, s->yp);
  // Line 11 -> 10 points along +y, line 10 -> 20 along +x: 90 degrees.
  EXPECT_NEAR(c[1], std::numbers::pi / 2, 1e-12);
  const auto r = requestColumns(*s->system, s->model.requests[0], 0.0, s->y, s->yp);
  EXPECT_NEAR(c[2], std::hypot(r[1], r[2], r[3]), 1e-12);  // FM between 21 and 10
  EXPECT_NEAR(c[3], 0.0, 1e-10);                           // a revolute passes no torque here
}

}  // namespace
}  // namespace openmss::analysis

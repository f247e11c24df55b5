// The coupled joints against hand-derived closed forms, through the kinematic solver
// (assembly, velocities, accelerations at each time of a march): a SCREW advances PITCH per
// turn, a RACKPIN rolls PD/2 per radian, a CONVEL passes rotation at exactly constant velocity
// at any bend angle; cumulative angles of many turns are tracked. Also the motion forms
// VELOCITY and ACCELERATION against their integrals, and the loop count of the part graph.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/loop_count.hpp"
#include "mechanics/motion_profile.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;
constexpr double kPi = std::numbers::pi;

model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "closed_form.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

// A kinematic march: at each time a first-order prediction, then positions, velocities and
// accelerations solved exactly (to 1e-13). `check` sees each solved state.
template <class Check>
void march(MultibodySystem& s, double tEnd, double dt, Check check) {
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
  }
}

TEST(ScrewJoint, AdvancesOnePitchPerTurnOverManyTurns) {
  // A nut on a cylindrical joint along ground z, turned at 3 rad/s for 4 s (almost two turns):
  // z = PITCH * angle / 2 pi, dz/dt = 3 PITCH / 2 pi, d2z/dt2 = 0.
  const model::Model m = build(
      "screw\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1, QP=0,0,0\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2, QP=0.1,0.05,0.2\n"
      "MARKER/21, PART=2, QP=0,0,0\n"
      "JOINT/1, CYLINDRICAL, I=21, J=10\n"
      "JOINT/2, SCREW, PITCH=0.05, I=21, J=10\n"
      "MOTION/1, JOINT=1, ROTATION, FUNCTION=3*TIME\n"
      "END\n");
  MultibodySystem s(m);
  const double pitch = 0.05;
  int steps = 0;
  march(s, 4.0, 0.05, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    const MarkerState<double> i = markerState(m, s.layout(), m.markerIndex.at(21), y.data());
    const double z = pitch * 3.0 * t / (2.0 * kPi);
    EXPECT_NEAR(i.p.z, z, 1e-12) << t;
    EXPECT_NEAR(i.pdot.z, 3.0 * pitch / (2.0 * kPi), 1e-12) << t;
    EXPECT_NEAR(yp(L::kV + 2), 0.0, 1e-11) << t;
    ++steps;
  });
  EXPECT_EQ(steps, 81);
}

TEST(RackPinJoint, RollsHalfThePitchDiameterPerRadian) {
  // A pinion (axis ground z) kept in the plane z = 0 (PLANAR) with its centre on y = 0
  // (INPLANE), meshing with a rack whose pitch line is y = −PD/2 (the −yI side, docs/theory.md
  // §5), turned by a B3 motion at 2 rad/s for 5 s (10 rad): it rolls like a wheel on a floor,
  // x = −(PD/2) 2t.
  const model::Model m = build(
      "rack and pinion\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1, QP=0,-0.4,0, ZP=1,-0.4,0, XP=0,-0.4,1\n"
      "MARKER/11, PART=1, QP=0,0,0\n"
      "MARKER/12, PART=1, QP=0,0,0, ZP=0,1,0, XP=1,0,0\n"
      "PART/2, MASS=1, CM=20, IP=1,1,2\n"
      "MARKER/20, PART=2, QP=0,0,0\n"
      "MARKER/21, PART=2, QP=0,0,0\n"
      "MARKER/22, PART=2, QP=0,0,0, ZP=0,1,0, XP=1,0,0\n"
      "JOINT/1, PLANAR, I=21, J=11\n"
      "JPRIM/2, INPLANE, I=22, J=12\n"
      "JOINT/3, RACKPIN, PD=0.8, I=21, J=10\n"
      "MOTION/1, I=21, J=11, B3, FUNCTION=2*TIME\n"
      "END\n");
  MultibodySystem s(m);
  march(s, 5.0, 0.05, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    EXPECT_NEAR(y(L::kR + 0), -0.4 * 2.0 * t, 1e-12) << t;
    EXPECT_NEAR(y(L::kR + 1), 0.0, 1e-12) << t;
    EXPECT_NEAR(y(L::kV + 0), -0.8, 1e-12) << t;
    EXPECT_NEAR(y(L::kW + 2), 2.0, 1e-12) << t;
    EXPECT_NEAR(yp(L::kV + 0), 0.0, 1e-11) << t;
  });
}

TEST(ConvelJoint, PassesRotationAtConstantVelocityAtABend) {
  // Shaft 2 turns about -z (its CV marker's z points away from the joint centre); shaft 3's
  // axis is bent by 35 degrees. A CONVEL joint makes the output turn exactly as the input:
  // angle about zJ = -angle about zI at every instant (a HOOKE joint would not).
  const double bend = 35.0 * kPi / 180.0;
  auto num = [](double x) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    return std::string(buffer);
  };
  const std::string b = num(bend);
  const model::Model m = build(
      "constant velocity joint\n"
      "PART/1, GROUND\n"
      "MARKER/12, PART=1, QP=0,0,-1, REULER=0,180D,0\n"
      "MARKER/13, PART=1, QP=0," +
      num(-std::sin(bend)) + "," + num(std::cos(bend)) + ", REULER=0," + b +
      ",0\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2, QP=0.05,0,-0.5\n"
      "MARKER/21, PART=2, QP=0,0,0, REULER=0,180D,0\n"
      "MARKER/22, PART=2, QP=0,0,-1, REULER=0,180D,0\n"
      "PART/3, MASS=1, CM=30, IP=1,1,1\n"
      "MARKER/30, PART=3, QP=0,0,0.1\n"
      "MARKER/31, PART=3, QP=0,0,0, REULER=0," +
      b +
      ",0\n"
      "MARKER/32, PART=3, QP=0," +
      num(-std::sin(bend)) + "," + num(std::cos(bend)) + ", REULER=0," + b +
      ",0\n"
      "JOINT/1, CONVEL, I=21, J=31\n"
      "JOINT/2, REVOLUTE, I=22, J=12\n"
      "JOINT/3, REVOLUTE, I=32, J=13\n"
      "MOTION/1, JOINT=2, FUNCTION=1.5*TIME\n"
      "END\n");
  MultibodySystem s(m);
  const int i32 = m.markerIndex.at(32), i13 = m.markerIndex.at(13);
  march(s, 6.0, 0.05, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    const MarkerState<double> out = markerState(m, s.layout(), i32, y.data());
    const MarkerState<double> ref = markerState(m, s.layout(), i13, y.data());
    const double beta = std::atan2(dot(out.a.c[0], ref.a.c[1]), dot(out.a.c[0], ref.a.c[0]));
    // -1.5 t, compared modulo 2 pi.
    const double diff = std::remainder(beta + 1.5 * t, 2.0 * kPi);
    EXPECT_NEAR(diff, 0.0, 1e-11) << t;
    const V3<double> zJ = ref.a.c[2];
    EXPECT_NEAR(dot(out.w, zJ), -1.5, 1e-11) << t;
    // Angular acceleration of shaft 3 (body axes of part 3, whose state is the second body).
    EXPECT_NEAR(yp.segment<3>(L::kPerBody + L::kW).norm(), 0.0, 1e-10) << t;
  });
}

TEST(MotionProfile, VelocityAndAccelerationFormsIntegrateTheirFunction) {
  model::Motion v;
  v.form = model::Motion::Form::Velocity;
  v.icDisp = 0.3;
  Diagnostics d;
  ASSERT_TRUE(expr::Expression::parse("COS(2*TIME)", {}, "MOTION/1", d, v.function));
  model::Motion a = v;
  a.form = model::Motion::Form::Acceleration;
  a.icVel = 0.5;
  for (double t : {0.0, 0.37, 1.0, 5.5, 20.0, -1.2}) {
    const expr::TimeJet jv = motionProfile(v, t);
    EXPECT_NEAR(jv.value, 0.3 + std::sin(2 * t) / 2, 1e-13) << t;
    EXPECT_NEAR(jv.d1, std::cos(2 * t), 1e-15) << t;
    EXPECT_NEAR(jv.d2, -2 * std::sin(2 * t), 1e-14) << t;
    const expr::TimeJet ja = motionProfile(a, t);
    EXPECT_NEAR(ja.value, 0.3 + 0.5 * t + (1 - std::cos(2 * t)) / 4, 1e-13 * (1 + std::abs(t)))
        << t;
    EXPECT_NEAR(ja.d1, 0.5 + std::sin(2 * t) / 2, 1e-13) << t;
    EXPECT_NEAR(ja.d2, std::cos(2 * t), 1e-15) << t;
  }
}

TEST(MotionProfile, VelocityMotionDrivesAJointThroughManyTurns) {
  // MOTION VELOCITY on a revolute joint: angle = ICDISP + t + t^2 (f = 1 + 2 TIME).
  const model::Model m = build(
      "velocity motion\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2, QP=0.5,0,0\n"
      "MARKER/21, PART=2, QP=0,0,0\n"
      "JOINT/1, REVOLUTE, I=21, J=10\n"
      "MOTION/1, JOINT=1, VELOCITY, ICDISP=0.25, FUNCTION=1+2*TIME\n"
      "END\n");
  MultibodySystem s(m);
  march(s, 3.0, 0.02, [&](double t, const Eigen::VectorXd& y, const Eigen::VectorXd& yp) {
    const double angle = 0.25 + t + t * t;
    EXPECT_NEAR(y(L::kR + 0), 0.5 * std::cos(angle), 1e-12) << t;
    EXPECT_NEAR(y(L::kR + 1), 0.5 * std::sin(angle), 1e-12) << t;
    EXPECT_NEAR(y(L::kW + 2), 1 + 2 * t, 1e-11) << t;
    EXPECT_NEAR(yp(L::kW + 2), 2.0, 1e-10) << t;
  });
}

TEST(LoopCount, AdamsOverviewFigureSevenHasTwoIndependentLoopsAndOneDependent) {
  model::Model m;
  m.parts.resize(6);  // 100 (ground) .. 105
  auto joint = [&](int a, int b) {
    const int ia = static_cast<int>(m.markers.size());
    m.markers.push_back({});
    m.markers.back().part = a;
    m.markers.push_back({});
    m.markers.back().part = b;
    model::Joint j;
    j.iMarker = ia;
    j.jMarker = ia + 1;
    m.joints.push_back(j);
  };
  // Loop A: 100-101-102-103-100; loop B: 100-103-104-105-100 (joint 13 shared).
  joint(0, 1);
  joint(1, 2);
  joint(2, 3);
  joint(3, 0);
  joint(3, 4);
  joint(4, 5);
  joint(5, 0);
  const LoopCount c = countLoops(m);
  EXPECT_EQ(c.independent, 2);
  EXPECT_EQ(c.dependent, 1);
  // A second hinge between two parts already joined closes one more (independent) loop and
  // three more simple cycles appear: the 2-cycle, and A and C through the new hinge.
  joint(0, 1);
  const LoopCount d = countLoops(m);
  EXPECT_EQ(d.independent, 3);
  EXPECT_EQ(d.dependent + d.independent, 6);
}

TEST(LoopCount, OpenChainHasNone) {
  model::Model m;
  m.parts.resize(3);
  for (int k = 0; k < 2; ++k) {
    m.markers.push_back({});
    m.markers.back().part = k;
    m.markers.push_back({});
    m.markers.back().part = k + 1;
    model::Joint j;
    j.iMarker = 2 * k;
    j.jMarker = 2 * k + 1;
    m.joints.push_back(j);
  }
  const LoopCount c = countLoops(m);
  EXPECT_EQ(c.independent, 0);
  EXPECT_EQ(c.dependent, 0);
}

}  // namespace
}  // namespace openmss::mechanics

namespace openmss::mechanics {
namespace {

TEST(AdamsOverviewFigureSeven, GrueblerOneTwoIndependentLoopsOneDependent) {
  language::Dataset ds;
  Diagnostics d;
  ASSERT_TRUE(language::readDatasetFile(
      OPENMSS_SOURCE_DIR "/tests/mechanics/joint_data/adams_overview_figure7.adm", ds, d));
  model::Model m;
  ASSERT_TRUE(model::buildModel(ds, m, d));
  EXPECT_EQ(m.bodyCount(), 5);
  EXPECT_EQ(m.joints.size(), 7u);
  // ADAMS/Solver overview, Figure 7: DOF = 6 (6 - 1) - (5 + 5 + 4 + 4 + 4 + 4 + 3) = 1.
  EXPECT_EQ(ConstraintSet::grueblerCount(m), 1);
  const LoopCount loops = countLoops(m);
  EXPECT_EQ(loops.independent, 2);
  EXPECT_EQ(loops.dependent, 1);
  MultibodySystem s(m);
  const Eigen::VectorXd y = s.initialState();
  for (int k = 0; k < s.constraints().size(); ++k)
    EXPECT_NEAR(s.constraintValue(k, 0.0, y.data()), 0.0, 1e-12) << s.constraints().describe(k, m);
  // The invented geometry is generic: no redundant equation, and the rank agrees.
  const auto red = removeRedundantConstraints(s, y);
  EXPECT_TRUE(red.removed.empty());
  EXPECT_EQ(6 * 5 - red.rank, 1);
}

TEST(JointStatements, UnsupportedAndInvalidArgumentsAreDiagnosed) {
  const char* text =
      "bad joints\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1\n"
      "PART/2, MASS=1, CM=20, IP=1,1,1\n"
      "MARKER/20, PART=2\n"
      "JOINT/1, RACKPIN, I=20, J=10\n"                      // PD missing
      "JOINT/2, SCREW, PITCH=0, I=20, J=10\n"               // zero pitch
      "JOINT/3, REVOLUTE, PD=1, I=20, J=10\n"               // PD on a revolute
      "JOINT/4, SPHERICAL, IC=0.1, I=20, J=10\n"            // IC on a spherical joint
      "JPRIM/5, I=20, J=10\n"                               // type missing
      "MOTION/6, I=20, J=10, FUNCTION=TIME\n"               // direction missing
      "MOTION/7, JOINT=1, I=20, J=10, B1, FUNCTION=TIME\n"  // JOINT and I/J
      "END\n";
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "bad.adm", ds, d);
  model::Model m;
  EXPECT_FALSE(model::buildModel(ds, m, d));
  std::string all;
  for (const auto& x : d.all()) all += format(x) + "\n";
  for (const char* expected :
       {"JOINT/1", "JOINT/2", "JOINT/3", "JOINT/4", "JPRIM/5", "MOTION/6", "MOTION/7"})
    EXPECT_NE(all.find(expected), std::string::npos) << expected << " not diagnosed:\n" << all;
}

}  // namespace
}  // namespace openmss::mechanics

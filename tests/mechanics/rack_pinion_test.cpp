// RACKPIN against ADAMS's sign convention (docs/theory.md §5, "RackPin"): a positive turn θ of
// the pinion (I) marker about its own z axis goes with a displacement −(PD/2)·θ of the I marker
// relative to the rack (J) marker along z_J. The mechanism is laid out as the real ADAMS
// rack-and-pinion run that showed the convention: a pinion on a revolute joint about ground x,
// its I marker's x axis along the rack marker's z axis (ground −z), and a rack on a
// translational joint along ground z under gravity. Checked against closed forms: the rack's
// position, velocity and acceleration for a driven pinion angle, the pinion's angular velocity,
// the joint's reaction force and torque, and the free mechanism's initial accelerations.
// (The equation's Jacobian rows and Newton matrix against central differences are checked with
// every other joint in joint_equations_test.cpp.)

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "mechanics/pose.hpp"
#include "model/model_builder.hpp"

namespace openmss::mechanics {
namespace {

using L = StateLayout;

constexpr double kG = 9.80665;
constexpr double kRadius = 0.08;  // PD/2
constexpr double kRackMass = 1.5;
constexpr double kPinionInertia = 0.3;  // about the pinion axis (ground x)

// Markers: 21 the pinion's I marker (z along ground x, x along ground −z), 32 the rack's J
// marker (z along ground −z); both REULERs as in the ADAMS data set. The rack's J marker starts
// at the pinion centre, so the coupling's constant is 0; with P_I at the origin and z_J = −z,
// z_J·(P_I − P_J) is the rack's z, and the convention reads z = −(PD/2)·θ.
std::string dataSet(const std::string& motion) {
  return "rack and pinion, ADAMS layout\n"
         "PART/1, GROUND\n"
         "MARKER/10, PART=1, QP=0,0,0, REULER=90D,90D,-90D\n"
         "MARKER/11, PART=1, QP=0,-0.1,0, REULER=0,180D,0\n"
         "PART/2, MASS=2, CM=20, IP=0.3,0.2,0.2\n"
         "MARKER/20, PART=2, QP=0,0,0\n"
         "MARKER/21, PART=2, QP=0,0,0, REULER=90D,90D,-90D\n"
         "PART/3, MASS=1.5, CM=30, IP=0.1,0.1,0.1\n"
         "MARKER/30, PART=3, QP=0,0.1,0\n"
         "MARKER/31, PART=3, QP=0,-0.1,0, REULER=0,180D,0\n"
         "MARKER/32, PART=3, QP=0,0,0, REULER=0,180D,0\n"
         "JOINT/1, REVOLUTE, I=21, J=10\n"
         "JOINT/2, TRANSLATIONAL, I=31, J=11\n"
         "JOINT/3, RACKPIN, PD=0.16, I=21, J=32\n" +
         motion + "ACCGRAV/KGRAV=-9.80665\nEND\n";
}

model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "rack_pinion.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

int bodyOffset(const model::Model& m, const MultibodySystem& s, long partId) {
  return s.layout().body(m.parts[m.partIndex.at(partId)].body);
}

TEST(RackPin, ADrivenPinionMovesTheRackAsAdamsDoesWithTheReactionOfTheClosedForm) {
  // θ(t) = 0.5 t + 0.3 sin 2t about z_I (ground +x), turning both ways of the rack.
  const model::Model m =
      build(dataSet("MOTION/1, JOINT=1, ROTATION, FUNCTION=0.5*TIME+0.3*SIN(2*TIME)\n"));
  MultibodySystem s(m);
  const int pinion = bodyOffset(m, s, 2), rack = bodyOffset(m, s, 3);
  const int rackPin = m.jointIndex.at(3), pinionMarker = m.markerIndex.at(21);
  Eigen::VectorXd y = s.initialState(), yp;
  removeRedundantConstraints(s, y);
  int checked = 0;
  for (double t = 0.0; t <= 3.0 + 1e-12; t += 0.05) {
    const double theta = 0.5 * t + 0.3 * std::sin(2 * t);
    const double omega = 0.5 + 0.6 * std::cos(2 * t);
    const double alpha = -1.2 * std::sin(2 * t);
    // The rack (CM and J marker at z = 0 in the data set): z = −(PD/2)·θ.
    const double z = -kRadius * theta, vz = -kRadius * omega, az = -kRadius * alpha;
    // The kinematic solution from a first-order prediction, solved to 1e-13.
    if (t > 0.0) {
      for (const int o : {pinion, rack}) {
        y.segment<7>(o) += 0.05 * yp.segment<7>(o);
        y.segment<4>(o + L::kE).normalize();
      }
    }
    ASSERT_TRUE(assemblePositions(s, t, y, 1e-13, 30).converged) << t;
    solveVelocities(s, t, y);
    ASSERT_TRUE(solveAccelerations(s, t, y, yp)) << t;
    // Tolerances: the solves converge to 1e-13 on lengths of order 0.1 m; 1e-11 leaves room
    // for the rounding of the velocity and acceleration solves (accelerations ~1).
    EXPECT_NEAR(y(rack + L::kR + 2), z, 1e-11) << t;
    EXPECT_NEAR(y(rack + L::kV + 2), vz, 1e-11) << t;
    EXPECT_NEAR(yp(rack + L::kV + 2), az, 1e-10) << t;
    // The pinion turns about ground +x (= z_I; body x stays ground x for this rotation).
    EXPECT_NEAR(y(pinion + L::kW + 0), omega, 1e-11) << t;
    // Reaction of the RACKPIN on the pinion: the rack needs m (g + a_z) upwards, which it gets
    // through the joint (the translational joint carries nothing along z), so the pinion is
    // pushed down by that much, with the torque r m (g + a_z) about +x (contact on the −y_I
    // side of the pinion centre): τ = −(PD/2)·F along z_J.
    Eigen::Vector3d f, tq;
    s.elementReaction(false, rackPin, pinionMarker, y.data(), f, tq);
    const double load = kRackMass * (kG + az);
    EXPECT_NEAR(f.z(), -load, 1e-9) << t;
    EXPECT_NEAR(f.x(), 0.0, 1e-9) << t;
    EXPECT_NEAR(f.y(), 0.0, 1e-9) << t;
    EXPECT_NEAR(tq.x(), kRadius * load, 1e-9) << t;
    EXPECT_NEAR(tq.y(), 0.0, 1e-9) << t;
    EXPECT_NEAR(tq.z(), 0.0, 1e-9) << t;
    ++checked;
  }
  EXPECT_EQ(checked, 61);
}

TEST(RackPin, AFreePinionTurnsPositivelyAsTheRackFalls) {
  // Real ADAMS output for this layout: the rack falls (−z) and the pinion's angular
  // acceleration about +x is positive. Closed form (energy, rolling without slip):
  // a = −g m r² / (J + m r²), α = −a / r, reaction torque on the pinion J α about +x.
  const model::Model m = build(dataSet(""));
  MultibodySystem s(m);
  const int pinion = bodyOffset(m, s, 2), rack = bodyOffset(m, s, 3);
  Eigen::VectorXd y = s.initialState(), yp;
  removeRedundantConstraints(s, y);
  solveVelocities(s, 0.0, y);
  ASSERT_TRUE(solveAccelerations(s, 0.0, y, yp));
  const double mr2 = kRackMass * kRadius * kRadius;
  const double a = -kG * mr2 / (kPinionInertia + mr2);
  const double alpha = -a / kRadius;
  // One linear solve of size ~40 with entries of order 1: 1e-12 relative.
  EXPECT_NEAR(yp(rack + L::kV + 2), a, 1e-12);
  EXPECT_GT(alpha, 0.0);
  EXPECT_NEAR(yp(pinion + L::kW + 0), alpha, 1e-12);
  Eigen::Vector3d f, tq;
  s.elementReaction(false, m.jointIndex.at(3), m.markerIndex.at(21), y.data(), f, tq);
  EXPECT_NEAR(tq.x(), kPinionInertia * alpha, 1e-12);
  EXPECT_NEAR(f.z(), -kRackMass * (kG + a), 1e-12);
}

TEST(RackPin, GivesTheFiguresRealAdamsPrintedForItsRackAndPinionCase) {
  // The layout, masses and PD of the rack-and-pinion case ADAMS 2012 ran in the public
  // projectchrono/chrono repository (data/adams/test_RackPinion_Case01, not copied here): PD =
  // 0.1, a 1 kg rack, a 1 kg pinion with 0.1 kg m² about its axis. At t = 0 ADAMS's .req
  // printed: rack acceleration −2.39187E-01 along ground z, pinion WDX +4.78373E+00, and the
  // RACKPIN reaction on the pinion (0, 0, −9.56746E+00) N and (4.78373E-01, 0, 0) N m.
  const model::Model m = build(
      "rack and pinion as ADAMS ran it\n"
      "PART/1, GROUND\n"
      "MARKER/102, PART=1, QP=0,0,0, REULER=90D,90D,-90D\n"
      "MARKER/103, PART=1, QP=0,-0.1,0, REULER=0D,180D,0D\n"
      "PART/2, MASS=1, CM=201, IP=0.04,0.1,0.1\n"
      "MARKER/201, PART=2, QP=0,0,0, REULER=90D,90D,-90D\n"
      "MARKER/202, PART=2, QP=0,0,0, REULER=90D,90D,-90D\n"
      "PART/3, MASS=1, CM=301, IP=0.1,0.1,0.04\n"
      "MARKER/301, PART=3, QP=0,0.1,0, REULER=0D,180D,0D\n"
      "MARKER/302, PART=3, QP=0,-0.1,0, REULER=0D,180D,0D\n"
      "MARKER/303, PART=3, QP=0,0,0, REULER=0D,180D,0D\n"
      "JOINT/1, REVOLUTE, I=102, J=202\n"
      "JOINT/2, TRANSLATIONAL, I=103, J=302\n"
      "JOINT/3, RACKPIN, I=202, J=303, PD=0.1\n"
      "ACCGRAV/KGRAV=-9.80665\nEND\n");
  MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState(), yp;
  removeRedundantConstraints(s, y);
  solveVelocities(s, 0.0, y);
  ASSERT_TRUE(solveAccelerations(s, 0.0, y, yp));
  const int rack = bodyOffset(m, s, 3);
  // The pinion's angular acceleration in ground (w' is in body axes).
  const int pinionBody = m.parts[m.partIndex.at(2)].body;
  const Eigen::Vector3d wdot = toEigen(bodyPose(s.layout(), pinionBody, y.data()).a) *
                               yp.segment<3>(s.layout().body(pinionBody) + L::kW);
  Eigen::Vector3d f, tq;
  s.elementReaction(false, m.jointIndex.at(3), m.markerIndex.at(202), y.data(), f, tq);
  // ADAMS printed six significant digits: agreement to half a unit of the last one.
  EXPECT_NEAR(yp(rack + L::kV + 2), -2.39187e-01, 5e-7);
  EXPECT_NEAR(wdot.x(), 4.78373, 5e-6);
  EXPECT_NEAR(f.z(), -9.56746, 5e-6);
  EXPECT_NEAR(tq.x(), 4.78373e-01, 5e-7);
  EXPECT_NEAR(f.x(), 0.0, 1e-12);
  EXPECT_NEAR(tq.y(), 0.0, 1e-12);
}

}  // namespace
}  // namespace openmss::mechanics

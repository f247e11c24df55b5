// Redundant constraints (docs/theory.md §8, §8b): a door on two coaxial revolute hinges. The
// second hinge's five equations are found redundant and reported by element and equation, the
// door keeps one degree of freedom, and the whole reaction is on the first hinge (statics of
// the door's weight about the first hinge: F = (0, 0, m g), T = -(r_cm x W)); the second
// hinge's reaction is exactly zero. During a run, a removed equation that stays consistent
// lets the run go on; one that a motion drives apart stops it, naming the equation, with the
// outputs up to the last good step on disk.

#include <gtest/gtest.h>

#include "support/cli_run.hpp"
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "language/reader.hpp"
#include "mechanics/initial_conditions.hpp"
#include "mechanics/multibody_system.hpp"
#include "model/model_builder.hpp"
#include "output/request_file_reader.hpp"

namespace openmss {
namespace {

namespace fs = std::filesystem;

// Door: 10 kg, CM at (0.5, 0, 1); hinges about ground z at heights 0.5 and 1.5.
const char* kDoor =
    "door on two coaxial hinges\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1, QP=0,0,0.5\n"
    "MARKER/11, PART=1, QP=0,0,1.5\n"
    "PART/2, MASS=10, CM=20, IP=1,2,3\n"
    "MARKER/20, PART=2, QP=0.5,0,1\n"
    "MARKER/21, PART=2, QP=0,0,0.5\n"
    "MARKER/22, PART=2, QP=0,0,1.5\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "JOINT/2, REVOLUTE, I=22, J=11\n"
    "ACCGRAV/KGRAV=-9.81\n";

const char* kDoorRequests =
    "REQUEST/1, F2=JOINT(1,0,2,0)\\F3=JOINT(1,0,3,0)\\F4=JOINT(1,0,4,0)\\"
    "F6=JOINT(1,0,6,0)\\F7=JOINT(1,0,7,0)\\F8=JOINT(1,0,8,0)\n"
    "REQUEST/2, F2=JOINT(2,0,2,0)\\F3=JOINT(2,0,3,0)\\F4=JOINT(2,0,4,0)\\"
    "F6=JOINT(2,0,6,0)\\F7=JOINT(2,0,7,0)\\F8=JOINT(2,0,8,0)\n"
    "OUTPUT/REQSAVE\n";

model::Model build(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "door.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d)) << text;
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  return m;
}

TEST(RedundantHinge, SecondHingeIsRemovedAndCarriesNothing) {
  const model::Model m = build(std::string(kDoor) + "END\n");
  mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState(), yp;
  const auto red = mechanics::removeRedundantConstraints(s, y);
  EXPECT_EQ(6 - red.rank, 1);
  ASSERT_EQ(red.removed.size(), 5u);
  const char* labels[5] = {"X (I-J)", "Y (I-J)", "Z (I-J)", "Zi.Xj", "Zi.Yj"};
  for (int k = 0; k < 5; ++k)
    EXPECT_EQ(s.constraints().describe(red.removed[k], m),
              std::string("JOINT/2 (REVOLUTE) equation ") + labels[k]);
  ASSERT_TRUE(mechanics::solveAccelerations(s, 0.0, y, yp));
  const double w = 10 * 9.81;
  Eigen::Vector3d f, t;
  s.elementReaction(false, 0, 3 /* marker 21 */, y.data(), f, t);
  ASSERT_EQ(m.markers[3].id, 21);
  // Hinge 1 holds the weight and its moment about the hinge point: r_cm = (0.5, 0, 0.5),
  // r x (0, 0, -W) = (0, W/2, 0). Tolerance: a 6x6 KKT solve on O(100) numbers, 1e-12 relative.
  EXPECT_NEAR((f - Eigen::Vector3d(0, 0, w)).norm(), 0.0, 1e-10 * w);
  EXPECT_NEAR((t - Eigen::Vector3d(0, -0.5 * w, 0)).norm(), 0.0, 1e-10 * w);
  s.elementReaction(false, 1, 4 /* marker 22 */, y.data(), f, t);
  EXPECT_EQ(f, Eigen::Vector3d::Zero());
  EXPECT_EQ(t, Eigen::Vector3d::Zero());
  for (int k : red.removed) EXPECT_EQ(y(s.layout().lambda(k)), 0.0);
}

using openmss::testing::Result;
using openmss::testing::run;
using openmss::testing::scratch;
using openmss::testing::write;

TEST(RedundantHinge, CheckReportsTheRemovedEquations) {
  const fs::path dir = scratch("check");
  write(dir / "door.adm", std::string(kDoor) + "END\n");
  const Result r = run("check door.adm", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  for (const char* label : {"X (I-J)", "Y (I-J)", "Z (I-J)", "Zi.Xj", "Zi.Yj"})
    EXPECT_NE(r.output.find(std::string("redundant: JOINT/2 (REVOLUTE) equation ") + label),
              std::string::npos)
        << r.output;
  EXPECT_NE(r.output.find("DOF 1"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

TEST(RedundantHinge, DynamicRunPutsTheWholeReactionOnTheFirstHinge) {
  const fs::path dir = scratch("dyn");
  // The door turns at 1 rad/s (no torque about the vertical axis: it keeps turning); the
  // hinges stay coaxial, so the removed equations stay satisfied and the run completes.
  std::string text = std::string(kDoor) + kDoorRequests + "END\n";
  text.replace(text.find("IP=1,2,3"), 8, "IP=1,2,3, WZ=1");
  write(dir / "door.adm", text);
  const Result r = run("run door.adm --end 1 --steps 10 --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  std::string error;
  const auto req = output::readRequestFile((dir / "door.req").string(), &error);
  ASSERT_TRUE(req) << error;
  const int e1 = req->entryIndex(1), e2 = req->entryIndex(2);
  ASSERT_GE(e1, 0);
  ASSERT_GE(e2, 0);
  ASSERT_GE(req->steps.size(), 11u);
  const double w = 10 * 9.81;
  for (const auto& step : req->steps) {
    for (int c = 0; c < 6; ++c) EXPECT_EQ(step.rows[e2][c], 0.0) << step.time;
    // Hinge 1: F = (0, 0, W) plus the centripetal force m w^2 r toward the axis (r = 0.5 along
    // the door's x, which turns with it). Fz = W holds whatever the speed (printed with 5
    // significant digits); the horizontal part depends on w, kept by the integrator to its
    // default ERROR (1e-3 on displacements): 2 % leaves margin.
    EXPECT_NEAR(step.rows[e1][2], w, 1e-4 * w) << step.time;
    const double fx = step.rows[e1][0], fy = step.rows[e1][1];
    EXPECT_NEAR(std::hypot(fx, fy), 10 * 1.0 * 0.5, 2e-2 * 5) << step.time;
  }
  fs::remove_all(dir);
}

TEST(RedundantHinge, ARunStopsWhenARemovedEquationComesApart) {
  const fs::path dir = scratch("apart");
  // A crank on a revolute joint about ground z, its tip (1, 0, 0) held in ground's plane
  // x = 1 by an INPLANE primitive: at theta = 0 the primitive's row (translation along x) is
  // the revolute joint's, so it is removed; once the motion turns the crank, cos(theta) - 1
  // violates it. The motion waits until t = 0.5, so the steps up to 0.5 are good.
  write(dir / "crank.adm",
        "crank pressed against a plane\n"
        "PART/1, GROUND\n"
        "MARKER/10, PART=1\n"
        "MARKER/11, PART=1, QP=1,0,0, ZP=2,0,0\n"
        "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\n"
        "MARKER/20, PART=2, QP=0.5,0,0\n"
        "MARKER/21, PART=2\n"
        "MARKER/22, PART=2, QP=1,0,0, ZP=2,0,0\n"
        "JOINT/1, REVOLUTE, I=21, J=10\n"
        "JPRIM/2, INPLANE, I=22, J=11\n"
        "MOTION/1, JOINT=1, FUNCTION=STEP(TIME,0.5,0,1.5,1)\n"
        "REQUEST/1, DISPLACEMENT, I=20, J=10\n"
        "OUTPUT/REQSAVE\n"
        "END\n");
  write(dir / "crank.acf", "crank.adm\ncrank\nSIMULATE/KINEMATICS, END=1, STEPS=10\nSTOP\n");
  const Result r = run("run crank.acf --quiet", dir);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("JPRIM/2 (INPLANE) equation Zj.(I-J), removed as redundant at the "
                          "start, is violated by"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("at time 6.000000E-01"), std::string::npos) << r.output;
  std::string error;
  const auto req = output::readRequestFile((dir / "crank.req").string(), &error);
  ASSERT_TRUE(req) << error;
  const auto steps = output::lastStepPerTime(req->steps);
  ASSERT_FALSE(steps.empty());
  EXPECT_NEAR(steps.back().time, 0.5, 1e-9);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace openmss

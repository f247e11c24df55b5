// Initial conditions: EXACT coordinates in the least-change assembly (closed forms), and end to
// end through the openmss program: a mis-assembled revolute is corrected and the .msg says by how
// much; a model that cannot close names the violated constraint and exits non-zero;
// SIMULATE/INITIAL_CONDITIONS writes one output step; the IC command's parameters take effect.

#include "mechanics/initial_conditions.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_run.hpp"

#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "output/request_file_reader.hpp"

namespace openmss {
namespace {

namespace fs = std::filesystem;

// ---- EXACT in the assembly (library level) ----

// A pendulum whose pivot marker is turned 0.1 rad about the CM from where the joint wants it:
// the CM is at (1, 0, 0) and the marker at CM + (-cos 0.1, sin 0.1, 0), one length away, while
// the ground pivot is at the origin. Holding X:Y:Z the part can only turn, by exactly +0.1 rad
// about z; holding PSI:THETA:PHI it can only translate, by minus the marker's offset.
std::string misturnedPendulum(const std::string& exact) {
  return "misturned pendulum\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1" +
         exact +
         "\n"
         "MARKER/20, PART=2, QP=1,0,0\n"
         "MARKER/21, PART=2, QP=0.004995834721974179,0.09983341664682815,0\n"
         "JOINT/1, REVOLUTE, I=21, J=10\nEND\n";
}

struct Assembled {
  Eigen::Vector3d cm;
  double turn = 0.0;  // rotation about z, rad
  mechanics::AssemblyResult result;
};

Assembled assemble(const std::string& text) {
  language::Dataset ds;
  Diagnostics d;
  language::readDatasetText(text, "ic.adm", ds, d);
  model::Model m;
  EXPECT_TRUE(model::buildModel(ds, m, d));
  for (const auto& x : d.all()) ADD_FAILURE() << format(x);
  mechanics::MultibodySystem s(m);
  Eigen::VectorXd y = s.initialState();
  mechanics::removeRedundantConstraints(s, y);
  mechanics::AssemblyOptions o;
  o.tolerance = 1e-13;
  o.honourExact = true;
  Assembled a;
  a.result = mechanics::assemblePositions(s, 0.0, y, o);
  a.cm = y.segment<3>(0);
  const Eigen::Matrix3d rot = toEigen(mechanics::bodyPose(s.layout(), 0, y.data()).a);
  a.turn = std::atan2(rot(1, 0), rot(0, 0));
  return a;
}

TEST(InitialConditions, ExactPositionIsHeldAndThePartTurnsInstead) {
  const Assembled a = assemble(misturnedPendulum(", EXACT=X:Y:Z"));
  ASSERT_TRUE(a.result.converged);
  // The weights make an EXACT coordinate 1e12 times dearer; what it may still move is of the
  // order 1e-12 of the correction, far below 1e-10.
  EXPECT_NEAR((a.cm - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-10);
  EXPECT_NEAR(a.turn, 0.1, 1e-10);
  EXPECT_TRUE(a.result.exactChanged.empty());
}

TEST(InitialConditions, ExactAnglesAreHeldAndThePartTranslatesInstead) {
  const Assembled a = assemble(misturnedPendulum(", EXACT=PSI:THETA:PHI"));
  ASSERT_TRUE(a.result.converged);
  EXPECT_NEAR(a.cm.x(), 1.0 - 0.004995834721974179, 1e-10);
  EXPECT_NEAR(a.cm.y(), -0.09983341664682815, 1e-10);
  EXPECT_NEAR(a.turn, 0.0, 1e-10);
}

TEST(InitialConditions, WithoutExactTheLeastChangeMixesTurnAndShift) {
  const Assembled a = assemble(misturnedPendulum(""));
  ASSERT_TRUE(a.result.converged);
  EXPECT_GT(std::abs(a.turn), 1e-3);
  EXPECT_GT((a.cm - Eigen::Vector3d(1, 0, 0)).norm(), 1e-3);
}

TEST(InitialConditions, AnExactCoordinateTheJointsContradictIsReported) {
  // Holding all six coordinates cannot close the joint: the assembly still closes it (EXACT
  // yields to the constraints, as ADAMS says) and lists what it had to change.
  const Assembled a = assemble(misturnedPendulum(", EXACT=X:Y:Z:PSI:THETA:PHI"));
  ASSERT_TRUE(a.result.converged);
  EXPECT_FALSE(a.result.exactChanged.empty());
}

// ---- end to end through the program ----

using namespace openmss::testing;  // scratch, run, slurp, write (tests/support)

// The pivot marker of the pendulum sits 0.1 away from the ground pivot.
const char* kMisassembled =
    "mis-assembled pendulum\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=1,0,0\n"
    "MARKER/21, PART=2, QP=0,0.1,0\nJOINT/1, REVOLUTE, I=21, J=10\nACCGRAV/ JGRAV=-9.81\n"
    "REQUEST/1, DISPLACEMENT, I=21, J=10\nOUTPUT/REQSAVE\nEND\n";

TEST(InitialConditionsRun, AMisassembledRevoluteAssemblesAndTheMsgReportsTheCorrection) {
  const fs::path dir = scratch("misassembled");
  write(dir / "p.adm", kMisassembled);
  write(dir / "p.acf", "p\np\nsimulate/initial_conditions\nstop\n");
  const Result r = run("run p.acf --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  const std::string msg = slurp(dir / "p.msg");
  EXPECT_NE(msg.find("PART/2 moved by"), std::string::npos) << msg;
  EXPECT_NE(msg.find("to satisfy the constraints"), std::string::npos) << msg;
  EXPECT_NE(msg.find("End initial conditions: constraints satisfied"), std::string::npos) << msg;
  // One output step, at t = 0, with the joint closed (to the 6 digits the file prints).
  std::string err;
  const auto req = output::readRequestFile((dir / "p.req").string(), &err);
  ASSERT_TRUE(req) << err;
  ASSERT_EQ(req->steps.size(), 1u);
  EXPECT_EQ(req->steps[0].time, 0.0);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(req->steps[0].rows[0][k], 0.0, 1e-9);
  fs::remove_all(dir);
}

TEST(InitialConditionsRun, ExactThatTheJointContradictsIsReportedAsAWarning) {
  const fs::path dir = scratch("exact");
  std::string model = kMisassembled;
  model.replace(model.find("IP=0.1,0.1,0.1"), 14, "IP=0.1,0.1,0.1, EXACT=X:Y:Z:PSI:THETA:PHI");
  write(dir / "p.adm", model);
  write(dir / "p.acf", "p\np\nsimulate/initial_conditions, displacement\nstop\n");
  const Result r = run("run p.acf --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  const std::string msg = slurp(dir / "p.msg");
  EXPECT_NE(msg.find("EXACT=Y could not be held"), std::string::npos) << msg;
  fs::remove_all(dir);
}

TEST(InitialConditionsRun, TheIcCommandLimitsTheIterations) {
  // One Gauss-Newton iteration cannot close a 0.1 gap to 1e-10: MAXIT=1 must make it fail.
  const fs::path dir = scratch("icmaxit");
  write(dir / "p.adm", kMisassembled);
  write(dir / "p.acf", "p\np\nic/maxit=1, list\nsimulate/initial_conditions\nstop\n");
  const Result r = run("run p.acf --quiet", dir);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("after 1 iterations"), std::string::npos) << r.output;
  EXPECT_NE(slurp(dir / "p.msg").find("IC: AERROR=0.0001"), std::string::npos);
  fs::remove_all(dir);
}

TEST(InitialConditionsRun, AModelThatCannotCloseNamesTheViolatedConstraint) {
  // Two unit links pivoted on ground 3 apart cannot meet at a joint: the rod ends stay >= 1
  // apart. JOINT/3 joins their ends, written 3 apart.
  const fs::path dir = scratch("noclose");
  write(dir / "p.adm",
        "cannot close\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "MARKER/11, PART=1, QP=3,0,0\n"
        "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=0,0.5,0\n"
        "MARKER/21, PART=2\nMARKER/22, PART=2, QP=0,1,0\n"
        "PART/3, MASS=1, CM=30, IP=0.1,0.1,0.1\nMARKER/30, PART=3, QP=3,0.5,0\n"
        "MARKER/31, PART=3, QP=3,0,0\nMARKER/32, PART=3, QP=3,1,0\n"
        "JOINT/1, REVOLUTE, I=21, J=10\nJOINT/2, REVOLUTE, I=31, J=11\n"
        "JOINT/3, REVOLUTE, I=22, J=32\nACCGRAV/ JGRAV=-9.81\nEND\n");
  write(dir / "p.acf", "p\np\nsimulate/statics\nstop\n");
  const Result r = run("run p.acf --quiet", dir);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("the model cannot be assembled: JOINT/3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("is still violated by"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace openmss

// SIMULATE/STATICS end to end through the openmss program: a quasi-static slider-crank whose
// driving torque is checked against virtual work at every output time (to the 6 significant
// digits the request file prints), the unbalanced-DOF report and its exit status, the
// EQUILIBRIUM statement and command, and a dynamic run continuing from a static equilibrium.

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

#include "output/request_file_reader.hpp"

namespace {

namespace fs = std::filesystem;

using namespace openmss::testing;  // scratch, run, slurp, write (tests/support)

// Crank r = 1 driven by theta = TIME, rod l = 3, slider on x, spring k = 50, L0 = 5 from the
// slider to (10, 0, 0). REQUEST/1 sums the revolute and the motion between markers 21 and 10:
// its z torque is the driving torque.
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
    "SFORCE/1, TRANSLATION, I=40, J=12, FUNCTION=-50*(DM(40,12)-5)\n"
    "REQUEST/1, FORCE, I=21, J=10\nREQUEST/2, DISPLACEMENT, I=40, J=10\n"
    "OUTPUT/REQSAVE\nEND\n";

double drivingTorque(double theta) {
  const double r = 1.0, len = 3.0, k = 50.0, l0 = 5.0;
  const double s = std::sqrt(len * len - r * r * std::sin(theta) * std::sin(theta));
  const double x = r * std::cos(theta) + s;
  const double dxdtheta = -r * std::sin(theta) - r * r * std::sin(theta) * std::cos(theta) / s;
  return -k * ((10.0 - x) - l0) * dxdtheta;
}

TEST(StaticsRun, QuasiStaticSliderCrankTorqueMatchesVirtualWorkAtEveryOutput) {
  const fs::path dir = scratch("crank");
  write(dir / "c.adm", kSliderCrank);
  write(dir / "c.acf", "c\nc\nsimulate/statics, end=6, steps=12\nstop\n");
  const Result r = run("run c.acf --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  std::string err;
  const auto req = openmss::output::readRequestFile((dir / "c.req").string(), &err);
  ASSERT_TRUE(req) << err;
  ASSERT_EQ(req->steps.size(), 13u);  // t = 0 and the 12 output times
  for (size_t i = 0; i < req->steps.size(); ++i) {
    const auto& step = req->steps[i];
    EXPECT_NEAR(step.time, 0.5 * static_cast<double>(i), 1e-12);
    const double expected = drivingTorque(step.time);
    // Printed with 6 significant digits: relative 5e-6, plus the print of values near zero.
    EXPECT_NEAR(step.rows[0][5], expected, 1e-5 * std::abs(expected) + 1e-4) << step.time;
  }
  const std::string msg = slurp(dir / "c.msg");
  EXPECT_NE(msg.find("Begin quasi-static analysis"), std::string::npos) << msg;
  fs::remove_all(dir);
}

TEST(StaticsRun, AnUnbalancedFreeDegreeOfFreedomIsReportedAndTheRunFails) {
  const fs::path dir = scratch("wheel");
  write(dir / "w.adm",
        "driven wheel\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\nMARKER/21, PART=2, QP=0.5,0,0\n"
        "JOINT/1, REVOLUTE, I=20, J=10\nSFORCE/1, ROTATION, I=20, J=10, FUNCTION=5\n"
        "EQUILIBRIUM/ MAXIT=500\nEND\n");
  write(dir / "w.acf", "w\nw\nsimulate/statics\nstop\n");
  const Result r = run("run w.acf --quiet", dir);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("there is no static equilibrium"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("rotation of PART/2 about the ground-axes direction (0, 0, 1)"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("at each of the 3 configurations Newton tried"), std::string::npos)
      << r.output;
  fs::remove_all(dir);
}

// The hanging mass of the library test: m = 2, k = 100, L0 = 1, g = 9.81, so z = -1.1962.
const char* kHanging =
    "hanging mass\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\nMARKER/11, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=1,1,1, QG=0,0,-1\nMARKER/20, PART=2\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
    "SFORCE/1, TRANSLATION, I=20, J=11, FUNCTION=-100*(DM(20,11)-1)\n"
    "ACCGRAV/ KGRAV=-9.81\nREQUEST/1, DISPLACEMENT, I=20, J=10\nOUTPUT/REQSAVE\n";

TEST(StaticsRun, ADynamicRunFromTheEquilibriumStaysThere) {
  const fs::path dir = scratch("hang");
  write(dir / "h.adm", std::string(kHanging) + "EQUILIBRIUM/ ERROR=1e-10, IMBALANCE=1e-8\nEND\n");
  write(dir / "h.acf", "h\nh\nsimulate/statics\nsimulate/dynamics, end=1, steps=5\nstop\n");
  const Result r = run("run h.acf --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  std::string err;
  const auto req = openmss::output::readRequestFile((dir / "h.req").string(), &err);
  ASSERT_TRUE(req) << err;
  ASSERT_EQ(req->steps.size(), 6u);  // the equilibrium, then 5 dynamic outputs
  for (const auto& step : req->steps) EXPECT_NEAR(step.rows[0][2], -1.1962, 1e-9) << step.time;
  fs::remove_all(dir);
}

TEST(StaticsRun, TheEquilibriumCommandChangesTheParameters) {
  // MAXIT=1 with a tight ERROR cannot converge the torsion pendulum started horizontal.
  const fs::path dir = scratch("equil");
  write(dir / "p.adm",
        "torsion pendulum\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=1,0,0\n"
        "MARKER/21, PART=2, QP=0,0,0\nJOINT/1, REVOLUTE, I=21, J=10\n"
        "SFORCE/1, ROTATION, I=21, J=10, FUNCTION=-20*(ATAN2(DX(20,10),-DY(20,10))-PI/2)\n"
        "ACCGRAV/ JGRAV=-9.81\nEND\n");
  write(dir / "p.acf", "p\np\nequilibrium/maxit=1, error=1e-12, list\nsimulate/statics\nstop\n");
  Result r = run("run p.acf --quiet", dir);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("static equilibrium not found"), std::string::npos) << r.output;
  EXPECT_NE(slurp(dir / "p.msg").find("EQUILIBRIUM: ALIMIT=0.174533 rad, ERROR=1e-12"),
            std::string::npos);
  // DEFAULT restores MAXIT 25, and the run succeeds.
  write(dir / "p.acf", "p\np\nequilibrium/maxit=1\nequilibrium/default\nsimulate/statics\nstop\n");
  r = run("run p.acf --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  fs::remove_all(dir);
}

TEST(StaticsRun, DynamicRelaxationParametersAreRejectedWithTheirLine) {
  const fs::path dir = scratch("dynrelax");
  write(dir / "h.adm", std::string(kHanging) + "EQUILIBRIUM/ DYNAMIC, GLOBAL_DAMPING=1\nEND\n");
  write(dir / "h.acf", "h\nh\nsimulate/statics\nstop\n");
  const Result r = run("run h.acf --quiet", dir);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("h.adm:13"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("DYNAMIC is not supported yet"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("GLOBAL_DAMPING is not supported yet"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace

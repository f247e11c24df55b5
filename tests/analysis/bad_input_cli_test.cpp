// Bad input that real data sets get wrong (issue 16, "Bad input"), run end to end through the
// openmss program: each gives one located message naming the element and what to change, and
// the program ends normally (exit status 0, 1 or 2; never a signal):
//   * FRICTION on a FIXED joint (ADAMS allows translational, revolute, cylindrical, spherical,
//     Hooke and universal joints): an input error at the FRICTION's JOINT argument;
//   * a PTCV whose I marker starts 0.2 off its curve (more than the 1e-3 of the curve's size
//     tolerated, docs/theory.md §5d): a warning at the PTCV, then the initial-conditions
//     analysis moves the point onto the curve and the run reaches its END;
//   * a massless part left free (its mass matrix singular): an error at the PART naming the
//     free motions, from the set-up analysis, and no output step after it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>
#include <string>

#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::testing;

const char* kCommands = "model\nmodel\nsimulate/dynamics, end=0.5, dtout=0.05\nstop\n";

Result runDataSet(const std::string& name, const std::string& adm) {
  const fs::path dir = scratch(name);
  write(dir / "model.adm", adm);
  write(dir / "run.acf", kCommands);
  Result r = run("run run.acf", dir);
  fs::remove_all(dir);
  return r;
}

// Exit statuses of the program: 0 done, 1 input error, 2 analysis failed. A crash (a signal)
// is -1 from cli_run or 128 + signal from the shell.
bool endedNormally(const Result& r) { return r.status >= 0 && r.status <= 2; }

TEST(BadInputCli, FrictionOnAFixedJointIsRefusedAtItsJointArgument) {
  const Result r = runDataSet("bad-friction",
                              "friction on a fixed joint\n"
                              "PART/1, GROUND\n"
                              "MARKER/10, PART=1\n"
                              "PART/2, MASS=1, CM=20, IP=1,1,1\n"
                              "MARKER/20, PART=2\n"
                              "JOINT/1, FIXED, I=20, J=10\n"
                              "FRICTION/1, JOINT=1, MU_STATIC=0.3, MU_DYNAMIC=0.2\n"
                              "END\n");
  EXPECT_TRUE(endedNormally(r)) << r.status;
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("model.adm:7:13: error: FRICTION/1: JOINT/1 is a FIXED joint, and "
                          "FRICTION acts only on "),
            std::string::npos)
      << r.output;
}

TEST(BadInputCli, APointStartingOffItsCurveIsNamedAndMovedOntoIt) {
  // A closed circle of radius 1 about ground's origin (65 points, the last repeating the
  // first); the bead starts at (0, -1.2): 0.2 off the curve.
  std::ostringstream adm;
  adm.precision(17);
  adm << "point off its curve\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "MARKER/11, PART=1, FLOATING\n"
         "PART/2, MASS=1, CM=20, IP=1e-3,1e-3,1e-3, QG=0,-1.2,0\nMARKER/20, PART=2\n"
         "MATRIX/1, FULL=RORDER, ROWS=65, COLUMNS=3, VALUES=";
  for (int k = 0; k <= 64; ++k) {
    const double a = 2.0 * std::numbers::pi * (k % 64) / 64.0;  // the last point is the first
    adm << (k ? ", " : "") << std::sin(a) << ", " << -std::cos(a) << ", 0";
  }
  adm << "\nCURVE/1, CLOSED, MATRIX=1, CURVE_POINTS\n"
         "PTCV/1, I=20, JFLOAT=11, CURVE=1, RM=10\n"
         "ACCGRAV/ JGRAV=-9.81\nEND\n";
  const Result r = runDataSet("bad-ptcv", adm.str());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("model.adm:10:1: warning: PTCV/1: marker I starts 0.2"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("away from CURVE/1 (in RM's frame); the initial-conditions analysis "
                          "will move it onto the curve. Place I (or the curve's points) so that "
                          "I lies on the curve."),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("reached t = 0.5"), std::string::npos) << r.output;
}

TEST(BadInputCli, AFreeMasslessPartIsNamedWithTheMotionsNothingHolds) {
  const Result r = runDataSet("bad-massless",
                              "free massless part\n"
                              "PART/1, GROUND\n"
                              "MARKER/10, PART=1\n"
                              "PART/2, MASS=1, CM=20, IP=1,1,1\n"
                              "MARKER/20, PART=2\n"
                              "JOINT/1, REVOLUTE, I=20, J=10\n"
                              "PART/3\n"
                              "ACCGRAV/ JGRAV=-9.80665\n"
                              "END\n");
  EXPECT_TRUE(endedNormally(r)) << r.status;
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("model.adm:7:1: error: PART/3: has no mass and no constraint holds a "
                          "translation along"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("a massless part must be held by constraints"), std::string::npos)
      << r.output;
}

}  // namespace

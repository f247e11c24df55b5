// VARVAL in MOTION functions (docs/theory.md §5, "Motions reading VARIABLEs";
// src/model/motion_variables.hpp). ADAMS requires a motion to be a function of time only; the
// corpus's FRS5 data sets write one through VARIABLEs that are functions of TIME
// (MOTION/5, FUNCTION = VARVAL(1001)+VARVAL(1002)). Truth: a revolute joint driven by
// VARVAL(1) + VARVAL(2), VARIABLE/1 = 0.5 TIME^2, VARIABLE/2 = VARVAL(3) SIN(TIME),
// VARIABLE/3 = 0.1, follows the closed form
//   theta = t^2/2 + 0.1 sin t, omega = t + 0.1 cos t, alpha = 1 - 0.1 sin t
// (the motion's exact time jets: the angle, its rate and its acceleration, 6-digit print).
// A VARVAL of a VARIABLE that reads the state, a cycle, and a missing VARIABLE are refused
// at the motion's function with their reason.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "language/reader.hpp"
#include "model/model_builder.hpp"
#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::testing;

const char* kHead =
    "motion through variables\n"
    "UNITS/ SYSTEM=NONE\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\n"
    "MARKER/20, PART=2, QP=0,0,0\n"
    "MARKER/21, PART=2, QP=1,0,0\n"
    "JOINT/1, REVOLUTE, I=20, J=10\n";

bool command(openmss::commands::Session& s, const std::string& text) {
  openmss::language::CommandReader reader("m.acf", 1);
  reader.feedLine(text);
  reader.finish();
  auto c = reader.takeCommands();
  EXPECT_EQ(c.size(), 1u);
  s.echoCommand(text);
  return s.execute(c.front());
}

TEST(MotionVariables, AJointDrivenThroughVariablesOfTimeFollowsTheClosedForm) {
  const fs::path dir = scratch("motion-variables");
  write(dir / "m.adm", std::string(kHead) +
                           "MOTION/1, JOINT=1, FUNCTION=VARVAL(1) + varval( 2 )\n"
                           "VARIABLE/1, FUNCTION=0.5*TIME**2\n"
                           "VARIABLE/2, FUNCTION=VARVAL(3)*SIN(TIME)\n"
                           "VARIABLE/3, FUNCTION=0.1\n"
                           "REQUEST/1, F2=AZ(20,10)\\F3=WZ(20,10)\\F4=WDTZ(20,10)\n"
                           "OUTPUT/REQSAVE\nEND\n");
  {
    openmss::commands::SessionOptions o;
    o.outputDirectory = dir.string();
    o.echoDiagnostics = false;
    openmss::commands::Session s(o);
    ASSERT_TRUE(s.loadModel((dir / "m.adm").string(), "m"));
    ASSERT_TRUE(command(s, "SIMULATE/KINEMATICS, END=1, STEPS=20"));
    ASSERT_TRUE(command(s, "STOP"));
    EXPECT_EQ(s.diagnostics().errorCount(), 0);
  }
  std::string err;
  const auto req = openmss::output::readRequestFile((dir / "m.req").string(), &err);
  ASSERT_TRUE(req) << err;
  int compared = 0;
  double worst = 0.0;
  for (const auto& step : req->steps) {
    const double t = step.time;
    const double theta = 0.5 * t * t + 0.1 * std::sin(t), omega = t + 0.1 * std::cos(t),
                 alpha = 1.0 - 0.1 * std::sin(t);
    // 6 significant digits in the .req: 1e-5 absolute on values of order one.
    EXPECT_NEAR(step.rows[0][0], theta, 1e-5) << t;
    EXPECT_NEAR(step.rows[0][1], omega, 1e-5) << t;
    EXPECT_NEAR(step.rows[0][2], alpha, 1e-5) << t;
    worst = std::max({worst, std::abs(step.rows[0][0] - theta), std::abs(step.rows[0][1] - omega),
                      std::abs(step.rows[0][2] - alpha)});
    ++compared;
  }
  EXPECT_GE(compared, 21);
  std::printf(
      "MOTION through VARVAL: angle, rate and acceleration within %.1e of the closed form "
      "over %d outputs\n",
      worst, compared);
  fs::remove_all(dir);
}

std::string errorsOf(const std::string& rest) {
  openmss::language::Dataset ds;
  openmss::Diagnostics d;
  openmss::language::readDatasetText(std::string(kHead) + rest + "END\n", "v.adm", ds, d);
  openmss::model::Model m;
  openmss::model::buildModel(ds, m, d);
  std::string errors;
  for (const auto& x : d.all())
    if (x.severity == openmss::Severity::Error) errors += format(x) + "\n";
  return errors;
}

TEST(MotionVariables, VariablesThatAreNotFunctionsOfTimeAreRefusedAtTheMotion) {
  // Line 9 is the MOTION, its FUNCTION value at column 29.
  const std::string state = errorsOf(
      "MOTION/1, JOINT=1, FUNCTION=VARVAL(4)\nVARIABLE/4, FUNCTION=2*VARVAL(5)\n"
      "VARIABLE/5, FUNCTION=DX(21,10)\n");
  EXPECT_NE(state.find("v.adm:9:29: error: MOTION/1: a MOTION function may depend on TIME only, "
                       "but VARVAL(5) through VARIABLE/5 calls DX"),
            std::string::npos)
      << state;
  EXPECT_NE(state.find("ADAMS requires a motion to be a function of time only"), std::string::npos);
  const std::string cycle =
      errorsOf("MOTION/1, JOINT=1, FUNCTION=VARVAL(6)\nVARIABLE/6, FUNCTION=VARVAL(6)+TIME\n");
  EXPECT_NE(cycle.find("v.adm:9:29: error: MOTION/1: the VARIABLEs read through VARVAL refer to "
                       "each other in a cycle"),
            std::string::npos)
      << cycle;
  const std::string missing = errorsOf("MOTION/1, JOINT=1, FUNCTION=VARVAL(7)\n");
  EXPECT_NE(missing.find("v.adm:9:29: error: MOTION/1: VARVAL(7) names no VARIABLE"),
            std::string::npos)
      << missing;
  // A direct state dependence keeps its message.
  const std::string direct = errorsOf(
      "MOTION/1, JOINT=1, FUNCTION=TIME+VARVAL(8)*DX(21,10)\n"
      "VARIABLE/8, FUNCTION=TIME\n");
  EXPECT_NE(direct.find("a MOTION function may depend on TIME only, but it calls "),
            std::string::npos)
      << direct;
}

}  // namespace

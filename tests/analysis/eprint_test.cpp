// DEBUG/EPRINT end to end: the statement (and the command) write, for every integration step,
// its number, order, time and step size, and for every corrector iteration the largest
// residual and change named by their elements, to the .msg only; without EPRINT none of it.

#include <gtest/gtest.h>

#include "support/cli_run.hpp"
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

using openmss::testing::scratch;
using openmss::testing::slurp;
using openmss::testing::write;

int run(const std::string& args, const fs::path& dir) {
  return openmss::testing::run(args, dir).status;
}

// A pendulum on a revolute joint (PART/2, JOINT/1) under gravity.
std::string pendulum(const std::string& debug) {
  return "pendulum\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
         "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\nMARKER/20, PART=2, QP=1,0,0\n"
         "MARKER/21, PART=2\nJOINT/1, REVOLUTE, I=21, J=10\nACCGRAV/ JGRAV=-9.81\n" +
         debug + "END\n";
}

int count(const std::string& text, const std::regex& re) {
  return static_cast<int>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

const std::regex kStep(
    R"( EPRINT step (\d+): order (\d), time \S+E[+-]\d+, step size \S+E[+-]\d+)");
const std::regex kIteration(
    R"(   iteration \d+: largest residual \S+ in (.+ of PART/2|JOINT/1 \(REVOLUTE\) equation [^;]+); )"
    R"(largest change \S+ in (\S+ of PART/2|reaction of JOINT/1 \(REVOLUTE\) equation \S+))");

TEST(Eprint, StatementWritesStepsAndNamedIterationsToTheMessageFile) {
  const fs::path dir = scratch("statement");
  write(dir / "p.adm", pendulum("DEBUG/ EPRINT\n"));
  write(dir / "p.acf", "p.adm\np\nSIMULATE/DYNAMICS, END=0.05, STEPS=5\nSTOP\n");
  ASSERT_EQ(run("run p.acf", dir), 0) << slurp(dir / "cli.log");
  const std::string msg = slurp(dir / "p.msg");
  const int steps = count(msg, kStep), iterations = count(msg, kIteration);
  std::printf("EPRINT: %d step lines, %d iteration lines\n", steps, iterations);
  EXPECT_GE(steps, 5);
  EXPECT_GE(iterations, steps);  // at least one corrector iteration per step
  EXPECT_NE(msg.find(" EPRINT step 1: order 1, time 0.000000000E+00"), std::string::npos);
  EXPECT_NE(msg.find("   step 1 accepted: local error"), std::string::npos);
  // Every iteration line names its elements (the regex accepts only named ones).
  EXPECT_EQ(count(msg, std::regex("   iteration ")), iterations);
  // Not on the terminal.
  EXPECT_EQ(slurp(dir / "cli.log").find("EPRINT"), std::string::npos);
}

// DSTIFF (SUNDIALS IDA) reports each accepted step with its order, start and step size as well
// (IDA's rejected attempts stay inside IDASolve): the EPRINT that located DSTIFF's stop at the
// first flat passage of IFToMM A02 (docs/validation.md).
TEST(Eprint, DstiffWritesEveryAcceptedStepWithItsOrderTimeAndStepSize) {
  const fs::path dir = scratch("dstiff");
  write(dir / "p.adm", pendulum("DEBUG/ EPRINT\n"));
  write(dir / "p.acf",
        "p.adm\np\nINTEGRATOR/DSTIFF, ERROR=1e-6\nSIMULATE/DYNAMICS, END=0.05, STEPS=5\nSTOP\n");
  ASSERT_EQ(run("run p.acf", dir), 0) << slurp(dir / "cli.log");
  const std::string msg = slurp(dir / "p.msg");
  const int steps = count(msg, kStep);
  EXPECT_GE(steps, 5);
  EXPECT_EQ(count(msg, std::regex("   step \\d+ accepted: local error")), steps);
  EXPECT_NE(msg.find(" EPRINT step 1: order 1, time 0.000000000E+00"), std::string::npos);
}

TEST(Eprint, CommandSwitchesItOnAndTheDefaultWritesNone) {
  const fs::path dir = scratch("command");
  write(dir / "p.adm", pendulum(""));
  write(dir / "p.acf",
        "p.adm\np\nSIMULATE/DYNAMICS, END=0.02, STEPS=2\nDEBUG/EPRINT\n"
        "SIMULATE/DYNAMICS, END=0.04, STEPS=2\nSTOP\n");
  ASSERT_EQ(run("run p.acf", dir), 0) << slurp(dir / "cli.log");
  const std::string msg = slurp(dir / "p.msg");
  const size_t command = msg.find("DEBUG/EPRINT");
  ASSERT_NE(command, std::string::npos);
  const std::string before = msg.substr(0, command), after = msg.substr(command);
  EXPECT_EQ(count(before, kStep), 0);
  EXPECT_EQ(before.find("iteration"), std::string::npos);
  EXPECT_GE(count(after, kStep), 2);
  EXPECT_GE(count(after, kIteration), 2);
}

}  // namespace

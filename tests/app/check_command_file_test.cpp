// `openmss check FILE.acf` (issue 15): the command file and its model in one pass, without
// simulating, every error of either reported, no output file written.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::testing;  // scratch, run, write (tests/support)

const char* kPendulum =
    "pendulum\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "PART/2, MASS=1, IP=0.1,0.1,0.1, CM=21\nMARKER/20, PART=2\nMARKER/21, PART=2, QP=0,-1,0\n"
    "JOINT/1, REVOLUTE, I=20, J=10\nMOTION/1, JOINT=1, FUNCTION=0\nACCGRAV/ JGRAV=-9.81\n"
    "PREFERENCES/ NTHREADS=4\nEND\n";

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(CheckCommandFile, ACleanStudyChecksWithoutSimulating) {
  const fs::path dir = scratch("check-clean");
  write(dir / "p.adm", kPendulum);
  write(dir / "p.acf",
        "p\np\nSIMULATE/STATICS\nDEACTIVATE/MOTION, ID=1\nSFORCE/1, LIST\n"
        "ACCGRAV/ JGRAV=-1.62\nSIMULATE/DYNAMICS, END=1, STEPS=10\nSTOP\n");
  const Result r = run("check p.acf", dir);
  // SFORCE/1 does not exist: the one error; the NTHREADS warning names the option.
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("p.acf:5:1: error: SFORCE/1: SFORCE/1 does not exist"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("PREFERENCES/NTHREADS"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("p.acf: 1 error(s)"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "p.msg"));
  EXPECT_FALSE(fs::exists(dir / "p.req"));

  write(dir / "q.acf",
        "p\nq\nSIMULATE/STATICS\nDEACTIVATE/MOTION, ID=1\nACCGRAV/ JGRAV=-1.62, LIST\n"
        "SIMULATE/DYNAMICS, END=1, STEPS=10\nSTOP\n");
  const Result clean = run("check q.acf", dir);
  EXPECT_EQ(clean.status, 0) << clean.output;
  EXPECT_NE(clean.output.find("q.acf: 0 error(s)"), std::string::npos) << clean.output;
  EXPECT_FALSE(fs::exists(dir / "q.msg"));
}

// Errors in both files, and after the first failing command: every one reported.
TEST(CheckCommandFile, ReportsEveryErrorOfTheModelAndTheCommands) {
  const fs::path dir = scratch("check-errors");
  write(dir / "p.adm", kPendulum);
  write(dir / "p.acf",
        "p\np\nDEACTIVATE/JOINT, ID=7\nSIMULATE/DYNAMICS, END=1, STEPS=10\n"
        "SIMULATE/DYNAMICS, END=0.5, STEPS=10\nMOTION/1, FUNCTION=1+\nSTOP\n");
  const Result r = run("check p.acf", dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("p.acf:3:"), std::string::npos) << r.output;  // no JOINT/7
  EXPECT_NE(r.output.find("p.acf:5:"), std::string::npos) << r.output;  // END before t = 1
  EXPECT_NE(r.output.find("p.acf:6:"), std::string::npos) << r.output;  // bad expression
  EXPECT_NE(r.output.find("p.acf: 3 error(s)"), std::string::npos) << r.output;

  // A model error is reported too (a MARKER on a missing PART), with the commands unread.
  write(dir / "bad.adm",
        std::string(kPendulum).replace(std::string(kPendulum).find("MARKER/21, PART=2"), 17,
                                       "MARKER/21, PART=9"));
  write(dir / "b.acf", "bad\nb\nSIMULATE/STATICS\nSTOP\n");
  const Result b = run("check b.acf", dir);
  EXPECT_EQ(b.status, 1);
  EXPECT_GE(count(b.output, "bad.adm:"), 1) << b.output;

  // A model that does not exist: one error at line 1 of the command file.
  write(dir / "n.acf", "nothere\nn\nSIMULATE/STATICS\nSTOP\n");
  const Result n = run("check n.acf", dir);
  EXPECT_EQ(n.status, 1);
  EXPECT_NE(n.output.find("n.acf:1:1: error: the data set"), std::string::npos) << n.output;
  EXPECT_NE(n.output.find("n.acf: 1 error(s)"), std::string::npos) << n.output;
}

}  // namespace

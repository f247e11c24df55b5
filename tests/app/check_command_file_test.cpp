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

  // A model error is reported too (a MARKER on a missing PART), and the commands are still
  // checked against the data set as written: every error of both files in one pass.
  write(dir / "bad.adm",
        std::string(kPendulum).replace(std::string(kPendulum).find("MARKER/21, PART=2"), 17,
                                       "MARKER/21, PART=9"));
  write(dir / "b.acf",
        "bad\nb\nSIMULATE/STATICS\nDEACTIVATE/JOINT, ID=7\nSFORCE/1, FUNCTION=1\n"
        "SIMULATE/DYNAMICS, END=1, STEPS=10\nSIMULATE/DYNAMICS, END=0.5, STEPS=10\n"
        "MOTION/1, FUNCTION=1+\nSAVE/STATES, FILE=s.sav\nRELOAD/STATES, FILE=s.sav\n"
        "RELOAD/STATES, FILE=none.sav\nDEACTIVATE/MOTION, ID=1\nSTOP\n");
  const Result b = run("check b.acf", dir);
  EXPECT_EQ(b.status, 1);
  int modelErrors = 0;  // lines "bad.adm:L:C: error: ..."
  for (size_t p = b.output.find("bad.adm:"); p != std::string::npos;
       p = b.output.find("bad.adm:", p + 1))
    modelErrors += b.output.compare(b.output.find(' ', p), 8, " error: ") == 0;
  EXPECT_EQ(modelErrors, 2) << b.output;  // MARKER/21 on PART/9; PART/2's CM not its marker
  // Lines 4 (no JOINT/7), 5 (no SFORCE/1), 7 (END before t = 1), 8 (bad expression), 11 (no
  // save file: the SAVE of line 9 names s.sav, which check mode does not write).
  for (const char* at : {"b.acf:4:", "b.acf:5:", "b.acf:7:", "b.acf:8:", "b.acf:11:"})
    EXPECT_EQ(count(b.output, at), 1) << at << "\n" << b.output;
  EXPECT_EQ(count(b.output, "b.acf:3:") + count(b.output, "b.acf:6:") +
                count(b.output, "b.acf:9:") + count(b.output, "b.acf:10:") +
                count(b.output, "b.acf:12:"),
            0)
      << b.output;
  EXPECT_NE(b.output.find("b.acf: " + std::to_string(modelErrors + 5) + " error(s)"),
            std::string::npos)
      << b.output;
  EXPECT_FALSE(fs::exists(dir / "s.sav"));
  EXPECT_FALSE(fs::exists(dir / "b.msg"));

  // A model that does not exist: one error at line 1 of the command file.
  write(dir / "n.acf", "nothere\nn\nSIMULATE/STATICS\nSTOP\n");
  const Result n = run("check n.acf", dir);
  EXPECT_EQ(n.status, 1);
  EXPECT_NE(n.output.find("n.acf:1:1: error: the data set"), std::string::npos) << n.output;
  EXPECT_NE(n.output.find("n.acf: 1 error(s)"), std::string::npos) << n.output;
}

// MREQUEST: refused at its line with what to write instead (docs/language.md, "MREQUEST").
TEST(CheckCommandFile, MrequestIsRefusedAtItsLine) {
  const fs::path dir = scratch("check-mrequest");
  std::string adm = kPendulum;
  adm.replace(adm.find("END\n"), 4, "MREQUEST/1, DISPLACEMENT, PART=2\nEND\n");
  write(dir / "m.adm", adm);
  const Result r = run("check m.adm", dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("m.adm:12:1: error: MREQUEST/1: MREQUEST is not supported"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("REQUEST/id, DISPLACEMENT"), std::string::npos) << r.output;
}

}  // namespace

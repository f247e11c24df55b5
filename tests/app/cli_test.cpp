// The command-line program as a user meets it: check (DOF, diagnostics), run (outputs,
// determinism, failures), eval and --help.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_run.hpp"
#include "support/integrator_test_models.hpp"
#include "support/validation_data.hpp"

namespace {

namespace fs = std::filesystem;

using namespace openmss::testing;  // scratch, run, slurp, write (tests/support)

const fs::path kJoints = adamsJointsDir();

TEST(Check, PrintsTheDegreesOfFreedomOfEachValidationModel) {
  const std::pair<const char*, int> expected[] = {
      {"Revolute_Case01", 1},  {"Revolute_Case02", 1},  {"Spherical_Case01", 3},
      {"Spherical_Case02", 3}, {"Universal_Case01", 2}, {"Universal_Case02", 2},
      {"Prismatic_Case01", 1}, {"Prismatic_Case02", 1}, {"Cylindrical_Case01", 2}};
  const fs::path dir = scratch("dof");
  for (const auto& [name, dof] : expected) {
    const Result r = run(
        "check '" + (kJoints / name / ("test_" + std::string(name) + ".adm")).string() + "'", dir);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("DOF " + std::to_string(dof) + "\n"), std::string::npos)
        << name << ":\n"
        << r.output;
  }
  fs::remove_all(dir);
}

TEST(Check, ReportsEveryErrorOfAMalformedModelWithItsLine) {
  // Three kinds of mistakes the issue names: an unknown marker id, a missing required
  // argument, a bad number; plus two more, all in one pass.
  const fs::path dir = scratch("malformed");
  write(dir / "bad.adm",
        "malformed model\n"
        "PART/1, GROUND\n"
        "MARKER/10, PART=1\n"
        "PART/2, MASS=1, CM=20, IP=1,1,1\n"
        "MARKER/20, PART=2, QP=1,0,0\n"
        "JOINT/1, REVOLUTE, I=20, J=99\n"    // line 6: marker 99 does not exist
        "JOINT/2, SPHERICAL, I=20\n"         // line 7: J missing
        "MARKER/21, PART=2, QP=1,0,0.5.3\n"  // line 8: not a number
        "SFORCE/3, I=20, J=10, TRANSLATION, FUNCTION=NOSUCH(1)\n"  // line 9: unknown function
        "PART/3, GROUND\n"                                         // line 10: a second ground
        "END\n");
  const Result r = run("check bad.adm", dir);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("bad.adm:6"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("JOINT/1"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("99"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bad.adm:7"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("JOINT/2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bad.adm:8"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bad.adm:9"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("NOSUCH"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bad.adm:10"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

TEST(Check, NamesAStatementTheSolverDoesNotSupportYet) {
  const fs::path dir = scratch("unsupported");
  write(dir / "u.adm",
        "unsupported\n"
        "PART/1, GROUND\n"
        "MARKER/10, PART=1\n"
        "PART/2, MASS=1, CM=20, IP=1,1,1\n"
        "MARKER/20, PART=2\n"
        "MFORCE/5, FLEX_BODY=1, JFLOAT=10\n"
        "END\n");
  const Result r = run("check u.adm", dir);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("u.adm:6"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("MFORCE/5: MFORCE is not supported yet"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

const char* kPendulum =
    "pendulum for the command-line tests\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=2, CM=20, IP=0.1,0.1,0.1\n"
    "MARKER/20, PART=2, QP=1,0,0\n"
    "MARKER/21, PART=2\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "ACCGRAV/ JGRAV=-9.81\n"
    "REQUEST/1, DISPLACEMENT, I=20, J=10\n"
    "REQUEST/2, F2=JOINT(1,0,2,0)\\F3=JOINT(1,0,3,0)\n"
    "OUTPUT/REQSAVE\n"
    "END\n";

TEST(Run, ADataSetWithDefaultsWritesRequestAndMessageFiles) {
  const fs::path dir = scratch("adm");
  write(dir / "pend.adm", kPendulum);
  const Result r = run("run pend.adm --end 0.5 --steps 10 --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "pend.msg"));
  const std::string req = slurp(dir / "pend.req");
  // 11 output times (0 .. 0.5) of 2 requests: 3 header lines, 4 directory lines, 11 * 3.
  EXPECT_EQ(std::count(req.begin(), req.end(), '\n'), 3 + 4 + 11 * 3) << req;
  fs::remove_all(dir);
}

TEST(Run, TheSameInputGivesBitIdenticalOutputs) {
  const fs::path a = scratch("det-a"), b = scratch("det-b");
  write(a / "pend.adm", kPendulum);
  write(b / "pend.adm", kPendulum);
  ASSERT_EQ(run("run pend.adm --end 1 --dtout 0.01 --quiet", a).status, 0);
  ASSERT_EQ(run("run pend.adm --end 1 --dtout 0.01 --quiet", b).status, 0);
  EXPECT_EQ(slurp(a / "pend.req"), slurp(b / "pend.req"));
  // The message files differ only in the path of the data set they echo.
  std::string ma = slurp(a / "pend.msg"), mb = slurp(b / "pend.msg");
  auto strip = [](std::string s, const fs::path& dir) {
    for (size_t at; (at = s.find(dir.string())) != std::string::npos;)
      s.erase(at, dir.string().size());
    return s;
  };
  EXPECT_EQ(strip(ma, a), strip(mb, b));
  fs::remove_all(a);
  fs::remove_all(b);
}

TEST(Run, AnAcfResolvesItsModelBesideItAndWritesToOutdir) {
  const fs::path dir = scratch("acf");
  fs::create_directories(dir / "model");
  write(dir / "model" / "pend.adm", kPendulum);
  write(dir / "model" / "pend.acf",
        "pend\nrun1\nintegrator/gstiff, error=1e-5\nsimulate/dynamics, end=0.2, steps=4\nstop\n");
  const Result r = run("run model/pend.acf --outdir out --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "run1.req"));
  EXPECT_TRUE(fs::exists(dir / "out" / "run1.msg"));
  fs::remove_all(dir);
}

TEST(Run, AnUnsupportedCommandStopsTheRunWithItsLine) {
  const fs::path dir = scratch("badcmd");
  write(dir / "pend.adm", kPendulum);
  write(dir / "pend.acf", "pend\npend\nautoscale\nstop\n");
  const Result r = run("run pend.acf --quiet", dir);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.output.find("pend.acf:3"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("AUTOSCALE is not supported yet"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

TEST(Run, AFailedDynamicRunNamesTheEquationAndKeepsEveryOutputStep) {
  // A force that grows without bound as t -> 0.55 s and has no value after it: the integrator
  // must give up there, say when and where, and leave the outputs of 0 .. 0.5 s complete.
  const fs::path dir = scratch("fail");
  std::string model = kPendulum;
  model.insert(model.find("OUTPUT/"),
               "SFORCE/7, I=20, J=10, TRANSLATION, FUNCTION=1/SQRT(0.55-TIME)\n");
  write(dir / "blow.adm", model);
  const Result r = run("run blow.adm --end 1 --dtout 0.1 --quiet", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  // The failure time is 0.55 to within HMIN = 1e-6 HMAX (GSTIFF's default, docs/integrators.md
  // "Defaults"): printed 5.500000E-01 or 5.49999xE-01.
  EXPECT_TRUE(r.output.find("the dynamic analysis failed at time 5.5") != std::string::npos ||
              r.output.find("the dynamic analysis failed at time 5.49999") != std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("PART/2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("SFORCE/7"), std::string::npos) << r.output;
  const std::string req = slurp(dir / "blow.req");
  // Header 3 + directory 4 lines, then t = 0, 0.1, ..., 0.5: six complete records of 3 lines.
  EXPECT_EQ(std::count(req.begin(), req.end(), '\n'), 3 + 4 + 6 * 3) << req;
  EXPECT_NE(req.find("   5.00000E-01\n"), std::string::npos) << req;
  const std::string msg = slurp(dir / "blow.msg");
  EXPECT_NE(msg.find("the dynamic analysis failed"), std::string::npos) << msg;
  fs::remove_all(dir);
}

// HHT with ALPHA = 0 is in ADAMS's range, but without numerical damping the Newmark rule on the
// index-3 equations is not stable (docs/integrators.md, "Without numerical damping"): the
// statement gets a warning at its column, and a failed run says so before the generic advice.
// The run fails on a force without a value after t = 0.55 s (as in
// AFailedDynamicRunNamesTheEquationAndKeepsEveryOutputStep; ERROR = 1e-2 so that the undamped
// method reaches it: at 1e-4 it crawls, its step shrinking, for minutes); the control, ADAMS's
// default ALPHA, fails there too, without the warning and without the sentence.
TEST(Run, HhtWithoutNumericalDampingIsWarnedAndItsFailureSaysWhy) {
  const fs::path dir = scratch("undamped");
  // The DAE test-set pendulum (tests/support) with a force on line 10 and INTEGRATOR on line 11.
  const auto pendulum = [](const std::string& integrator) {
    return openmss::test::beforeEnd(
        openmss::test::kPendulum,
        "SFORCE/7, I=20, J=10, TRANSLATION, FUNCTION=1/SQRT(0.55-TIME)\n" + integrator + "\n");
  };
  write(dir / "undamped.adm", pendulum("INTEGRATOR/HHT, ALPHA=0, ERROR=1e-2"));
  write(dir / "damped.adm", pendulum("INTEGRATOR/HHT, ERROR=1e-2"));
  const char* sentence = "no numerical damping (GAMMA = 0.5): choose ALPHA below 0";
  const Result bad = run("run undamped.adm --end 1 --dtout 0.1 --quiet", dir);
  EXPECT_EQ(bad.status, 2) << bad.output;
  EXPECT_NE(bad.output.find("undamped.adm:11:17: warning: INTEGRATOR: HHT without numerical "
                            "damping (ALPHA = 0)"),
            std::string::npos)
      << bad.output;
  EXPECT_NE(bad.output.find("the dynamic analysis failed at time 5.49999"), std::string::npos)
      << bad.output;
  EXPECT_NE(bad.output.find(sentence), std::string::npos) << bad.output;
  const Result good = run("run damped.adm --end 1 --dtout 0.1 --quiet", dir);
  EXPECT_EQ(good.status, 2) << good.output;
  EXPECT_NE(good.output.find("the dynamic analysis failed at time 5.49999"), std::string::npos)
      << good.output;
  EXPECT_EQ(good.output.find("numerical damping"), std::string::npos) << good.output;
  // NEWMARK's undamped pair (GAMMA = 0.5, BETA = 0.25) is the same method, warned at GAMMA.
  write(dir / "newmark.adm", pendulum("INTEGRATOR/NEWMARK, BETA=0.25, GAMMA=0.5"));
  const Result newmark = run("check newmark.adm", dir);
  EXPECT_EQ(newmark.status, 0) << newmark.output;
  EXPECT_NE(newmark.output.find("newmark.adm:11:32: warning: INTEGRATOR: NEWMARK without "
                                "numerical damping (GAMMA = 0.5)"),
            std::string::npos)
      << newmark.output;
  fs::remove_all(dir);
}

TEST(Eval, PrintsTheValueAndTheTimeDerivative) {
  const fs::path dir = scratch("eval");
  const Result r = run("eval 'STEP(TIME,0,0,1,1)' --time 0.5 --derivative", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("0.5\n"), std::string::npos) << r.output;        // midpoint of the cubic
  EXPECT_NE(r.output.find("d/dTIME 1.5"), std::string::npos) << r.output;  // 6 s (1-s) at 0.5
  fs::remove_all(dir);
}

TEST(Help, EveryCommandHasIt) {
  const fs::path dir = scratch("help");
  for (const char* c : {"--help", "run --help", "check --help", "eval --help"}) {
    const Result r = run(c, dir);
    EXPECT_EQ(r.status, 0) << c;
    EXPECT_NE(r.output.find("openmss"), std::string::npos) << c;
  }
  EXPECT_EQ(run("frobnicate", dir).status, 64);
  fs::remove_all(dir);
}

}  // namespace

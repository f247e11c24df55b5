// User equations end to end through the openmss program: DIFF, DIF1, VARVAL, ARYVAL, PINVAL and
// POUVAL in a request against the closed form y = exp(-2t), a 0-DOF model with a DIFF run as a
// dynamic analysis by SIMULATE/TRANSIENT, and SIMULATE/KINEMATICS refused for it.

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

const char* kDecay =
    "decay\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "DIFF/1, FUNCTION=-2*DIF(1), IC=1\n"
    "VARIABLE/1, FUNCTION=3*DIF(1)\n"
    "ARRAY/5, NUMBERS=3, 4\n"
    "PINPUT/1, VARIABLES=1\nPOUTPUT/2, VARIABLES=1\n"
    "REQUEST/1, F2=DIF(1), F3=DIF1(1), F4=VARVAL(1), F6=ARYVAL(5, 2), F7=PINVAL(1, 1),\n"
    ", F8=POUVAL(2, 1)\n"
    "OUTPUT/REQSAVE\nEND\n";

// ERROR = 1e-8: the integration error (about 1e-8) is far below the 6 printed digits, so the
// tolerance is the print's: 1e-5 relative plus 1e-9 for values near zero.
TEST(UserEquationsRun, RequestsReadTheUserStatesOfATransientRun) {
  const fs::path dir = scratch("decay");
  write(dir / "d.adm", kDecay);
  write(dir / "d.acf",
        "d\nd\nintegrator/gstiff, error=1e-8\nsimulate/transient, end=2, steps=8\nstop\n");
  const Result r = run("run d.acf --quiet", dir);
  ASSERT_EQ(r.status, 0) << r.output;
  std::string err;
  const auto req = openmss::output::readRequestFile((dir / "d.req").string(), &err);
  ASSERT_TRUE(req) << err;
  const auto steps = openmss::output::lastStepPerTime(req->steps);
  ASSERT_EQ(steps.size(), 9u);
  for (const auto& step : steps) {
    const double y = std::exp(-2.0 * step.time);
    const auto& row = step.rows[0];  // F2 F3 F4 F6 F7 F8
    auto near = [&](double got, double want, const char* what) {
      EXPECT_NEAR(got, want, 1e-5 * std::abs(want) + 1e-9) << what << " t=" << step.time;
    };
    near(row[0], y, "DIF");
    near(row[1], -2.0 * y, "DIF1");
    near(row[2], 3.0 * y, "VARVAL");
    near(row[3], 4.0, "ARYVAL");
    near(row[4], 3.0 * y, "PINVAL");
    near(row[5], 3.0 * y, "POUVAL");
  }
  const std::string msg = slurp(dir / "d.msg");
  EXPECT_NE(msg.find("User equations:       1 VARIABLE, 1 DIFF"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Dynamic Simulation"), std::string::npos) << msg;  // 0 DOF, one DIFF
  fs::remove_all(dir);
}

TEST(UserEquationsRun, KinematicsRefusesAModelWithDiffStates) {
  const fs::path dir = scratch("kin");
  write(dir / "d.adm", kDecay);
  write(dir / "d.acf", "d\nd\nsimulate/kinematics, end=1, steps=2\nstop\n");
  const Result r = run("run d.acf --quiet", dir);
  EXPECT_NE(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("a kinematic analysis does not integrate DIFF, LSE or TFSISO states"),
            std::string::npos)
      << r.output;
  fs::remove_all(dir);
}

}  // namespace

// The analysis variables MODE, HSIZE, ORDER, NJAC and NRHS end to end through the openmss
// program: MODE against the ADAMS codes (1 kinematics, 3 initial conditions, 4 dynamics,
// 5 statics, 6 quasi-statics)
// in requests and in a force that only acts in statics (checked against the closed-form
// equilibrium and oscillation), the integrator statistics against the numbers the .msg
// prints, and the refusals (CPU anywhere, the statistics outside requests).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;

using namespace openmss::testing;  // scratch, run, slurp, write (tests/support)

// A unit mass sliding on z, held by a spring k = 100 (free length 10 from marker 12 at z = -10)
// and pushed by 20 only while MODE = 5 (statics): static equilibrium z = 20/k = 0.2, then a
// free oscillation z = 0.2 cos(10 t) once the force is gone in dynamics.
const char* kSlider =
    "mode slider\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "MARKER/12, PART=1, QP=0,0,-10\n"
    "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
    "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
    "SFORCE/1, TRANSLATION, I=20, J=12, FUNCTION=-100*(DM(20,12)-10) + IF(MODE-5: 0, 20, 0)\n"
    "REQUEST/1, F2=MODE, F3=DZ(20,10), F4=HSIZE, F6=ORDER, F7=NJAC, F8=NRHS\n"
    "OUTPUT/REQSAVE\nEND\n";

openmss::output::RequestFileData runAndRead(const fs::path& dir, const std::string& acf) {
  write(dir / "s.adm", kSlider);
  write(dir / "s.acf", acf);
  const Result r = run("run s.acf --quiet", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  std::string err;
  const auto req = openmss::output::readRequestFile((dir / "s.req").string(), &err);
  EXPECT_TRUE(req) << err;
  return req ? *req : openmss::output::RequestFileData{};
}

TEST(AnalysisVariables, ModeSwitchesAStaticsOnlyForceAndReadsBackPerAnalysis) {
  const fs::path dir = scratch("mode");
  const auto req = runAndRead(
      dir, "s\ns\nsimulate/statics\nintegrator/gstiff, error=1e-8, hmax=1e-3\n"
           "simulate/transient, end=0.5, steps=5\nstop\n");
  ASSERT_GE(req.steps.size(), 6u);
  // First record: the static equilibrium, MODE = 5 and z = 20/100.
  EXPECT_EQ(req.steps.front().rows[0][0], 5.0);
  EXPECT_NEAR(req.steps.front().rows[0][1], 0.2, 1e-6);
  // Dynamics: MODE = 4 and the force is gone, z = 0.2 cos(10 t) (ERROR=1e-8; the .req prints
  // 6 significant digits, so 2e-6 of the 0.2 amplitude plus the integration error).
  int dynamic = 0;
  for (const auto& step : req.steps) {
    if (step.time <= 0.0) continue;
    ++dynamic;
    EXPECT_EQ(step.rows[0][0], 4.0) << step.time;
    EXPECT_NEAR(step.rows[0][1], 0.2 * std::cos(10.0 * step.time), 2e-5) << step.time;
  }
  EXPECT_EQ(dynamic, 5);
  fs::remove_all(dir);
}

TEST(AnalysisVariables, InitialConditionsIsMode3) {
  const fs::path dir = scratch("ic");
  const auto req = runAndRead(dir, "s\ns\nsimulate/initial_conditions\nstop\n");
  ASSERT_EQ(req.steps.size(), 1u);
  EXPECT_EQ(req.steps[0].rows[0][0], 3.0);
  EXPECT_EQ(req.steps[0].rows[0][1], 0.0);  // the statics-only force does not act
  fs::remove_all(dir);
}

TEST(AnalysisVariables, QuasiStaticsIsMode6AndKinematicsMode1) {
  const fs::path dir = scratch("quasi");
  const auto req = runAndRead(dir, "s\ns\nsimulate/statics, end=1, steps=2\nstop\n");
  ASSERT_EQ(req.steps.size(), 3u);
  // The t = 0 record is the quasi-static analysis' first equilibrium.
  for (const auto& step : req.steps) EXPECT_EQ(step.rows[0][0], 6.0) << step.time;
  fs::remove_all(dir);

  const fs::path kin = scratch("kin");
  write(kin / "k.adm",
        "driven slider\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
        "JOINT/1, TRANSLATIONAL, I=20, J=10\nMOTION/1, JOINT=1, TRANSLATION, FUNCTION=TIME\n"
        "REQUEST/1, F2=MODE, F3=DZ(20,10), F4=HSIZE\nOUTPUT/REQSAVE\nEND\n");
  write(kin / "k.acf", "k\nk\nsimulate/kinematics, end=1, steps=4\nstop\n");
  const Result r = run("run k.acf --quiet", kin);
  ASSERT_EQ(r.status, 0) << r.output;
  std::string err;
  const auto kreq = openmss::output::readRequestFile((kin / "k.req").string(), &err);
  ASSERT_TRUE(kreq) << err;
  ASSERT_EQ(kreq->steps.size(), 5u);
  for (const auto& step : kreq->steps) {
    EXPECT_EQ(step.rows[0][0], 1.0) << step.time;
    EXPECT_NEAR(step.rows[0][1], step.time, 1e-6) << step.time;
    EXPECT_EQ(step.rows[0][2], 0.0) << step.time;  // no integrator in kinematics
  }
  fs::remove_all(kin);
}

TEST(AnalysisVariables, IntegratorStatisticsEqualTheNumbersTheMsgPrints) {
  const fs::path dir = scratch("stats");
  const auto req = runAndRead(
      dir, "s\ns\nintegrator/gstiff, error=1e-6\nsimulate/transient, end=1, steps=10\nstop\n");
  const std::string msg = slurp(dir / "s.msg");
  // The .msg prints one line per output step (10 outputs): time, step size, residual
  // evaluations, steps, order; and the run's totals at the end.
  int matched = 0;
  std::istringstream lines(msg);
  std::string line;
  long lastJac = -1;
  while (std::getline(lines, line)) {
    double t = 0, h = 0;
    long nrhs = 0, steps = 0;
    int order = 0;
    if (std::sscanf(line.c_str(), " %lf %lf %ld %ld %d", &t, &h, &nrhs, &steps, &order) == 5) {
      for (const auto& step : req.steps) {
        if (std::abs(step.time - t) > 1e-9 || t <= 0.0) continue;
        const auto& row = step.rows[0];  // MODE DZ HSIZE ORDER NJAC NRHS
        // Both print 6 significant digits of the same double.
        EXPECT_NEAR(row[2], h, 1e-5 * h) << t;
        EXPECT_EQ(row[3], order) << t;
        EXPECT_EQ(row[5], static_cast<double>(nrhs)) << t;
        if (std::abs(t - 1.0) < 1e-12) lastJac = static_cast<long>(row[4]);
        ++matched;
      }
    }
  }
  EXPECT_EQ(matched, 10) << msg;
  const auto at = msg.find(" Jacobian evaluations");
  ASSERT_NE(at, std::string::npos) << msg;
  const auto from = msg.rfind(", ", at);
  EXPECT_EQ(std::stol(msg.substr(from + 2, at - from - 2)), lastJac) << msg;
  fs::remove_all(dir);
}

TEST(AnalysisVariables, CpuAndStatisticsOutsideRequestsAreRefused) {
  const fs::path dir = scratch("refuse");
  write(dir / "r.adm",
        "refusals\nUNITS/ SYSTEM=NONE\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "PART/2, MASS=1, CM=20, IP=1,1,1\nMARKER/20, PART=2\n"
        "JOINT/1, TRANSLATIONAL, I=20, J=10\n"
        "SFORCE/1, TRANSLATION, I=20, J=10, FUNCTION=HSIZE\n"
        "REQUEST/1, F2=CPU\nEND\n");
  const Result r = run("check r.adm", dir);
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("r.adm:8:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("SFORCE/1: HSIZE: the integrator statistics HSIZE, ORDER, NJAC and "
                          "NRHS are supported in REQUEST functions only"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("r.adm:9:"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("REQUEST/1: CPU: CPU time is not available"), std::string::npos)
      << r.output;
  fs::remove_all(dir);
}

}  // namespace

// INFO, SHOW, TIME and the environment commands (docs/commands.md): INFO against the data
// set's geometry, SHOW/TIME against the run's counters, one named warning per option of
// PREFERENCES, LSOLVER and ENVIRONMENT however often it is given.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss;
using namespace openmss::testing;  // scratch, slurp, write (tests/support)

struct SessionRun {
  std::unique_ptr<commands::Session> session;
  std::vector<bool> results;
  std::string msg;
};

SessionRun runCommands(const std::string& name, const std::vector<std::string>& lines) {
  SessionRun r;
  const fs::path dir = scratch(name);
  // A body fixed at (3, 4, 0) with its CM marker rotated 90 degrees about z (psi = pi/2).
  write(dir / "m.adm",
        "info\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1\n"
        "MARKER/11, PART=1, QP=3,4,0, REULER=90D,0,0\n"
        "PART/2, MASS=1, IP=1,1,1, CM=20\nMARKER/20, PART=2, QP=3,4,0, REULER=90D,0,0\n"
        "JOINT/1, FIXED, I=20, J=11\nEND\n");
  commands::SessionOptions options;
  options.outputDirectory = dir.string();
  options.echoDiagnostics = false;
  options.printInformation = false;
  r.session = std::make_unique<commands::Session>(options);
  if (!r.session->loadModel((dir / "m.adm").string(), "m")) return r;
  language::CommandReader reader("m.acf", 3);
  for (const auto& l : lines) reader.feedLine(l);
  reader.finish();
  for (const auto& c : reader.takeCommands()) r.results.push_back(r.session->execute(c));
  r.msg = slurp(dir / "m.msg");
  return r;
}

TEST(InfoCommands, InfoDisplacementListsThePoseOfIRelativeToJ) {
  const SessionRun r = runCommands("info", {"SIMULATE/STATICS", "INFO/DISPLACEMENT, I=20, J=10"});
  ASSERT_EQ(r.results.size(), 2u);
  EXPECT_TRUE(r.results[0] && r.results[1]);
  // x, y, z = 3, 4, 0 and psi, theta, phi = pi/2, 0, 0 (3-1-3, theta = 0: psi takes it all).
  EXPECT_NE(r.msg.find("   x, y, z:      3.000000e+00  4.000000e+00  0.000000e+00"),
            std::string::npos)
      << r.msg;
  EXPECT_NE(r.msg.find("1.570796e+00  0.000000e+00  0.000000e+00"), std::string::npos) << r.msg;
  // A missing marker: one located error.
  const SessionRun bad = runCommands("info-bad", {"INFO/VELOCITY, I=99"});
  ASSERT_EQ(bad.results.size(), 1u);
  EXPECT_FALSE(bad.results[0]);
  EXPECT_EQ(bad.session->diagnostics().errorCount(), 1);
}

TEST(InfoCommands, TimeReportsTheRunDeterministically) {
  const SessionRun a =
      runCommands("time-a", {"SIMULATE/DYNAMICS, END=0.5, STEPS=5", "TIME", "SHOW/STATUS"});
  const SessionRun b =
      runCommands("time-b", {"SIMULATE/DYNAMICS, END=0.5, STEPS=5", "TIME", "SHOW/STATUS"});
  ASSERT_EQ(a.results.size(), 3u);
  for (bool ok : a.results) EXPECT_TRUE(ok);
  EXPECT_NE(a.msg.find(" Simulation time 0.5, last analysis"), std::string::npos) << a.msg;
  EXPECT_NE(a.msg.find(" Degrees of freedom 0"), std::string::npos) << a.msg;
  EXPECT_EQ(a.msg.find("CPU time"), std::string::npos);  // stdout only
  // Identical after the model's path (each run has its own scratch folder).
  const auto from = [](const std::string& m) { return m.substr(m.find(" Model title")); };
  EXPECT_EQ(from(a.msg), from(b.msg));
}

TEST(InfoCommands, EnvironmentOptionsWarnOnceEachByName) {
  const SessionRun r = runCommands(
      "prefs", {"PREFERENCES/ NTHREADS=4", "PREFERENCES/ NTHREADS=8, LIST", "LSOLVER/ CALAHAN",
                "ENVIRONMENT/NAME=MDI_ADAMS_CONTACT_OUT, VALUE=off",
                "ENVIRONMENT/NAME=MDI_ADAMS_CONTACT_OUT, VALUE=on", "PREFERENCES/ SIMFAIL=STOPCF"});
  ASSERT_EQ(r.results.size(), 6u);
  for (bool ok : r.results) EXPECT_TRUE(ok);
  const auto& d = r.session->diagnostics();
  EXPECT_EQ(d.errorCount(), 0);
  ASSERT_EQ(d.warningCount(), 3);  // NTHREADS, LSOLVER/CALAHAN, the environment variable
  EXPECT_NE(d.all()[0].message.find("PREFERENCES/NTHREADS"), std::string::npos);
  EXPECT_NE(d.all()[1].message.find("LSOLVER/CALAHAN"), std::string::npos);
  EXPECT_NE(d.all()[2].message.find("MDI_ADAMS_CONTACT_OUT"), std::string::npos);
  EXPECT_EQ(d.all()[2].where.line, 6);
}

}  // namespace

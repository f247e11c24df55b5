// The run command's options and the summary it prints: --version, --end/--dtout passed on at
// full precision, unknown options refused, and the summary naming only output files that
// exist.

#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::testing;  // scratch, run, slurp, write (tests/support)

// A pendulum on a revolute joint: one moving part, no requests unless added.
const char* const kPendulum =
    "pendulum\n"
    "PART/1, GROUND\n"
    "MARKER/10, PART=1\n"
    "PART/2, MASS=1, CM=20, IP=0.1,0.1,0.1\n"
    "MARKER/20, PART=2, QP=1,0,0\n"
    "MARKER/21, PART=2, QP=0,0,0\n"
    "JOINT/1, REVOLUTE, I=21, J=10\n"
    "ACCGRAV/JGRAV=-9.80665\n";

TEST(Options, VersionPrintsTheProjectVersion) {
  // The version CMakeLists.txt declares: project(OpenMSS VERSION x.y.z ...).
  const std::string cmake = slurp(fs::path(OPENMSS_SOURCE_DIR) / "CMakeLists.txt");
  std::smatch match;
  ASSERT_TRUE(std::regex_search(cmake, match, std::regex(R"(project\(OpenMSS VERSION ([0-9.]+))")));
  const fs::path dir = scratch("version");
  const Result r = run("--version", dir);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output, "openmss " + match[1].str() + "\n");
  fs::remove_all(dir);
}

TEST(Options, EndAndDtoutKeepTheirFullPrecision) {
  // std::to_string printed --end 1e-7 as END=0.000000: the run ended before it began.
  const fs::path dir = scratch("end");
  write(dir / "pend.adm", std::string(kPendulum) + "END\n");
  const Result r = run("run pend.adm --end 1e-7 --dtout 2.5e-8", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  const std::string msg = slurp(dir / "pend.msg");
  EXPECT_NE(msg.find("SIMULATE/TRANSIENT, END=1e-07, DTOUT=2.5e-08"), std::string::npos) << msg;
  EXPECT_NE(r.output.find("reached t = 1e-07"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

TEST(Options, AnUnknownOptionIsRefused) {
  // --summary used to be accepted and ignored (the summary is printed unless --quiet).
  const fs::path dir = scratch("unknown");
  write(dir / "pend.adm", std::string(kPendulum) + "END\n");
  for (const char* option : {"--summary", "--nosuch"}) {
    const Result r = run(std::string("run pend.adm ") + option, dir);
    EXPECT_EQ(r.status, 64) << option;
    EXPECT_NE(r.output.find(std::string("openmss run: unknown option ") + option),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "pend.msg")) << option;
  }
  fs::remove_all(dir);
}

TEST(Summary, AFailedRunNamesOnlyTheOutputFilesThatExist) {
  // A model without OUTPUT/REQSAVE whose force has no value from t = 0: the run fails and
  // writes no request file, so neither the diagnostic nor the summary may send the user to
  // one.
  const fs::path dir = scratch("failed-summary");
  write(dir / "bad.adm", std::string(kPendulum) +
                             "SFORCE/7, I=20, J=10, TRANSLATION, FUNCTION=1/SQRT(-1-TIME)\n"
                             "END\n");
  const Result r = run("run bad.adm --end 0.1", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  ASSERT_FALSE(fs::exists(dir / "bad.req"));
  EXPECT_TRUE(fs::exists(dir / "bad.msg"));
  EXPECT_NE(r.output.find("the dynamic analysis failed"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("  outputs:  ./bad.msg\n"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("bad.req"), std::string::npos) << r.output;
  EXPECT_EQ(slurp(dir / "bad.msg").find("bad.req"), std::string::npos);
  fs::remove_all(dir);
}

TEST(Summary, AFailedRunWithARequestFileNamesIt) {
  // With OUTPUT/REQSAVE the t = 0 output is written before the failure: the file is named.
  const fs::path dir = scratch("failed-summary-req");
  write(dir / "bad.adm", std::string(kPendulum) +
                             "SFORCE/7, I=20, J=10, TRANSLATION, FUNCTION=1/SQRT(-1-TIME)\n"
                             "OUTPUT/REQSAVE\nEND\n");
  const Result r = run("run bad.adm --end 0.1", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  ASSERT_TRUE(fs::exists(dir / "bad.req"));
  EXPECT_NE(r.output.find("Outputs up to the last successful output step are in bad.req"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("  outputs:  ./bad.msg, ./bad.req\n"), std::string::npos) << r.output;
  fs::remove_all(dir);
}

}  // namespace

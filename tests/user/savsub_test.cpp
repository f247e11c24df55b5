// SAVSUB and RELSUB (docs/user-subroutines.md, "SAVSUB and RELSUB"): a user library that keeps
// its own counter (how many output steps its REQSUB has been evaluated at) saves it with
// SAVE/STATES and restores it with RELOAD/STATES, so that a study saved at t = 1, taken on a
// detour to t = 1.6 and reloaded continues to t = 2 exactly as the study that never stopped.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"
#include "user/user_library.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss;
using namespace openmss::testing;  // scratch, write (tests/support)

// A body falling freely under gravity (a state the save file carries) and REQUEST/1 of the
// library's REQSUB (F2, the .req's first column: its counter; F3: the time).
const char* kFall =
    "fall\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "PART/2, MASS=1, IP=1,1,1, CM=20\nMARKER/20, PART=2\nACCGRAV/ JGRAV=-9.81\n"
    "REQUEST/1, FUNCTION=USER(0)\nREQUEST/2, DISPLACEMENT, I=20, J=10\nOUTPUT/ REQSAVE\nEND\n";

std::vector<output::RequestFileStep> study(const std::string& name,
                                           const std::vector<std::string>& acf,
                                           const std::string& library = OPENMSS_TEST_SAVSUB) {
  const fs::path dir = scratch(name);
  write(dir / "m.adm", kFall);
  user::setDefaultLibrary(library);  // `openmss run --user-library LIB`
  commands::SessionOptions options;
  options.outputDirectory = dir.string();
  options.echoDiagnostics = false;
  options.printInformation = false;
  {
    commands::Session session(options);
    EXPECT_TRUE(session.loadModel((dir / "m.adm").string(), "m"));
    language::CommandReader reader("m.acf", 3);
    for (const auto& c : acf) reader.feedLine(c);
    reader.finish();
    for (const auto& c : reader.takeCommands()) EXPECT_TRUE(session.execute(c)) << c.subject();
  }
  user::setDefaultLibrary("");
  std::string why;
  const auto req = output::readRequestFile((dir / "m.req").string(), &why);
  EXPECT_TRUE(req.has_value()) << why;
  return req ? req->steps : std::vector<output::RequestFileStep>{};
}

// Returns the counter's rows after RELOAD relative to its first row (5 values).
std::vector<double> expectContinues(const std::string& library, const std::string& tag) {
  // Uninterrupted: 0, 0.2, ..., 2 (the library's counter is a process global: the first study
  // starts it from wherever the process left it, so each study is compared in differences).
  const auto plain = study("savsub-plain" + tag, {"SIMULATE/DYNAMICS, END=1, STEPS=5",
                                                  "SIMULATE/DYNAMICS, END=2, STEPS=5", "STOP"},
                           library);
  const auto reloaded = study(
      "savsub-reload" + tag,
      {"SIMULATE/DYNAMICS, END=1, STEPS=5", "SAVE/STATES, FILE=s.sav",
       "SIMULATE/DYNAMICS, END=1.6, STEPS=3", "RELOAD/STATES, FILE=s.sav",
       "SIMULATE/DYNAMICS, END=2, STEPS=5", "STOP"},
      library);
  std::vector<double> counts;
  if (plain.size() != 11u || reloaded.size() != 14u) {
    ADD_FAILURE() << plain.size() << " " << reloaded.size();
    return counts;
  }
  // The counter counts from its value at the first row of each study.
  const double plainStart = plain[0].rows[0][0], reloadedStart = reloaded[0].rows[0][0];
  int compared = 0;
  for (std::size_t k = 0; k < 5; ++k) {  // the rows after RELOAD, t = 1.2 .. 2
    const auto& a = reloaded[9 + k];
    const auto& b = plain[6 + k];
    EXPECT_EQ(a.time, b.time);
    // Bit-identical: the states are restored exactly (docs/save-format.md) and the counter by
    // RELSUB; without RELSUB it would be 3 ahead (the detour's three output steps).
    EXPECT_EQ(a.rows[0][0] - reloadedStart, b.rows[0][0] - plainStart) << k;
    counts.push_back(a.rows[0][0] - reloadedStart);
    for (int c = 0; c < 6; ++c, ++compared) EXPECT_EQ(a.rows[1][c], b.rows[1][c]) << k << c;
  }
  EXPECT_EQ(compared, 30);
  // The detour counted on: its rows continue the counter past the saved value.
  EXPECT_EQ(reloaded[8].rows[0][0] - reloadedStart, 8.0);
  EXPECT_EQ(reloaded[9].rows[0][0] - reloadedStart, 6.0);
  return counts;
}

TEST(SavsubRelsub, UserDataContinuesAfterReloadAsIfNeverStopped) {
  const std::vector<double> c = expectContinues(OPENMSS_TEST_SAVSUB, "");
  EXPECT_EQ(c.size(), 5u);
}

// The FORTRAN library (savsub_routines.f): SAVSUB writes an unformatted record to the unit
// OpenMSS connected, RELSUB reads it back; the same counts as the C library's.
TEST(SavsubRelsub, FortranSavsubAndRelsubMatchTheCRoutines) {
  const std::vector<double> c = expectContinues(OPENMSS_TEST_SAVSUB, "-c");
  const std::vector<double> f = expectContinues(OPENMSS_TEST_SAVSUB_F77, "-f77");
  ASSERT_EQ(c.size(), 5u);
  EXPECT_EQ(f, c);
}

}  // namespace

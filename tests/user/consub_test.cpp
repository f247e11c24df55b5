// CONTROL with a user CONSUB (docs/user-subroutines.md, "CONSUB"): a C library drives the
// study "simulate to 1, change SFORCE/1, simulate to 2" through ANALYS, MODIFY and DATOUT, and
// its request file must hold the same numbers, bit for bit, as the same study written as an
// .acf, and agree with the closed form; CONSUBs that give up (ERRMES STOP), ask for a NaN end
// time or crash end the CONTROL command with one located error, and the run goes on.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "output/request_file_reader.hpp"
#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss;
using namespace openmss::testing;  // scratch, write (tests/support)

const std::string kLibrary = OPENMSS_TEST_CONSUB;

// A unit mass, no gravity, at rest at the origin, pushed by SFORCE/1 (action-only: along z of
// its J marker, ground z) of FUNCTION=1; REQUEST/1 reports its displacement.
const char* kSlider =
    "slider\nUNITS/ SYSTEM=MKS\nPART/1, GROUND\nMARKER/10, PART=1\n"
    "PART/2, MASS=1, IP=1,1,1, CM=20\nMARKER/20, PART=2\n"
    "SFORCE/1, TRANSLATION, ACTIONONLY, I=20, J=10, FUNCTION=1\n"
    "REQUEST/1, DISPLACEMENT, I=20, J=10\nOUTPUT/ REQSAVE\n"
    // Tight: at the default ERROR=1e-3 the first steps (order 1) leave 1.5e-4 in z(1).
    "INTEGRATOR/ GSTIFF, ERROR=1e-9\nEND\n";

struct Outcome {
  std::vector<bool> results;
  std::vector<std::string> errors;
  output::RequestFileData req;
  double z = 0.0;  // the slider's final z
};

Outcome study(const std::string& name, const std::vector<std::string>& acf) {
  Outcome o;
  const fs::path dir = scratch(name);
  write(dir / "m.adm", kSlider);
  commands::SessionOptions options;
  options.outputDirectory = dir.string();
  options.echoDiagnostics = false;
  options.printInformation = false;
  // The session's scope: its end closes the files.
  {
    commands::Session session(options);
    EXPECT_TRUE(session.loadModel((dir / "m.adm").string(), "m"));
    language::CommandReader reader("m.acf", 3);
    for (const auto& c : acf) reader.feedLine(c);
    reader.finish();
    EXPECT_FALSE(reader.takeDiagnostics().hasErrors());
    for (const auto& c : reader.takeCommands()) o.results.push_back(session.execute(c));
    for (const auto& d : session.diagnostics().all())
      if (d.severity == Severity::Error) o.errors.push_back(format(d));
    o.z = session.state()->y(session.system()->layout().body(0) + 2);
  }
  if (!fs::exists(dir / "m.req")) return o;  // no output step was written
  std::string why;
  auto req = output::readRequestFile((dir / "m.req").string(), &why);
  EXPECT_TRUE(req.has_value()) << why;
  if (req) o.req = *req;
  return o;
}

std::string control(const std::string& routine, const std::string& par,
                    const std::string& library = kLibrary) {
  return "CONTROL/ROUTINE=\"" + library + "::" + routine + "\", FUNCTION=USER(" + par + ")";
}

TEST(Consub, DrivesTheStudyAsTheCommandFileDoes) {
  const Outcome byConsub = study("consub", {control("Consub", "1, 2, 2"), "STOP"});
  const Outcome byAcf =
      study("consub-acf", {"SIMULATE/DYNAMICS, END=1, STEPS=1", "SFORCE/1, FUNCTION=2",
                           "SIMULATE/DYNAMICS, END=2, STEPS=1", "STOP"});
  ASSERT_EQ(byConsub.results, std::vector<bool>({true, true})) << byConsub.errors.size();
  ASSERT_EQ(byAcf.results, std::vector<bool>({true, true, true, true}));
  // The .acf writes the initial conditions at t = 0, and again at t = 1 after the SFORCE
  // command reprocessed the model; CONSUB's output is what DATOUT writes, after each ANALYS:
  // t = 1 and t = 2, to compare with the .acf's steps 1 (the end of its first SIMULATE) and 3.
  ASSERT_EQ(byConsub.req.steps.size(), 2u);
  ASSERT_EQ(byAcf.req.steps.size(), 4u);
  int compared = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& a = byConsub.req.steps[k];
    const auto& b = byAcf.req.steps[2 * k + 1];
    EXPECT_EQ(a.time, b.time);
    ASSERT_EQ(a.rows.size(), b.rows.size());
    // Bit-identical: ANALYS runs the same SIMULATE (END, STEPS=1) from the same state, so the
    // integrator takes the same steps; DATOUT writes the state the analysis ended on, which
    // is the .acf's output step at END.
    for (std::size_t r = 0; r < a.rows.size(); ++r)
      for (int c = 0; c < 6; ++c, ++compared) EXPECT_EQ(a.rows[r][c], b.rows[r][c]) << k << r << c;
  }
  EXPECT_EQ(compared, 12);
  // Closed form: z(1) = 1/2 (unit force), z(2) = 1/2 + 1 + 1 (force 2 from velocity 1). The
  // integrator reproduces a quadratic to its error tolerance (default ERROR 1e-3; measured
  // far below): 1e-6.
  EXPECT_NEAR(byConsub.req.steps[0].rows[0][2], 0.5, 1e-6);
  EXPECT_NEAR(byConsub.req.steps[1].rows[0][2], 2.5, 1e-6);
  EXPECT_EQ(byConsub.req.steps[0].time, 1.0);
  EXPECT_EQ(byConsub.req.steps[1].time, 2.0);
}

// The FORTRAN CONSUB (consub_routines.f, found as consub_ under the default name) runs the
// same study through analys_, datout_ and modify_ (its command written with ES25.17, which
// reads back as the same force 2): its output steps are the C CONSUB's, bit for bit.
TEST(Consub, FortranConsubMatchesTheCRoutine) {
  const Outcome c = study("consub-c", {control("Consub", "1, 2, 2"), "STOP"});
  const Outcome f = study("consub-f77", {control("", "1, 2, 2", OPENMSS_TEST_CONSUB_F77), "STOP"});
  ASSERT_EQ(f.results, std::vector<bool>({true, true})) << (f.errors.empty() ? "" : f.errors[0]);
  ASSERT_EQ(c.req.steps.size(), 2u);
  ASSERT_EQ(f.req.steps.size(), 2u);
  int compared = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(c.req.steps[k].time, f.req.steps[k].time);
    ASSERT_EQ(c.req.steps[k].rows.size(), f.req.steps[k].rows.size());
    for (std::size_t r = 0; r < c.req.steps[k].rows.size(); ++r)
      for (int col = 0; col < 6; ++col, ++compared)
        EXPECT_EQ(c.req.steps[k].rows[r][col], f.req.steps[k].rows[r][col]) << k << r << col;
  }
  EXPECT_EQ(compared, 12);
  EXPECT_EQ(c.z, f.z);
}

// A CONSUB that gives up: the CONTROL command fails with its message, at its line; the MODIFY
// it tries afterwards does nothing, so the following SIMULATE runs with the data set's force.
TEST(Consub, ErrmesStopEndsTheControlSequence) {
  const Outcome o = study("consub-errmes", {control("Consub_errmes", "0"),
                                            "SIMULATE/DYNAMICS, END=1, STEPS=1", "STOP"});
  ASSERT_EQ(o.results, std::vector<bool>({false, true, true}));
  ASSERT_EQ(o.errors.size(), 1u);
  EXPECT_NE(o.errors[0].find("m.acf:3:1: error: CONTROL"), std::string::npos) << o.errors[0];
  EXPECT_NE(o.errors[0].find("the user's routine gives up"), std::string::npos) << o.errors[0];
  EXPECT_NEAR(o.z, 0.5, 1e-6);  // force 1, not 5 or 6
}

TEST(Consub, NanEndTimeAndCrashAreContained) {
  const Outcome nan = study(
      "consub-nan", {control("Consub_nan", "0"), "SIMULATE/DYNAMICS, END=1, STEPS=1", "STOP"});
  ASSERT_EQ(nan.results, std::vector<bool>({false, true, true}));
  ASSERT_EQ(nan.errors.size(), 2u);  // ANALYS refused, then the routine's ERRMES STOP
  EXPECT_NE(nan.errors[0].find("TIMBEG must be the current time and TIMEND after it"),
            std::string::npos)
      << nan.errors[0];
  EXPECT_NEAR(nan.z, 0.5, 1e-6);

  const Outcome crash = study(
      "consub-crash", {control("Consub_crash", "0"), "SIMULATE/DYNAMICS, END=1, STEPS=1", "STOP"});
  ASSERT_EQ(crash.results, std::vector<bool>({false, true, true}));
  ASSERT_EQ(crash.errors.size(), 1u);
  EXPECT_NE(crash.errors[0].find("crashed"), std::string::npos) << crash.errors[0];
  EXPECT_NEAR(crash.z, 0.5, 1e-6);
}

// Outside CONSUB the utilities still refuse (istat = 1): covered by
// utility_subroutines_test.cpp. A library without CONSUB: one located error.
TEST(Consub, MissingRoutineIsOneLocatedError) {
  const Outcome o = study("consub-missing", {control("Nothere", "0"), "STOP"});
  ASSERT_EQ(o.results, std::vector<bool>({false, true}));
  ASSERT_EQ(o.errors.size(), 1u);
  EXPECT_NE(o.errors[0].find("exports no CONSUB routine"), std::string::npos) << o.errors[0];
}

}  // namespace

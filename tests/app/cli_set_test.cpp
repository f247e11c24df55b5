// `openmss run … --set STATEMENT/id.ARGUMENT=value`: an override gives the same request file,
// byte for byte, as the data set edited by hand (the independent truth: the reader and the
// solver on the edited text), for a number, an abbreviated statement name, a function
// expression and a statement without id; a bad override is an input error (exit 1) located
// at --set:N:COL, and nothing is simulated.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/cli_run.hpp"

namespace {

namespace fs = std::filesystem;
using namespace openmss::testing;  // scratch, run, slurp, write (tests/support)

// A mass sliding along global X on a spring-damper, pulled by an SFORCE whose function reads
// VARIABLE/7, with gravity along the slide.
std::string deck(const std::string& k, const std::string& variable, const std::string& gravity) {
  std::string text =
      "oscillator\n"
      "PART/1, GROUND\n"
      "MARKER/10, PART=1, REULER=90D,90D,0\n"
      "PART/2, MASS=2, CM=20, IP=0.1,0.1,0.1\n"
      "MARKER/20, PART=2, QP=1,0,0, REULER=90D,90D,0\n"
      "JOINT/1, TRANSLATIONAL, I=20, J=10\n";
  text += "SPRINGDAMPER/3, TRANSLATIONAL, I=20, J=10, K=" + k + ", C=0.5, LENGTH=0.8\n";
  text += "VARIABLE/7, FUNCTION=" + variable + "\n";
  text += "SFORCE/4, TRANSLATION, I=20, J=10, FUNCTION=VARVAL(7)\n";
  if (!gravity.empty()) text += "ACCGRAV/IGRAV=" + gravity + "\n";  // "": no gravity
  text +=
      "REQUEST/1, DISPLACEMENT, I=20, J=10\n"
      "OUTPUT/REQSAVE\n"
      "END\n";
  return text;
}

const std::string kVariable = "3*SIN(2*TIME)";

// Runs base.adm with `options` in its own folder and returns the request file.
std::string requestsOf(const fs::path& dir, const std::string& adm, const std::string& options) {
  fs::create_directories(dir);
  write(dir / "m.adm", adm);
  const Result r = run("run m.adm --end 1 --steps 50 --quiet " + options, dir);
  EXPECT_EQ(r.status, 0) << options << "\n" << r.output;
  EXPECT_TRUE(fs::exists(dir / "m.req")) << options;
  return slurp(dir / "m.req");
}

TEST(SetOption, OverridesGiveTheRequestFileOfTheEditedDataSet) {
  const fs::path dir = scratch("set-same");
  const std::string base = deck("100", kVariable, "-9.80665");
  const std::string unchanged = requestsOf(dir / "base", base, "");
  struct Case {
    std::string options, edited;
  };
  const Case cases[] = {
      {"--set SPRINGDAMPER/3.K=250", deck("250", kVariable, "-9.80665")},
      // An abbreviated statement name and an exponent, read as the data-set reader reads them.
      {"--set SPRINGD/3.K=2.5E2", deck("250", kVariable, "-9.80665")},
      // A function expression as a whole, with D-degrees inside.
      {"--set 'VARIABLE/7.FUNCTION=5*COS(90D*TIME)'", deck("100", "5*COS(90D*TIME)", "-9.80665")},
      // A statement without id, and two overrides at once.
      {"--set ACCGRAV.IGRAV=-3 --set SPRINGDAMPER/3.K=40", deck("40", kVariable, "-3")},
  };
  // A data set without gravity: the override of the singleton ACCGRAV adds it.
  const std::string weightless = deck("100", kVariable, "");
  const std::string added = requestsOf(dir / "added", weightless, "--set ACCGRAV.IGRAV=-3");
  EXPECT_EQ(added, requestsOf(dir / "written", deck("100", kVariable, "-3"), ""));
  EXPECT_NE(added, requestsOf(dir / "weightless", weightless, ""));
  int compared = 0;
  for (const Case& c : cases) {
    const std::string name = std::to_string(compared);
    const std::string viaSet = requestsOf(dir / ("set" + name), base, c.options);
    const std::string viaEdit = requestsOf(dir / ("edit" + name), c.edited, "");
    ASSERT_FALSE(viaSet.empty()) << c.options;
    EXPECT_EQ(viaSet, viaEdit) << c.options;
    // The override changed something: without it the run differs (else the cmp proves nothing).
    EXPECT_NE(viaSet, unchanged) << c.options;
    ++compared;
  }
  EXPECT_EQ(compared, 4);
  // The .msg records the overrides, so a variant's output says what it ran.
  const std::string msg = slurp(dir / "set3" / "m.msg");
  EXPECT_NE(msg.find("override: --set ACCGRAV.IGRAV=-3"), std::string::npos) << msg;
  fs::remove_all(dir);
}

TEST(SetOption, OverridesApplyToTheModelOfACommandFile) {
  const fs::path dir = scratch("set-acf");
  write(dir / "m.adm", deck("100", kVariable, "-9.80665"));
  write(dir / "m.acf", "m\nm\nsimulate/transient, end=1, steps=50\nstop\n");
  ASSERT_EQ(run("run m.acf --quiet --set SPRINGDAMPER/3.K=250", dir).status, 0);
  const fs::path edited = dir / "edited";
  fs::create_directories(edited);
  write(edited / "m.adm", deck("250", kVariable, "-9.80665"));
  write(edited / "m.acf", "m\nm\nsimulate/transient, end=1, steps=50\nstop\n");
  ASSERT_EQ(run("run m.acf --quiet", edited).status, 0);
  EXPECT_EQ(slurp(dir / "m.req"), slurp(edited / "m.req"));
  EXPECT_FALSE(slurp(dir / "m.req").empty());
  fs::remove_all(dir);
}

TEST(SetOption, ABadOverrideIsALocatedInputError) {
  const fs::path dir = scratch("set-bad");
  write(dir / "m.adm", deck("100", kVariable, "-9.80665"));
  struct Case {
    std::string option, diagnostic;
  };
  const Case cases[] = {
      {"SPRINGDAMPER/9.K=1",
       "--set:1:1: error: SPRINGDAMPER/9: the data set has no SPRINGDAMPER/9 to override. "
       "The SPRINGDAMPER ids of the data set are 3"},
      {"BEAM/3.LENGTH=1",
       "error: BEAM/3: the data set has no BEAM/3 to override. The data set "
       "has no BEAM statement"},
      {"SPRINGDAMPER/3.KK=1", "--set:1:16: error: SPRINGDAMPER/3"},
      {"SPRINGDAMPER/3.K=stiff", "--set:1:"},
      {"K=1", "--set:1:1: error: the override 'K=1' is not STATEMENT/id.ARGUMENT=value"},
      {"'SPRINGDAMPER/3.K=1, C=2'", "must set exactly one argument"},
  };
  for (const Case& c : cases) {
    const Result r = run("run m.adm --end 0.1 --set " + c.option, dir);
    EXPECT_EQ(r.status, 1) << c.option << "\n" << r.output;
    EXPECT_NE(r.output.find(c.diagnostic), std::string::npos) << c.option << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir / "m.req")) << c.option;
  }
  // The second of two overrides is named by its position.
  const Result r = run("run m.adm --set SPRINGDAMPER/3.K=1 --set PART/5.MASS=1", dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.output.find("--set:2:1: error: PART/5: the data set has no PART/5"),
            std::string::npos)
      << r.output;
  fs::remove_all(dir);
}

}  // namespace

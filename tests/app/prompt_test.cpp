// The interactive prompt (`openmss` with no arguments), driven by piping a script into it:
// HELP, continuation lines, an unsupported command that does not end the session, and a
// model loaded and simulated at the prompt.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "language/schema.hpp"
#include "support/validation_data.hpp"

namespace {

namespace fs = std::filesystem;

struct Result {
  int status = -1;
  std::string out;  // standard output
  std::string err;  // standard error
};

fs::path scratch(const std::string& name) {
  const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  fs::path p = fs::temp_directory_path() / ("openmss-prompt-" + name + "-" + std::to_string(ticks));
  fs::create_directories(p);
  return p;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Runs `openmss` in `dir` with `script` on standard input (a file, so not a terminal).
Result runPrompt(const std::string& script, const fs::path& dir) {
  std::ofstream(dir / "script.txt", std::ios::binary) << script;
  const std::string cmd =
      "cd '" + dir.string() + "' && '" OPENMSS_BINARY "' < script.txt > out.txt 2> err.txt";
  const int raw = std::system(cmd.c_str());
  Result r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = slurp(dir / "out.txt");
  r.err = slurp(dir / "err.txt");
  return r;
}

const fs::path kRevolute =
    openmss::testing::adamsJointsDir() / "Revolute_Case01/test_Revolute_Case01.adm";

TEST(Prompt, HelpListsEveryCommandWithItsSupportAndNoPromptTextWhenPiped) {
  const fs::path dir = scratch("help");
  const Result r = runPrompt("HELP\nSTOP\n", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  // Not a terminal: no banner and no "openmss> ".
  EXPECT_EQ(r.out.find("openmss>"), std::string::npos) << r.out;
  for (const auto& c : openmss::language::commandSchema()) {
    EXPECT_FALSE(c.summary.empty()) << c.name;
    std::string line = "  " + c.name;
    line.resize(16, ' ');
    line += (c.solverSupported ? "supported  " : "not yet    ") + c.summary + "\n";
    EXPECT_NE(r.out.find(line), std::string::npos) << line;
  }
  EXPECT_NE(r.out.find("  SIMULATE      supported  runs an analysis"), std::string::npos);
  EXPECT_NE(r.out.find("  SAVE          supported  saves the model"), std::string::npos);
  EXPECT_NE(r.out.find("  AUTOSCALE     not yet    "), std::string::npos);
  fs::remove_all(dir);
}

TEST(Prompt, AnUnsupportedCommandIsReportedAndTheNextOneRuns) {
  const fs::path dir = scratch("unsupported");
  // CONTROL is read (it is in the schema) but the solver cannot run it; HELP then still runs.
  const Result r = runPrompt("control/routine=consub\nhelp\n", dir);
  EXPECT_EQ(r.status, 1);  // something failed, but the session went on to the end
  EXPECT_EQ(r.err,
            "<stdin>:1:1: error: CONTROL: no model is loaded. Load a data set first (line 1 of "
            "the .acf, or FILE/MODEL=).\n");
  EXPECT_NE(r.out.find("  STOP          supported"), std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(Prompt, ContinuationLinesModelLoadAndSimulate) {
  ASSERT_TRUE(fs::exists(kRevolute)) << kRevolute;
  const fs::path dir = scratch("simulate");
  fs::copy_file(kRevolute, dir / "rev.adm");
  const Result r = runPrompt(
      "file/model=rev\n"
      "autoscale\n"              // a model is loaded: now the solver says it cannot
      "simulate/transient, &\n"  // continued with '&' ...
      "   end=0.5, &\n"          // ... over three lines
      "   steps=5\n"
      "stop\n"
      "help\n",  // after STOP nothing is read
      dir);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("<stdin>:2:1: error: AUTOSCALE: AUTOSCALE is not supported yet"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("model ./rev.adm: 1 moving parts, 1 joints, 0 motions; 1 degrees of "
                       "freedom; messages in ./rev.msg\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("analysis reached t = 0.5 ("), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(", 6 output steps)"), std::string::npos) << r.out;  // t = 0, 0.1, .., 0.5
  EXPECT_EQ(r.out.find("Commands ("), std::string::npos) << "HELP after STOP ran";
  // The message file echoes the command as typed, continuation lines included.
  const std::string msg = slurp(dir / "rev.msg");
  EXPECT_NE(msg.find(" command: simulate/transient, &\n command:    end=0.5, &\n command:    "
                     "steps=5\n"),
            std::string::npos)
      << msg;
  // The request file holds the six output steps (header 3 + directory lines + 3 per step).
  const std::string req = slurp(dir / "rev.req");
  EXPECT_NE(req.find("   5.00000E-01\n"), std::string::npos) << req;
  fs::remove_all(dir);
}

TEST(Prompt, ASyntaxErrorIgnoresTheWholeCommandAndTheSessionGoesOn) {
  const fs::path dir = scratch("syntax");
  // docs/language.md ("Decision"): a command with a bad argument is not run at all.
  const Result r = runPrompt("simulate/transient, end=abc\n, steps=5\nhelp\n", dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err,
            "<stdin>:1:25: error: SIMULATE: END expects a number, not 'abc'. Write a number "
            "such as 1.5, -2E-3 or 90D\n"
            "<stdin>:1:1: note: SIMULATE: the command was not run. Correct it and enter it again\n"
            "<stdin>:2:1: error: SIMULATE: a command continues on a new line only after '&' at "
            "the end of the previous line. End the previous line with '&'\n");
  EXPECT_NE(r.out.find("Commands ("), std::string::npos) << r.out;
  fs::remove_all(dir);
}

TEST(Prompt, EndOfInputInsideAContinuationIsDiagnosed) {
  const fs::path dir = scratch("eof");
  const Result r = runPrompt("help &\n", dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err,
            "<stdin>:1:6: error: the command ends with '&' but no line follows. Remove the '&' "
            "or add the rest of the command\n"
            "<stdin>:1:1: note: HELP: the command was not run. Correct it and enter it again\n");
  fs::remove_all(dir);
}

}  // namespace

#include "app/prompt.hpp"

#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "app/command_runner.hpp"
#include "commands/session.hpp"
#include "language/command_reader.hpp"

namespace openmss::app {
namespace {

constexpr const char* kPrompt = "openmss> ";
constexpr const char* kContinuationPrompt = "      > ";

// Reports the reader's diagnostics; true when there was an error among them.
bool reportReading(language::CommandReader& reader) {
  const Diagnostics d = reader.takeDiagnostics();
  for (const auto& x : d.all()) std::fprintf(stderr, "%s\n", format(x).c_str());
  return d.hasErrors();
}

void discardReady(language::CommandReader& reader) {
  for (const auto& c : reader.takeCommands()) {
    Diagnostic d;
    d.severity = Severity::Note;
    d.where = c.where;
    d.subject = c.subject();
    d.message = "the command was not run";
    d.hint = "Correct it and enter it again";
    std::fprintf(stderr, "%s\n", format(d).c_str());
  }
}

// One line on what a successful command did, so the user sees progress without opening the
// message file.
void acknowledge(const language::Statement& c, const commands::Session& session) {
  if (c.name == "FILE" && c.has("MODEL") && session.model()) {
    const model::Model& m = *session.model();
    std::printf(
        "model %s: %d moving parts, %zu joints, %zu motions; %d degrees of freedom; "
        "messages in %s\n",
        m.file.c_str(), m.bodyCount(), m.joints.size(), m.motions.size(),
        session.degreesOfFreedom(), session.messageFilePath().c_str());
  } else if (c.name == "SIMULATE") {
    const auto& r = session.summary();
    std::printf("%s analysis reached t = %g (%ld integration steps, %ld output steps)\n",
                r.analysis.c_str(), r.time, r.steps, r.outputSteps);
  }
  std::fflush(stdout);
}

}  // namespace

int runPrompt(std::istream& in, const PromptOptions& options) {
  commands::SessionOptions sessionOptions;
  sessionOptions.outputDirectory = options.outputDirectory;
  sessionOptions.progress = options.interactive;
  commands::Session session(sessionOptions);
  CommandRunner runner(session, stdout);
  language::CommandReader reader("<stdin>");
  const std::filesystem::path here = ".";

  if (options.interactive)
    std::printf(
        "OpenMSS %s -- ADAMS/Solver commands. HELP lists them; STOP ends the session.\n"
        "Load a model with FILE/MODEL=name.\n",
        OPENMSS_VERSION);
  bool anyFailed = false;
  std::vector<std::string> echo;  // the physical lines of the command being read
  auto runReady = [&] {
    for (const auto& c : reader.takeCommands()) {
      // With ';' several commands share a line: the message file shows it once.
      const bool ok = runner.execute(c, std::exchange(echo, {}), here);
      if (ok) acknowledge(c, session);
      anyFailed = anyFailed || !ok;
      if (session.stopped()) return;
    }
  };

  bool more = false;
  std::string line;
  while (!session.stopped()) {
    if (options.interactive) {
      std::printf("%s", more ? kContinuationPrompt : kPrompt);
      std::fflush(stdout);
    }
    if (!std::getline(in, line)) break;
    echo.push_back(line);
    more = reader.feedLine(line);
    if (reportReading(reader)) {
      // docs/language.md ("Decision"): a command with a syntax error is ignored as a whole, rather than run
      // without the argument that was wrong.
      discardReady(reader);
      anyFailed = true;
    }
    runReady();
    if (!more) echo.clear();
  }
  if (!session.stopped()) {
    if (options.interactive) std::printf("\n");
    // End of input: a command still waiting for its continuation is diagnosed and run as is.
    reader.finish();
    if (reportReading(reader)) {
      discardReady(reader);
      anyFailed = true;
    }
    runReady();
  }
  return anyFailed ? 1 : 0;
}

}  // namespace openmss::app

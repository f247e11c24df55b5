#include "api/run.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "app/command_runner.hpp"
#include "commands/session.hpp"
#include "language/command_reader.hpp"
#include "language/reader.hpp"

namespace fs = std::filesystem;

namespace openmss::api {
namespace {

commands::SessionOptions sessionOptions(const std::string& outputDirectory) {
  commands::SessionOptions opt;
  opt.outputDirectory = outputDirectory;
  opt.progress = false;
  // The caller gets the diagnostics as records; the terminal stays quiet.
  opt.echoDiagnostics = false;
  opt.printInformation = false;
  return opt;
}

DiagnosticRecord missingFile(const std::string& path, const std::string& what) {
  Diagnostic d;
  d.where.file = path;
  d.message = what + " does not exist";
  d.hint = "Check the path.";
  return toRecord(d);
}

std::string existing(const std::string& path) {
  return !path.empty() && fs::exists(path) ? path : std::string();
}

void collect(const commands::Session& s, RunResult& r) {
  const auto& summary = s.summary();
  r.time = summary.time;
  r.steps = summary.steps;
  r.outputSteps = summary.outputSteps;
  r.analysis = summary.analysis;
  r.messageFile = existing(s.messageFilePath());
  r.requestFile = existing(s.requestFilePath());
  // The results file (.res) sits beside the request file with the same prefix when the run
  // writes one (docs/output-files.md).
  const std::string req = s.requestFilePath().empty() ? s.messageFilePath() : s.requestFilePath();
  if (!req.empty()) r.resultsFile = existing(fs::path(req).replace_extension(".res").string());
  if (!r.messageFile.empty()) r.prefix = fs::path(r.messageFile).stem().string();
  for (auto& d : toRecords(s.diagnostics())) r.diagnostics.push_back(std::move(d));
}

// Reads `text` as commands and executes them in order; false at the first that fails.
bool executeText(commands::Session& session, const std::string& text, RunResult& r) {
  language::CommandReader reader("<openmss.simulate>");
  reader.feedLine(text);
  reader.finish();
  const Diagnostics read = reader.takeDiagnostics();
  for (auto& d : toRecords(read)) r.diagnostics.push_back(std::move(d));
  if (read.hasErrors()) return false;
  for (const auto& c : reader.takeCommands()) {
    session.echoCommand(text);
    if (!session.execute(c)) return false;
  }
  return true;
}

}  // namespace

std::string exactNumber(double v) {
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  return text;
}

RunResult runCommandFile(const std::string& path, const std::string& outputDirectory) {
  RunResult r;
  r.outputDirectory = outputDirectory;
  // The command file's own reading errors, as records (the runner prints them only).
  Diagnostics readDiags;
  language::CommandFile cf;
  language::readCommandFile(path, cf, readDiags);
  if (readDiags.hasErrors() || !fs::is_regular_file(path)) {
    r.diagnostics = toRecords(readDiags);
    if (r.diagnostics.empty()) r.diagnostics.push_back(missingFile(path, "the command file"));
    return r;
  }
  commands::Session session(sessionOptions(outputDirectory));
  std::FILE* sink = std::fopen("/dev/null", "w");  // HELP listings have no reader here
  app::CommandRunner runner(session, sink ? sink : stdout);
  const app::RunOutcome outcome = runner.runCommandFile(path);
  if (sink) std::fclose(sink);
  r.diagnostics = toRecords(readDiags);  // warnings of the reading
  collect(session, r);
  r.status = outcome == app::RunOutcome::Completed    ? RunResult::Status::Completed
             : outcome == app::RunOutcome::InputError ? RunResult::Status::InputError
                                                      : RunResult::Status::Failed;
  return r;
}

RunResult simulateModel(const std::string& path, const SimulateOptions& o,
                        const std::string& outputDirectory) {
  RunResult r;
  r.outputDirectory = outputDirectory;
  commands::Session session(sessionOptions(outputDirectory));
  const std::string prefix = o.prefix.empty() ? fs::path(path).stem().string() : o.prefix;
  if (!fs::is_regular_file(path)) {
    r.diagnostics.push_back(missingFile(path, "the data set"));
    return r;
  }
  if (!session.loadModel(path, prefix)) {
    collect(session, r);
    return r;
  }
  std::vector<std::string> commands = {"OUTPUT/REQSAVE"};
  if (!o.integrator.empty())
    commands.push_back("INTEGRATOR/" + o.integrator +
                       (o.error > 0 ? ", ERROR=" + exactNumber(o.error) : std::string()));
  commands.push_back(
      "SIMULATE/TRANSIENT, END=" + exactNumber(o.end) +
      (o.dtout > 0 ? ", DTOUT=" + exactNumber(o.dtout) : ", STEPS=" + std::to_string(o.steps)));
  bool ok = true;
  for (const auto& text : commands) {
    ok = executeText(session, text, r);
    if (!ok) break;
  }
  collect(session, r);
  // A command rejected before any analysis (an unknown integrator) is an input error.
  r.status = ok ? RunResult::Status::Completed
                : (r.analysis.empty() ? RunResult::Status::InputError : RunResult::Status::Failed);
  return r;
}

}  // namespace openmss::api

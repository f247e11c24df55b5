#include "app/command_runner.hpp"

#include <fstream>

#include "app/print_diagnostics.hpp"
#include "language/reader.hpp"
#include "language/schema.hpp"

namespace fs = std::filesystem;

namespace openmss::app {
namespace {

// A command file that names itself in FILE/COMMAND= would otherwise recurse until the stack
// runs out; ADAMS users nest command files one or two levels deep.
constexpr int kMaxCommandFileDepth = 16;

std::vector<std::string> fileLines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  std::string l;
  while (std::getline(in, l)) {
    if (!l.empty() && l.back() == '\r') l.pop_back();
    lines.push_back(l);
  }
  return lines;
}

std::string firstValue(const language::Statement& c, const char* argument) {
  const language::Argument* a = c.find(argument);
  // `written` keeps the file name's case; `text` is upper-cased.
  return a && !a->values.empty() ? a->values[0].written.str() : std::string();
}

}  // namespace

fs::path resolveInputPath(const std::string& written, const fs::path& base,
                          const std::string& extension) {
  fs::path p = written;
  if (p.is_relative()) p = base / p;
  if (!fs::exists(p) && p.extension().empty()) p += extension;
  return p;
}

std::string commandHelp() {
  std::string out =
      "Commands (any unique prefix is accepted; '&' at the end of a line continues a command;\n"
      "'supported' says whether the solver runs the command yet):\n";
  for (const auto& c : language::commandSchema()) {
    std::string line = "  " + c.name;
    line.resize(16, ' ');
    line += c.solverSupported ? "supported  " : "not yet    ";
    line += c.summary;
    out += line + "\n";
  }
  return out;
}

CommandRunner::CommandRunner(commands::Session& session, std::FILE* helpOut)
    : session_(session), helpOut_(helpOut) {}

bool CommandRunner::loadModel(const language::Statement& c, const fs::path& base) {
  const std::string written = firstValue(c, "MODEL");
  const fs::path model = resolveInputPath(written, base, ".adm");
  if (!fs::is_regular_file(model)) {
    // Checked here so that a typing mistake gets one clear message, not the model checks of
    // an empty data set.
    Diagnostic d;
    d.where = c.where;
    d.subject = c.subject();
    d.message = "the data set " + model.string() + " does not exist";
    d.hint = "Check the name; .adm is added when it has no extension";
    std::fprintf(stderr, "%s\n", format(d).c_str());
    return false;
  }
  std::string prefix = firstValue(c, "OUTPUT_PREFIX");
  if (prefix.empty()) prefix = model.stem().string();
  modelLoaded_ = session_.loadModel(model.string(), prefix);
  return modelLoaded_;
}

bool CommandRunner::execute(const language::Statement& c, const std::vector<std::string>& echo,
                            const fs::path& base) {
  for (const auto& line : echo) session_.echoCommand(line);
  if (c.name == "HELP") {
    std::fprintf(helpOut_, "%s", commandHelp().c_str());
    return true;
  }
  if (c.name == "FILE") {
    if (c.has("MODEL") && !loadModel(c, base)) return false;
    if (c.has("COMMAND")) {
      const fs::path file = resolveInputPath(firstValue(c, "COMMAND"), base, ".acf");
      return runCommandFile(file.string()) == RunOutcome::Completed;
    }
    if (c.has("MODEL")) return true;
  }
  return session_.execute(c);
}

RunOutcome CommandRunner::runCommandFile(const std::string& path) {
  if (commandFileDepth_ >= kMaxCommandFileDepth) {
    std::fprintf(stderr, "openmss: %s: command files nested more than %d deep; not read\n",
                 path.c_str(), kMaxCommandFileDepth);
    return RunOutcome::InputError;
  }
  Diagnostics diags;
  language::CommandFile cf;
  language::readCommandFile(path, cf, diags);
  printDiagnostics(diags);
  readErrors_ += diags.errorCount();
  readWarnings_ += diags.warningCount();
  if (diags.hasErrors() && !keepGoing_) return RunOutcome::InputError;

  const fs::path base = fs::path(path).parent_path();
  if (!cf.modelFile.empty()) {
    const fs::path model = resolveInputPath(cf.modelFile, base, ".adm");
    const std::string prefix = cf.outputPrefix.empty() ? model.stem().string() : cf.outputPrefix;
    if (!fs::is_regular_file(model)) {  // one clear message, not the checks of an empty model
      std::fprintf(stderr, "%s:1:1: error: the data set %s does not exist. Check line 1 of the "
                   "command file; .adm is added when it has no extension\n",
                   path.c_str(), model.string().c_str());
      ++readErrors_;
      return RunOutcome::InputError;
    }
    modelLoaded_ = session_.loadModel(model.string(), prefix);
    if (!modelLoaded_ && !keepGoing_) {
      std::fprintf(stderr, "openmss: the model %s has errors; nothing was simulated\n",
                   model.string().c_str());
      return RunOutcome::InputError;
    }
    // `openmss check`: the commands are checked against the data set as written as well, so
    // that one pass reports the errors of both files (Session::checkWithoutSystem).
  }
  ++commandFileDepth_;
  const auto lines = fileLines(path);
  RunOutcome outcome = RunOutcome::Completed;
  for (const auto& c : cf.commands) {
    std::vector<std::string> echo;
    for (int l = c.where.line;
         l >= 1 && l <= std::max(c.lastLine, c.where.line) && l <= static_cast<int>(lines.size());
         ++l)
      echo.push_back(lines[l - 1]);
    const bool loadsModel = c.name == "FILE" && c.has("MODEL");
    if (!execute(c, echo, base)) {
      outcome = loadsModel ? RunOutcome::InputError : RunOutcome::CommandFailed;
      if (!keepGoing_ || loadsModel) break;
    }
    if (session_.stopped()) break;
  }
  --commandFileDepth_;
  if (!cf.modelFile.empty() && !modelLoaded_) return RunOutcome::InputError;
  return outcome;
}

}  // namespace openmss::app

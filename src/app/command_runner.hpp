#pragma once
// Runs ADAMS commands against a Session, the same way from an .acf file and from the
// interactive prompt: FILE (MODEL=, COMMAND=) and HELP are carried out here, every other
// command by the session. Paths in FILE/MODEL= and FILE/COMMAND= resolve against the folder of
// the command file that names them (the current folder at the prompt).

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "commands/session.hpp"
#include "language/dataset.hpp"

namespace openmss::app {

// "model" -> "<base>/model", and "<base>/model.<extension>" when "model" does not exist and
// has no extension (ADAMS supplies .adm for data sets and .acf for command files).
std::filesystem::path resolveInputPath(const std::string& written,
                                       const std::filesystem::path& base,
                                       const std::string& extension);

// The HELP listing: every command of the schema, whether the solver runs it yet, and what it
// does. Built from language::commandSchema(), so it cannot fall behind the reader.
std::string commandHelp();

// How a command file ended, for the program's exit status.
enum class RunOutcome {
  Completed,      // every command ran (or STOP ended it)
  InputError,     // the command file or its model could not be read
  CommandFailed,  // a command was rejected or its analysis failed; later commands were skipped
};

class CommandRunner {
 public:
  // `helpOut` receives the HELP listing (stdout for the program).
  CommandRunner(commands::Session& session, std::FILE* helpOut);

  // Executes one command whose source lines are `echo` (written to the message file first).
  // Returns false when the command failed; the reason is in the session's diagnostics.
  bool execute(const language::Statement& command, const std::vector<std::string>& echo,
               const std::filesystem::path& base);

  // Reads and runs a command file as ADAMS does: line 1 the model, line 2 the output prefix,
  // then commands until STOP; the first failing command ends the file.
  RunOutcome runCommandFile(const std::string& path);

  bool modelLoaded() const { return modelLoaded_; }
  // `openmss check`: a failing command does not end the file, so that every error is
  // reported; errors of the command file's reading are counted here.
  void setKeepGoing(bool keepGoing) { keepGoing_ = keepGoing; }
  int readErrors() const { return readErrors_; }
  int readWarnings() const { return readWarnings_; }

 private:
  bool loadModel(const language::Statement& command, const std::filesystem::path& base);

  commands::Session& session_;
  std::FILE* helpOut_;
  bool modelLoaded_ = false;
  int commandFileDepth_ = 0;  // FILE/COMMAND nesting, bounded against a file that runs itself
  bool keepGoing_ = false;
  int readErrors_ = 0, readWarnings_ = 0;
};

}  // namespace openmss::app

#pragma once
// Incremental reader of ADAMS commands, for the interactive prompt and for command files:
// feed it one physical line at a time; a line ending with '&' asks for the next line, and
// every complete command comes out as a Statement with its source location.

#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "language/source_line.hpp"

namespace openmss::language {

class CommandReader {
 public:
  // `sourceName` appears in diagnostics ("<stdin>" at the prompt); `firstLineNumber` is the
  // number of the first line fed (3 in a classic .acf, whose first two lines are file names).
  explicit CommandReader(std::string sourceName = "<stdin>", int firstLineNumber = 1);

  // Reads one physical line (terminator optional). Returns true when the command is not
  // complete yet because the line ended with '&' — the prompt should ask for another line.
  bool feedLine(std::string_view line);
  bool needsMoreLines() const { return !pending_.empty(); }

  // End of input: a command still waiting for its continuation is diagnosed and read as is.
  void finish();

  // Complete commands read so far, in order; they are handed over once.
  std::vector<Statement> takeCommands();
  // Diagnostics of everything read so far, handed over once.
  Diagnostics takeDiagnostics();
  bool sawStop() const { return sawStop_; }

 private:
  void parsePending();

  std::string source_;
  int nextLineNumber_;
  std::vector<SourceLine> pending_;      // the lines of the command being continued with '&'
  std::deque<std::string> pendingText_;  // their raw text (SourceLine::text views into it)
  std::vector<Statement> ready_;
  Diagnostics diags_;
  std::string previousSubject_;
  bool sawStop_ = false;
};

}  // namespace openmss::language

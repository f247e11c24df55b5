#include "language/command_reader.hpp"

#include <utility>

#include "language/statement_parser.hpp"

namespace openmss::language {

CommandReader::CommandReader(std::string sourceName, int firstLineNumber)
    : source_(std::move(sourceName)), nextLineNumber_(firstLineNumber) {}

bool CommandReader::feedLine(std::string_view raw) {
  while (!raw.empty() && (raw.back() == '\n' || raw.back() == '\r')) raw.remove_suffix(1);
  // The line's text is a view: it is kept with the pending lines until they are parsed.
  pendingText_.emplace_back(raw);
  SourceLine line = prepareLine(pendingText_.back(), nextLineNumber_++);
  if (line.blank()) {  // blank and comment lines change nothing
    pendingText_.pop_back();
    return needsMoreLines();
  }
  if (pending_.empty() && line.text[line.firstColumn() - 1] == ',') {
    // Commands continue only after '&': a prompt cannot wait to see whether the next line
    // starts with ',' before running the command it has.
    diags_.error({source_, line.number, line.firstColumn()}, previousSubject_,
                 "a command continues on a new line only after '&' at the end of the "
                 "previous line",
                 "End the previous line with '&'");
    pendingText_.pop_back();
    return false;
  }
  const bool more = line.endsWithAmpersand;
  pending_.push_back(std::move(line));
  if (more) return true;
  parsePending();
  return false;
}

void CommandReader::finish() {
  if (pending_.empty()) return;
  const SourceLine& last = pending_.back();
  diags_.error({source_, last.number, last.ampersandColumn}, previousSubject_,
               "the command ends with '&' but no line follows",
               "Remove the '&' or add the rest of the command");
  parsePending();
}

void CommandReader::parsePending() {
  std::vector<LinePiece> pieces;
  for (size_t k = 0; k < pending_.size(); ++k)
    pieces.push_back({&pending_[k], k == 0 ? LineJoin::First : LineJoin::Ampersand});
  auto commands =
      parseStatementGroup(pieces, InputKind::Command, source_, diags_, previousSubject_);
  pending_.clear();
  pendingText_.clear();
  for (auto& c : commands) {
    previousSubject_ = c.subject();
    if (c.name == "STOP") sawStop_ = true;
    ready_.push_back(std::move(c));
  }
}

std::vector<Statement> CommandReader::takeCommands() { return std::exchange(ready_, {}); }

Diagnostics CommandReader::takeDiagnostics() { return std::exchange(diags_, {}); }

}  // namespace openmss::language

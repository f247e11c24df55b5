// libFuzzer target for the ADAMS language reader (src/language): the same bytes are read as a
// data set, as a command file and line by line as prompt input. Besides the sanitizers'
// checks, it asserts the reader's promises: it never throws, and every statement and
// diagnostic points at a line that exists in the input.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "common/diagnostics.hpp"
#include "language/command_reader.hpp"
#include "language/reader.hpp"

namespace {

using namespace openmss;

// Physical lines as the reader counts them: "\r\n", "\n" and a lone "\r" each end a line.
int countLines(std::string_view text) {
  int lines = 1;
  for (size_t k = 0; k < text.size(); ++k) {
    if (text[k] == '\n')
      ++lines;
    else if (text[k] == '\r' && (k + 1 == text.size() || text[k + 1] != '\n'))
      ++lines;
  }
  return lines;
}

// A location must be unknown (0) or inside the input; one past the last line is allowed for
// "missing END"-style diagnostics that point at the end of the text.
void checkLine(int line, int lineCount) {
  if (line < 0 || line > lineCount + 1) std::abort();
}

void checkDiagnostics(const Diagnostics& diags, int lineCount) {
  for (const auto& d : diags.all()) {
    checkLine(d.where.line, lineCount);
    if (format(d).empty()) std::abort();
  }
}

void checkStatements(const std::vector<language::Statement>& statements, int lineCount) {
  for (const auto& s : statements) {
    checkLine(s.where.line, lineCount);
    checkLine(s.lastLine, lineCount);
    if (s.name.empty()) std::abort();
    (void)s.subject();
    for (const auto& a : s.args) {
      checkLine(a.where.line, lineCount);
      if (a.separators.size() + 1 < a.values.size()) std::abort();
    }
  }
}

void readAsDataset(std::string_view text, int lineCount, bool warnLongLines) {
  language::Dataset dataset;
  Diagnostics diags;
  language::ReadOptions options;
  options.warnLongLines = warnLongLines;
  language::readDatasetText(text, "fuzz.adm", dataset, diags, options);
  checkStatements(dataset.statements, lineCount);
  checkDiagnostics(diags, lineCount);
}

void readAsCommandFile(std::string_view text, int lineCount) {
  language::CommandFile file;
  Diagnostics diags;
  language::readCommandText(text, "fuzz.acf", file, diags);
  checkStatements(file.commands, lineCount);
  checkDiagnostics(diags, lineCount);
}

// The prompt path: one physical line at a time, as a terminal delivers them.
void readAtPrompt(std::string_view text, int lineCount) {
  language::CommandReader reader("<fuzz>");
  size_t start = 0;
  while (start <= text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    reader.feedLine(text.substr(start, end - start));
    if (reader.sawStop()) break;
    start = end + 1;
  }
  reader.finish();
  checkStatements(reader.takeCommands(), lineCount);
  checkDiagnostics(reader.takeDiagnostics(), lineCount);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const int lineCount = countLines(text);
  // The last byte's low bit toggles the long-line warning, so both paths are explored.
  readAsDataset(text, lineCount, size > 0 && (data[size - 1] & 1) != 0);
  readAsCommandFile(text, lineCount);
  readAtPrompt(text, lineCount);
  return 0;
}

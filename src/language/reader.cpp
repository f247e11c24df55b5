#include "language/reader.hpp"

#include <fstream>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

#include "language/command_reader.hpp"
#include "language/source_line.hpp"
#include "language/statement_parser.hpp"

namespace openmss::language {

namespace {

// A statement must begin in one of the first five columns; later starts are comments.
constexpr int kLastStatementColumn = 5;
constexpr int kDocumentedLineLength = 80;

std::string trimmedLine(std::string_view s) {
  while (!s.empty() && (isBlank(s.back()) || s.back() == '\r')) s.remove_suffix(1);
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
  return std::string(s);
}

// "dir/model.adm" -> "model": the default output prefix.
std::string baseNameWithoutExtension(const std::string& path) {
  auto slash = path.find_last_of("/\\");
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  auto dot = name.find_last_of('.');
  if (dot != std::string::npos && dot > 0) name.resize(dot);
  return name;
}

bool readWholeFile(const std::string& path, std::string& text) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream buffer;
  buffer << in.rdbuf();
  text = buffer.str();
  return true;
}

// Keeps, of statements with the same name and id, the last one (as ADAMS does), warning at
// each redefinition; earlier definitions are removed from the data set.
class DuplicateFilter {
 public:
  explicit DuplicateFilter(Diagnostics& diags) : diags_(diags) {}

  void add(Statement st, std::vector<Statement>& out, std::vector<bool>& superseded) {
    if (st.id) {
      auto key = std::make_pair(st.name, *st.id);
      auto it = seen_.find(key);
      if (it != seen_.end()) {
        const Statement& earlier = out[it->second];
        diags_.warning(st.where, st.subject(),
                       st.subject() + " is defined again; the definition at line " +
                           std::to_string(earlier.where.line) + " is ignored",
                       "Remove or renumber one of them");
        superseded[it->second] = true;
      }
      seen_[key] = out.size();
    }
    out.push_back(std::move(st));
    superseded.push_back(false);
  }

 private:
  Diagnostics& diags_;
  std::map<std::pair<CompactString, long>, size_t> seen_;
};

}  // namespace

void readDatasetText(std::string_view text, const std::string& fileName, Dataset& out,
                     Diagnostics& diags, const ReadOptions& options) {
  out.file = fileName;
  const auto raw = splitPhysicalLines(text);
  if (raw.empty()) {
    diags.error({fileName, 0, 0}, "", "the data set is empty",
                "Line 1 is the title; statements follow and END closes the data set");
    return;
  }
  out.title = trimmedLine(raw[0]);
  std::vector<SourceLine> lines;
  lines.reserve(raw.size());
  for (size_t k = 0; k < raw.size(); ++k)
    lines.push_back(prepareLine(raw[k], static_cast<int>(k) + 1));

  std::vector<Statement> statements;
  std::vector<bool> superseded;
  DuplicateFilter duplicates(diags);
  std::string previousSubject;
  size_t i = 1;
  while (i < lines.size() && !out.sawEnd) {
    const SourceLine& first = lines[i];
    if (first.blank()) {
      ++i;
      continue;
    }
    if (first.text[0] == ',') {
      if (statements.empty()) {
        // Continuation lines straight after the title continue the title record: line 1 is
        // never a statement, so they continue nothing that could be read. Skipped with a
        // warning rather than refused (docs/language.md, "Title line").
        diags.warning({fileName, first.number, 1}, "",
                      "continuation line after the title continues the title (line 1 is "
                      "never a statement); it is skipped",
                      "If line 1 was meant as a statement, insert a title line before it");
      } else {
        diags.error({fileName, first.number, 1}, previousSubject,
                    "continuation line has no statement to continue",
                    "Start the statement on a line without a leading ','");
      }
      ++i;
      continue;
    }
    if (first.firstColumn() > kLastStatementColumn) {
      ++i;
      continue;
    }
    // The statement's continuation lines: after '&' any line, else lines with ',' in column
    // 1; blank, '!' and indented comment lines between them are skipped.
    std::vector<LinePiece> pieces{{&first, LineJoin::First}};
    bool ampersand = first.endsWithAmpersand;
    size_t j = i + 1;
    while (j < lines.size()) {
      const SourceLine& next = lines[j];
      if (next.blank()) {
        ++j;
      } else if (ampersand || next.text[0] == ',') {
        pieces.push_back({&next, ampersand ? LineJoin::Ampersand : LineJoin::Comma});
        ampersand = next.endsWithAmpersand;
        ++j;
      } else if (next.firstColumn() > kLastStatementColumn) {
        ++j;
      } else {
        break;
      }
    }
    if (ampersand) {
      const SourceLine& last = *pieces.back().line;
      diags.error({fileName, last.number, last.ampersandColumn}, previousSubject,
                  "the statement ends with '&' but no line follows",
                  "Remove the '&' or add the rest of the statement");
    }
    int lastLineRead = pieces.back().line->number;
    for (auto& st : parseStatementGroup(pieces, InputKind::DataSet, fileName, diags,
                                        previousSubject, options.requireArguments)) {
      if (st.name == "END") {
        // Nothing after END is read.
        out.sawEnd = true;
        lastLineRead = st.where.line;
        break;
      }
      previousSubject = st.subject();
      duplicates.add(std::move(st), statements, superseded);
    }
    if (options.warnLongLines) {
      for (size_t k = i; k < j && static_cast<int>(k) < lastLineRead; ++k)
        if (lines[k].rawLength > kDocumentedLineLength)
          diags.warning({fileName, lines[k].number, kDocumentedLineLength + 1}, "",
                        "line is longer than 80 columns",
                        "ADAMS documents 80 columns; continue long statements on a new line "
                        "starting with ','");
    }
    i = j;
  }
  if (!out.sawEnd)
    diags.warning({fileName, static_cast<int>(lines.size()), 0}, "",
                  "the data set has no END statement", "Add END as the last statement");
  // Superseded definitions are dropped in place, and the statements handed over without a
  // second array of them (a large data set's tree is its largest part; docs/performance.md).
  size_t kept = 0;
  for (size_t k = 0; k < statements.size(); ++k) {
    if (superseded[k]) continue;
    if (kept != k) statements[kept] = std::move(statements[k]);
    ++kept;
  }
  statements.resize(kept);
  if (out.statements.empty()) {
    out.statements = std::move(statements);
  } else {
    out.statements.reserve(out.statements.size() + statements.size());
    for (auto& st : statements) out.statements.push_back(std::move(st));
  }
}

bool readDatasetFile(const std::string& path, Dataset& out, Diagnostics& diags,
                     const ReadOptions& options) {
  std::string text;
  if (!readWholeFile(path, text)) {
    diags.error({path, 0, 0}, "", "cannot open the data set file",
                "Check the file name and that the file is readable");
    return false;
  }
  const int errorsBefore = diags.errorCount();
  readDatasetText(text, path, out, diags, options);
  return diags.errorCount() == errorsBefore;
}

void readCommandText(std::string_view text, const std::string& fileName, CommandFile& out,
                     Diagnostics& diags) {
  out.file = fileName;
  const auto raw = splitPhysicalLines(text);
  size_t firstCommand = 0;
  if (!raw.empty()) {
    out.modelFile = trimmedLine(raw[0]);
    firstCommand = 1;
    if (!out.modelFile.empty()) {
      const std::string prefix = raw.size() > 1 ? trimmedLine(raw[1]) : std::string();
      out.outputPrefix = prefix.empty() ? baseNameWithoutExtension(out.modelFile) : prefix;
      firstCommand = 2;
    }
  }
  CommandReader reader(fileName, static_cast<int>(firstCommand) + 1);
  for (size_t k = firstCommand; k < raw.size() && !reader.sawStop(); ++k) reader.feedLine(raw[k]);
  reader.finish();
  for (auto& c : reader.takeCommands()) out.commands.push_back(std::move(c));
  diags.append(reader.takeDiagnostics());
}

bool readCommandFile(const std::string& path, CommandFile& out, Diagnostics& diags) {
  std::string text;
  if (!readWholeFile(path, text)) {
    diags.error({path, 0, 0}, "", "cannot open the command file",
                "Check the file name and that the file is readable");
    return false;
  }
  const int errorsBefore = diags.errorCount();
  readCommandText(text, path, out, diags);
  return diags.errorCount() == errorsBefore;
}

}  // namespace openmss::language

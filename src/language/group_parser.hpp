#pragma once
// Internal to language/: the parser of one statement group (a statement and its continuation
// lines) behind parseStatementGroup (language/statement_parser.hpp). Statements, separators and
// recovery are in statement_parser.cpp; arguments, values, expressions and text in
// argument_parser.cpp. Nothing outside language/ includes this header.

#include <cctype>
#include <optional>
#include <string>
#include <vector>

#include "language/name_resolution.hpp"
#include "language/schema.hpp"
#include "language/statement_parser.hpp"

namespace openmss::language::parsing {

inline bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
inline bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
// Characters that can end an operand of an expression: a name, a number or a closing bracket.
inline bool isOperandEnd(char c) { return isNameChar(c) || c == ')' || c == ']' || c == '.'; }

std::string joinNames(const std::vector<std::string>& names);
std::string trimmed(std::string s);
bool acceptsWords(const ArgumentSpec& a);
std::string placeholder(const ArgumentSpec& a);
std::string countMessage(const ArgumentSpec& a, size_t given);
std::vector<NameCandidate> candidatesOf(const std::vector<StatementSpec>& table);
std::vector<NameCandidate> candidatesOf(const StatementSpec& spec);

enum class Separator { None, Comma, Colon, Backslash, Semicolon, End };

struct Cursor {
  size_t piece = 0;
  size_t pos = 0;
};

class GroupParser {
 public:
  GroupParser(const std::vector<LinePiece>& pieces, InputKind kind, const std::string& file,
              Diagnostics& diags, const std::string& previousSubject, bool requireArguments = true)
      : pieces_(pieces),
        kind_(kind),
        file_(file),
        fileIndex_(internFileName(file)),
        diags_(diags),
        previousSubject_(previousSubject),
        table_(kind == InputKind::DataSet ? statementSchema() : commandSchema()),
        tableCandidates_(candidatesOf(table_)),
        requireArguments_(requireArguments) {}

  std::vector<Statement> parseAll();

 private:
  // --- cursor ------------------------------------------------------------------------------
  const SourceLine& line() const { return *pieces_[c_.piece].line; }
  std::string_view text() const { return line().text; }
  char peek() const { return c_.pos < text().size() ? text()[c_.pos] : '\0'; }
  bool atLineEnd() const { return c_.pos >= text().size(); }
  bool hasNextPiece() const { return c_.piece + 1 < pieces_.size(); }
  LineJoin nextJoin() const { return pieces_[c_.piece + 1].join; }
  // The cursor's location; compact (the file's interned index), as the tree keeps it.
  CompactLocation here() const {
    return CompactLocation::inFile(fileIndex_, line().number, static_cast<int>(c_.pos) + 1);
  }
  void enterNextPiece() {
    ++c_.piece;
    // The comma in column 1 of a comma continuation line is not statement text.
    c_.pos = pieces_[c_.piece].join == LineJoin::Comma ? 1 : 0;
  }
  // Five or more blanks end the statement text of a line (the rest is a comment), except
  // inside expressions and text and in the indentation of a line continued after '&'.
  void skipBlanks(bool fiveBlanksEndLine) {
    size_t start = c_.pos;
    while (!atLineEnd() && isBlank(peek())) ++c_.pos;
    if (fiveBlanksEndLine && c_.pos - start >= 5) c_.pos = text().size();
  }
  std::string readName() {
    std::string s;
    if (!isNameStart(peek())) return s;
    while (!atLineEnd() && isNameChar(peek())) s += text()[c_.pos++];
    return s;
  }
  // A value token runs to a blank or delimiter; "::" (lib::routine) stays inside the token.
  std::string readRawToken() {
    std::string s;
    while (!atLineEnd()) {
      char ch = peek();
      if (isBlank(ch) || ch == ',' || ch == ';' || ch == '=' || ch == '\\' || ch == '"') break;
      if (ch == ')' && inParenthesisedList_) break;
      if (ch == ':') {
        if (c_.pos + 1 < text().size() && text()[c_.pos + 1] == ':') {
          s += "::";
          c_.pos += 2;
          continue;
        }
        break;
      }
      s += ch;
      ++c_.pos;
    }
    return s;
  }

  // --- grammar -----------------------------------------------------------------------------
  std::optional<Statement> parseStatement();
  void parseArguments(Statement& st, const StatementSpec& spec, bool needSeparator, bool hadSlash);
  bool parseArgument(Statement& st, const StatementSpec& spec);
  void parseValues(Statement& st, Argument& arg, const ArgumentSpec& as, const StatementSpec& spec);
  std::optional<Value> readValue(const Statement& st, const ArgumentSpec& as);
  bool checkValue(const Statement& st, const ArgumentSpec& as, Value& v);
  void parseExpression(Statement& st, Argument& arg, const StatementSpec& spec);
  bool continueExpression(Statement& st, std::string& expr, int depth, const StatementSpec& spec,
                          bool& ampersandReported);
  void parseText(Argument& arg);
  Separator readSeparator();
  bool nextIsValue(const ArgumentSpec& as, const StatementSpec& spec, size_t valuesSoFar);
  bool startsAnotherStatement();
  void skipValues(const StatementSpec& spec);
  void skipToDelimiter();
  void skipStatement();
  void checkRequired(const Statement& st, const StatementSpec& spec);

  const std::vector<LinePiece>& pieces_;
  InputKind kind_;
  const std::string& file_;
  std::uint32_t fileIndex_;  // file_ in the table of CompactLocation
  Diagnostics& diags_;
  const std::string& previousSubject_;
  const std::vector<StatementSpec>& table_;
  std::vector<NameCandidate> tableCandidates_;
  bool requireArguments_;  // parseStatementGroup's requireArguments
  Cursor c_;
  // Inside a parenthesised value list, e.g. INPUTS=(PRELOAD:REACTION_FORCE): ')' ends a token.
  bool inParenthesisedList_ = false;
  // Arguments written in the current statement, valid or not: a required argument that was
  // written with a bad value has been diagnosed already and is not "missing".
  std::vector<std::string> writtenArguments_;
};

}  // namespace openmss::language::parsing

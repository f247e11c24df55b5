// Over ~700 lines by intent: one GroupParser class (statements, arguments, values, expressions
// of one statement group) whose methods share its cursor; a split would expose it in a header.
#include "language/statement_parser.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "language/name_resolution.hpp"
#include "language/number_token.hpp"
#include "language/schema.hpp"

namespace openmss::language {

namespace {

bool isNameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isNameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
// Characters that can end an operand of an expression: a name, a number or a closing bracket.
bool isOperandEnd(char c) { return isNameChar(c) || c == ')' || c == ']' || c == '.'; }

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += ", ";
    out += names[i];
  }
  return out;
}

std::string trimmed(std::string s) {
  while (!s.empty() && isBlank(s.back())) s.pop_back();
  size_t b = 0;
  while (b < s.size() && isBlank(s[b])) ++b;
  return s.substr(b);
}

bool acceptsWords(const ArgumentSpec& a) {
  return a.type == ValueType::Word || a.type == ValueType::WordOrNumber;
}

std::string placeholder(const ArgumentSpec& a) {
  switch (a.type) {
    case ValueType::Flag:
      return a.name;
    case ValueType::Integer:
      return a.name + "=<integer>";
    case ValueType::Real:
      return a.name + "=<number>";
    case ValueType::Word:
    case ValueType::WordOrNumber:
      return a.name + "=<name>";
    case ValueType::Expression:
      return a.name + "=<expression>";
    case ValueType::Text:
      return a.name + "=<text>";
  }
  return a.name;
}

std::string countMessage(const ArgumentSpec& a, size_t given) {
  std::string expected;
  if (a.minValues == a.maxValues)
    expected = std::to_string(a.minValues) + (a.minValues == 1 ? " value" : " values");
  else if (a.maxValues >= kUnlimited)
    expected =
        "at least " + std::to_string(a.minValues) + (a.minValues == 1 ? " value" : " values");
  else
    expected = std::to_string(a.minValues) + " to " + std::to_string(a.maxValues) + " values";
  return a.name + " expects " + expected + "; " + std::to_string(given) + " given";
}

std::vector<NameCandidate> candidatesOf(const std::vector<StatementSpec>& table) {
  std::vector<NameCandidate> c;
  for (const auto& s : table) c.push_back({s.name, s.minAbbreviation, nullptr});
  return c;
}

std::vector<NameCandidate> candidatesOf(const StatementSpec& spec) {
  std::vector<NameCandidate> c;
  for (const auto& a : spec.arguments) c.push_back({a.name, a.minAbbreviation, &a.aliases});
  return c;
}

enum class Separator { None, Comma, Colon, Backslash, Semicolon, End };

struct Cursor {
  size_t piece = 0;
  size_t pos = 0;
};

class GroupParser {
 public:
  GroupParser(const std::vector<LinePiece>& pieces, InputKind kind, const std::string& file,
              Diagnostics& diags, const std::string& previousSubject)
      : pieces_(pieces),
        kind_(kind),
        file_(file),
        diags_(diags),
        previousSubject_(previousSubject),
        table_(kind == InputKind::DataSet ? statementSchema() : commandSchema()),
        tableCandidates_(candidatesOf(table_)) {}

  std::vector<Statement> parseAll();

 private:
  // --- cursor ------------------------------------------------------------------------------
  const SourceLine& line() const { return *pieces_[c_.piece].line; }
  const std::string& text() const { return line().text; }
  char peek() const { return c_.pos < text().size() ? text()[c_.pos] : '\0'; }
  bool atLineEnd() const { return c_.pos >= text().size(); }
  bool hasNextPiece() const { return c_.piece + 1 < pieces_.size(); }
  LineJoin nextJoin() const { return pieces_[c_.piece + 1].join; }
  SourceLocation here() const { return {file_, line().number, static_cast<int>(c_.pos) + 1}; }
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
  Diagnostics& diags_;
  const std::string& previousSubject_;
  const std::vector<StatementSpec>& table_;
  std::vector<NameCandidate> tableCandidates_;
  Cursor c_;
  // Arguments written in the current statement, valid or not: a required argument that was
  // written with a bad value has been diagnosed already and is not "missing".
  std::vector<std::string> writtenArguments_;
};

std::vector<Statement> GroupParser::parseAll() {
  std::vector<Statement> out;
  while (true) {
    skipBlanks(false);
    while (peek() == ';') {  // empty statements ("a; ;b" or a trailing ';') are harmless
      ++c_.pos;
      skipBlanks(false);
    }
    if (atLineEnd()) {
      if (!hasNextPiece()) break;
      // Only a ';' ending the previous statement gets here with lines left over.
      enterNextPiece();
      diags_.error({file_, line().number, 1}, out.empty() ? "" : out.back().subject(),
                   "continuation line follows a statement ended by ';'",
                   "Remove the ';' at the end of the previous line");
      c_.pos = text().size();
      continue;
    }
    auto st = parseStatement();
    if (st) {
      bool isEnd = st->name == "END";
      out.push_back(std::move(*st));
      if (isEnd && kind_ == InputKind::DataSet) break;
    }
  }
  return out;
}

std::optional<Statement> GroupParser::parseStatement() {
  const bool startsGroup = c_.piece == 0 && c_.pos + 1 == static_cast<size_t>(line().firstColumn());
  writtenArguments_.clear();
  Statement st;
  st.where = here();
  st.lastLine = line().number;
  const std::string spelled = readName();
  const char* what = kind_ == InputKind::DataSet ? "statement" : "command";
  if (spelled.empty()) {
    if (startsGroup && kind_ == InputKind::DataSet && startsNumber(peek())) {
      diags_.error(st.where, previousSubject_,
                   "this line continues a statement without a continuation mark",
                   "End the previous line with '&' or put ',' in column 1 of this line");
    } else {
      diags_.error(
          st.where, "", std::string("expected a ") + what + " name, found '" + peek() + "'",
          "Start the line with a name such as PART or MARKER, or make it a comment with '!'");
    }
    skipStatement();
    return std::nullopt;
  }
  st.spelled = spelled;
  const std::string upper = toUpper(spelled);

  skipBlanks(true);
  bool hadSlash = false;
  bool looksLikeArgument = peek() == '=';
  std::string idText;
  SourceLocation idWhere;
  if (peek() == '/') {
    hadSlash = true;
    ++c_.pos;
    skipBlanks(true);
    if (startsNumber(peek())) {
      idWhere = here();
      idText = readRawToken();
    }
  }

  auto r = resolveName(upper, tableCandidates_);
  if (r.status != NameResolution::Status::Resolved) {
    std::string subject = upper + (idText.empty() ? "" : "/" + idText);
    if (r.status == NameResolution::Status::Ambiguous) {
      diags_.error(st.where, subject,
                   "'" + upper + "' is an ambiguous abbreviation of " + joinNames(r.ambiguous),
                   std::string("Write more letters of the ") + what + " name");
    } else if (startsGroup && looksLikeArgument && kind_ == InputKind::DataSet) {
      diags_.error(st.where, previousSubject_,
                   "this line continues a statement without a continuation mark",
                   "End the previous line with '&' or put ',' in column 1 of this line");
    } else {
      diags_.error(st.where, subject, "'" + upper + "' is not an ADAMS " + what,
                   std::string("Check the spelling; docs/language.md lists every ") + what);
    }
    skipStatement();
    return std::nullopt;
  }
  const StatementSpec& spec = table_[r.index];
  st.name = spec.name;

  if (!idText.empty()) {
    auto number = parseNumber(idText);
    const bool valid =
        number && number->isInteger && number->value >= 1 && number->value <= 99999999;
    if (!valid) {
      diags_.error(idWhere, st.name,
                   "identifier '" + idText + "' is not a positive integer of at most 8 digits",
                   "Use a whole number from 1 to 99999999");
    } else if (spec.idRule == IdRule::NotAllowed) {
      diags_.warning(idWhere, st.name,
                     st.name + " takes no identifier; '" + idText + "' is ignored",
                     "Write " + st.name + "/ without a number");
    } else {
      st.id = static_cast<long>(number->value);
    }
  } else if (spec.idRule == IdRule::Required) {
    diags_.error(st.where, st.name, "missing identifier",
                 "Write " + st.name + "/id with a positive integer id, e.g. " + st.name + "/1");
  }

  parseArguments(st, spec, !idText.empty(), hadSlash);
  st.lastLine = line().number;
  if (kind_ == InputKind::DataSet) checkRequired(st, spec);
  return st;
}

void GroupParser::parseArguments(Statement& st, const StatementSpec& spec, bool needSeparator,
                                 bool hadSlash) {
  bool separatorPending = false;
  bool slashReported = false;
  SourceLocation separatorWhere;
  while (true) {
    skipBlanks(true);
    const SourceLocation before = here();
    const Separator s = readSeparator();
    if (s == Separator::End || s == Separator::Semicolon) {
      if (separatorPending)
        diags_.error(separatorWhere, st.subject(), "',' is not followed by an argument",
                     "Remove the ',' or add the argument");
      return;
    }
    if (s == Separator::Colon) {
      diags_.error(before, st.subject(), "unexpected ':' between arguments",
                   "Use ':' only between the values of one argument");
      continue;
    }
    if (s == Separator::Comma || s == Separator::Backslash) {
      if (separatorPending)
        diags_.error(before, st.subject(), "two delimiters in a row",
                     "Remove one of them; arguments are separated by a single ','");
      separatorPending = true;
      separatorWhere = before;
      continue;
    }
    // A token follows.
    if (startsAnotherStatement()) {
      diags_.error(here(), st.subject(), "a second statement starts on this line without ';'",
                   "Put ';' between two statements on one line, or start a new line");
      return;
    }
    if (!hadSlash && !slashReported) {
      diags_.error(here(), st.subject(), "missing '/' after " + st.name,
                   "Write " + st.name + "/ before the arguments");
      slashReported = true;
    } else if (needSeparator && !separatorPending) {
      Cursor save = c_;
      const std::string next = readName();
      c_ = save;
      // When no name follows, parseArgument reports what was found instead; one message
      // per problem.
      if (!next.empty())
        diags_.error(here(), st.subject(), "missing ',' before '" + next + "'",
                     "Separate arguments with ','");
    }
    if (!parseArgument(st, spec)) return;
    needSeparator = true;
    separatorPending = false;
  }
}

Separator GroupParser::readSeparator() {
  while (true) {
    skipBlanks(true);
    if (!atLineEnd()) {
      switch (peek()) {
        case ',':
          ++c_.pos;
          skipBlanks(true);
          // "2.0," at the end of a line and ", 10.0" on the next: the two commas are one
          // delimiter (FAST writes data sets this way and ADAMS reads them).
          if (atLineEnd() && hasNextPiece() && nextJoin() == LineJoin::Comma &&
              !line().endsWithAmpersand)
            enterNextPiece();
          return Separator::Comma;
        case ':':
          ++c_.pos;
          return Separator::Colon;
        case ';':
          ++c_.pos;
          return Separator::Semicolon;
        case '\\':
          // '\' ends an expression; a ',' right after it (same or next line) is the same break.
          ++c_.pos;
          skipBlanks(true);
          if (peek() == ',') {
            ++c_.pos;
          } else if (atLineEnd() && hasNextPiece() && nextJoin() == LineJoin::Comma) {
            enterNextPiece();
          } else if (atLineEnd() && hasNextPiece() && line().endsWithAmpersand) {
            enterNextPiece();
            skipBlanks(false);
            if (peek() == ',') ++c_.pos;
          }
          return Separator::Backslash;
        default:
          return Separator::None;
      }
    }
    if (!hasNextPiece()) return Separator::End;
    if (line().endsWithAmpersand) {
      enterNextPiece();
      skipBlanks(false);
      if (peek() == ',') {
        ++c_.pos;
        skipBlanks(true);
        if (peek() == ':') {
          ++c_.pos;
          return Separator::Colon;
        }
        return Separator::Comma;
      }
      continue;
    }
    if (nextJoin() == LineJoin::Comma) {
      enterNextPiece();
      skipBlanks(true);
      // A break before a ':' keeps the colon; the continuation comma is then not a delimiter.
      if (peek() == ':') {
        ++c_.pos;
        return Separator::Colon;
      }
      return Separator::Comma;
    }
    return Separator::End;
  }
}

bool GroupParser::startsAnotherStatement() {
  Cursor save = c_;
  std::string name = readName();
  skipBlanks(false);
  bool another = false;
  if (!name.empty() && peek() == '/') {
    auto r = resolveName(toUpper(name), tableCandidates_);
    another = r.status == NameResolution::Status::Resolved;
  }
  c_ = save;
  return another;
}

bool GroupParser::parseArgument(Statement& st, const StatementSpec& spec) {
  skipBlanks(true);
  const SourceLocation where = here();
  const std::string spelled = readName();
  if (spelled.empty()) {
    std::string found = peek() == '"' ? std::string("\"") : readRawToken();
    if (found.empty()) found = std::string(1, peek());
    c_ = Cursor{c_.piece, static_cast<size_t>(where.column - 1)};
    diags_.error(where, st.subject(), "expected an argument name, found '" + found + "'",
                 "Arguments are names such as PART=1 or GROUND; check for a missing name or "
                 "an extra ','");
    skipToDelimiter();
    return true;
  }
  const std::string upper = toUpper(spelled);
  auto r = resolveName(upper, candidatesOf(spec));
  if (r.status != NameResolution::Status::Resolved) {
    if (r.status == NameResolution::Status::Ambiguous) {
      diags_.error(where, st.subject(),
                   "ambiguous abbreviation '" + upper + "' matches " + joinNames(r.ambiguous),
                   "Write more letters of the argument name");
    } else {
      std::vector<std::string> valid;
      for (const auto& a : spec.arguments) valid.push_back(a.name);
      diags_.error(where, st.subject(), "unknown argument '" + upper + "'",
                   valid.empty() ? st.name + " takes no arguments"
                                 : st.name + " accepts: " + joinNames(valid));
    }
    skipBlanks(true);
    if (peek() == '=') {
      ++c_.pos;
      skipValues(spec);
    }
    return true;
  }
  const ArgumentSpec& as = spec.arguments[r.index];
  writtenArguments_.push_back(as.name);
  Argument arg;
  arg.name = as.name;
  arg.spelled = spelled;
  arg.where = where;
  skipBlanks(true);
  if (peek() == '=') {
    ++c_.pos;
    switch (as.type) {
      case ValueType::Flag:
        diags_.error(where, st.subject(), as.name + " takes no value",
                     "Remove the '=' and the value after " + as.name);
        skipValues(spec);
        break;
      case ValueType::Expression:
        parseExpression(st, arg, spec);
        break;
      case ValueType::Text:
        parseText(arg);
        break;
      default:
        parseValues(st, arg, as, spec);
        if (arg.values.empty()) return true;
        break;
    }
  } else if (as.type != ValueType::Flag) {
    diags_.error(where, st.subject(), as.name + " needs a value", "Write " + placeholder(as));
    return true;
  }
  st.args.push_back(std::move(arg));
  return true;
}

void GroupParser::parseValues(Statement& st, Argument& arg, const ArgumentSpec& as,
                              const StatementSpec& spec) {
  skipBlanks(true);
  // "SECTION =" at the end of a line, values on the next: that continuation comma is dropped.
  if (atLineEnd() && hasNextPiece() && nextJoin() == LineJoin::Comma) {
    enterNextPiece();
    skipBlanks(true);
  }
  size_t given = 0;
  bool valuesOk = true;
  while (true) {
    skipBlanks(true);
    if (atLineEnd() || peek() == ',' || peek() == ';' || peek() == '\\' || peek() == ':') {
      diags_.error(here(), st.subject(),
                   given == 0 ? as.name + "= has no value" : "missing value after a delimiter",
                   "Write " + placeholder(as));
      valuesOk = false;
      break;
    }
    if (arg.values.empty()) arg.valueWhere = here();
    auto v = readValue(st, as);
    ++given;
    if (v)
      arg.values.push_back(std::move(*v));
    else
      valuesOk = false;
    const Cursor save = c_;
    const Separator s = readSeparator();
    if (s == Separator::Colon) {
      arg.separators.push_back(':');
      continue;
    }
    if (s == Separator::Comma && nextIsValue(as, spec, given)) {
      arg.separators.push_back(',');
      continue;
    }
    c_ = save;
    break;
  }
  if (valuesOk &&
      (given < static_cast<size_t>(as.minValues) || given > static_cast<size_t>(as.maxValues)))
    diags_.error(arg.where, st.subject(), countMessage(as, given));
  if (!valuesOk) {
    arg.values.clear();
    arg.separators.clear();
  }
}

bool GroupParser::nextIsValue(const ArgumentSpec& as, const StatementSpec& spec,
                              size_t valuesSoFar) {
  skipBlanks(true);
  const char ch = peek();
  if (ch == '"' || startsNumber(ch)) return true;
  if (!isNameStart(ch)) return false;
  if (!acceptsWords(as) || valuesSoFar >= static_cast<size_t>(as.maxValues)) return false;
  const Cursor save = c_;
  const std::string name = toUpper(readRawToken());
  skipBlanks(true);
  const bool assignment = peek() == '=';
  c_ = save;
  if (assignment) return false;
  if (!as.allowedWords.empty()) {
    for (const auto& w : as.allowedWords)
      if (w == name) return true;
  }
  // A word that names an argument of the statement starts that argument.
  auto r = resolveName(name, candidatesOf(spec));
  return r.status == NameResolution::Status::Unknown;
}

std::optional<Value> GroupParser::readValue(const Statement& st, const ArgumentSpec& as) {
  Value v;
  v.where = here();
  if (peek() == '"') {
    const size_t close = text().find('"', c_.pos + 1);
    if (close == std::string::npos) {
      diags_.error(v.where, st.subject(), "unterminated quoted string",
                   "Close the string with '\"' on the same line");
      c_.pos = text().size();
      return std::nullopt;
    }
    v.kind = Value::Kind::Word;
    v.text = v.written = text().substr(c_.pos + 1, close - c_.pos - 1);
    v.quoted = true;
    c_.pos = close + 1;
  } else {
    const std::string token = readRawToken();
    if (token.empty()) {
      diags_.error(v.where, st.subject(),
                   "expected a value for " + as.name + ", found '" + std::string(1, peek()) + "'",
                   "Write " + placeholder(as));
      skipToDelimiter();
      return std::nullopt;
    }
    v.written = token;
    if (auto number = parseNumber(token)) {
      v.kind = Value::Kind::Number;
      v.number = number->value;
      v.isInteger = number->isInteger;
      v.degrees = number->degrees;
      v.text = token;
    } else if (startsNumber(token.front()) && !acceptsWords(as)) {
      diags_.error(v.where, st.subject(), "'" + token + "' is not a valid number",
                   "Write numbers like 12, -0.5, 1.5E-3 or 90D");
      return std::nullopt;
    } else {
      v.kind = Value::Kind::Word;
      v.text = toUpper(token);
    }
  }
  if (!checkValue(st, as, v)) return std::nullopt;
  return v;
}

bool GroupParser::checkValue(const Statement& st, const ArgumentSpec& as, Value& v) {
  const bool isWord = v.kind == Value::Kind::Word;
  switch (as.type) {
    case ValueType::Integer:
      if (isWord) {
        diags_.error(v.where, st.subject(),
                     as.name + " expects an integer, not '" + v.written + "'",
                     "Write a whole number, e.g. " + as.name + "=1");
        return false;
      }
      if (v.degrees) {
        diags_.error(v.where, st.subject(),
                     as.name + " expects an integer; " + v.written + " is an angle in degrees",
                     "Write a whole number without D");
        return false;
      }
      if (std::floor(v.number) != v.number) {
        diags_.error(v.where, st.subject(),
                     as.name + " expects an integer; " + v.written + " is not a whole number",
                     "Write a whole number such as 2 or 2.0");
        return false;
      }
      return true;
    case ValueType::Real:
      if (isWord) {
        diags_.error(v.where, st.subject(), as.name + " expects a number, not '" + v.written + "'",
                     "Write a number such as 1.5, -2E-3 or 90D");
        return false;
      }
      return true;
    case ValueType::Word:
      if (!isWord) {
        diags_.error(v.where, st.subject(),
                     as.name + " expects a name, not the number " + v.written,
                     as.allowedWords.empty() ? "" : "Use one of: " + joinNames(as.allowedWords));
        return false;
      }
      break;
    default:
      break;
  }
  if (isWord && !as.allowedWords.empty()) {
    std::vector<NameCandidate> allowed;
    std::vector<std::string_view> names(as.allowedWords.begin(), as.allowedWords.end());
    for (const auto& w : as.allowedWords)
      allowed.push_back({w, shortestUniquePrefix(w, names), nullptr});
    auto r = resolveName(toUpper(v.text), allowed);
    if (r.status != NameResolution::Status::Resolved) {
      diags_.error(v.where, st.subject(), "'" + v.written + "' is not a valid value of " + as.name,
                   "Use one of: " + joinNames(as.allowedWords));
      return false;
    }
    v.text = as.allowedWords[r.index];
  }
  return true;
}

void GroupParser::parseExpression(Statement& st, Argument& arg, const StatementSpec& spec) {
  arg.isExpression = true;
  bool ampersandReported = false;
  std::string expr;
  skipBlanks(false);
  // "FUNCTION =" at the end of a line with the expression on the continuation line.
  if (atLineEnd()) continueExpression(st, expr, 0, spec, ampersandReported);
  arg.valueWhere = here();
  int depth = 0;
  while (true) {
    if (atLineEnd()) {
      if (!continueExpression(st, expr, depth, spec, ampersandReported)) break;
      continue;
    }
    const char ch = peek();
    if (ch == '\\') break;  // the explicit end of an expression
    // A ',' or ';' outside parentheses cannot belong to an expression: it ends it. (ADAMS
    // accepted "...\F6=ORIENT(27,4,0201,0101),C=EULER PARAMETERS" without a '\'.)
    if (depth <= 0 && (ch == ',' || ch == ';')) break;
    if (ch == '(' || ch == '[') ++depth;
    if (ch == ')' || ch == ']') --depth;
    expr += ch;
    ++c_.pos;
  }
  arg.expression = trimmed(expr);
  if (arg.expression.empty())
    diags_.error(arg.where, st.subject(), arg.name + "= has no expression",
                 "Write the function expression after '='");
}

// At the end of a line inside an expression: decides whether the next line continues it and,
// when it does, moves there (dropping the continuation comma).
bool GroupParser::continueExpression(Statement& st, std::string& expr, int depth,
                                     const StatementSpec& spec, bool& ampersandReported) {
  (void)spec;
  if (!hasNextPiece()) return false;
  const bool ampersand = line().endsWithAmpersand;
  if (!ampersand && nextJoin() != LineJoin::Comma) return false;

  // What the next line starts with, after its continuation comma.
  const SourceLine& next = *pieces_[c_.piece + 1].line;
  size_t k = nextJoin() == LineJoin::Comma ? 1 : 0;
  while (k < next.text.size() && isBlank(next.text[k])) ++k;
  if (ampersand && k < next.text.size() && next.text[k] == ',') {
    ++k;
    while (k < next.text.size() && isBlank(next.text[k])) ++k;
  }
  const char first = k < next.text.size() ? next.text[k] : '\0';
  const std::string sofar = trimmed(expr);
  // Outside parentheses, an expression that is complete followed by a name is two things:
  // the expression ends and the name starts the next argument ("..., C=comment").
  if (depth <= 0 && !sofar.empty() && isOperandEnd(sofar.back()) && isNameStart(first))
    return false;

  if (ampersand && kind_ == InputKind::DataSet && !ampersandReported) {
    diags_.error({file_, line().number, line().ampersandColumn}, st.subject(),
                 "'&' cannot continue a function expression in a data set",
                 "End the line without '&' and start the next line with ',' in column 1");
    ampersandReported = true;
  }
  enterNextPiece();
  c_.pos = k;
  // Joining keeps the pieces apart only where they would otherwise fuse two names or numbers.
  if (!sofar.empty() && first != '\0' && isOperandEnd(sofar.back()) && isNameChar(first))
    expr = sofar + " ";
  else
    expr = sofar;
  return true;
}

void GroupParser::parseText(Argument& arg) {
  arg.isText = true;
  skipBlanks(false);
  arg.valueWhere = here();
  Value v;
  v.kind = Value::Kind::Word;
  v.where = here();
  v.text = v.written = trimmed(text().substr(c_.pos));
  c_.pos = text().size();
  arg.values.push_back(std::move(v));
}

// Skips the values of an argument that could not be resolved, stopping before the next
// argument so that it is still read.
void GroupParser::skipValues(const StatementSpec& spec) {
  ArgumentSpec anyValue;
  anyValue.type = ValueType::WordOrNumber;
  anyValue.maxValues = kUnlimited;
  while (true) {
    skipToDelimiter();
    const Cursor save = c_;
    const Separator s = readSeparator();
    if (s == Separator::Colon) continue;
    if (s == Separator::Comma && nextIsValue(anyValue, spec, 0)) continue;
    c_ = save;
    return;
  }
}

void GroupParser::skipToDelimiter() {
  int depth = 0;
  while (!atLineEnd()) {
    const char ch = peek();
    if (depth <= 0 && (ch == ',' || ch == ';' || ch == '\\' || ch == ':')) return;
    if (ch == '(') ++depth;
    if (ch == ')') --depth;
    ++c_.pos;
  }
}

void GroupParser::skipStatement() {
  while (true) {
    while (!atLineEnd()) {
      if (peek() == ';') {
        ++c_.pos;
        return;
      }
      ++c_.pos;
    }
    if (!hasNextPiece()) return;
    enterNextPiece();
  }
}

void GroupParser::checkRequired(const Statement& st, const StatementSpec& spec) {
  for (const auto& a : spec.arguments) {
    if (!a.required || st.has(a.name)) continue;
    if (std::find(writtenArguments_.begin(), writtenArguments_.end(), a.name) !=
        writtenArguments_.end())
      continue;
    diags_.error(st.where, st.subject(), "missing required argument " + a.name,
                 "Add " + placeholder(a));
  }
}

}  // namespace

std::vector<Statement> parseStatementGroup(const std::vector<LinePiece>& pieces, InputKind kind,
                                           const std::string& file, Diagnostics& diags,
                                           const std::string& previousSubject) {
  if (pieces.empty()) return {};
  GroupParser parser(pieces, kind, file, diags, previousSubject);
  return parser.parseAll();
}

}  // namespace openmss::language

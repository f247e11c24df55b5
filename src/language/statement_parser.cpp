// Text to statements: one statement group at a time (language/group_parser.hpp) — the
// statement name and id, separators, continuation and recovery after an error. Arguments and
// values are read in argument_parser.cpp.
#include "language/statement_parser.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "language/group_parser.hpp"
#include "language/name_resolution.hpp"
#include "language/number_token.hpp"
#include "language/schema.hpp"

namespace openmss::language::parsing {

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
  CompactLocation idWhere;
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
  // The tree of a large data set is kept whole: no spare capacity (docs/performance.md).
  st.args.shrink_to_fit();
  st.lastLine = line().number;
  if (kind_ == InputKind::DataSet && requireArguments_) checkRequired(st, spec);
  return st;
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

}  // namespace openmss::language::parsing

namespace openmss::language {

std::vector<Statement> parseStatementGroup(const std::vector<LinePiece>& pieces, InputKind kind,
                                           const std::string& file, Diagnostics& diags,
                                           const std::string& previousSubject,
                                           bool requireArguments) {
  if (pieces.empty()) return {};
  parsing::GroupParser parser(pieces, kind, file, diags, previousSubject, requireArguments);
  return parser.parseAll();
}

}  // namespace openmss::language

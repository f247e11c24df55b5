// The arguments of one statement (language/group_parser.hpp): names against the schema,
// values (numbers, ids, words, lists) with their checks, expressions with their continuation
// rules, and text.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include "language/group_parser.hpp"
#include "language/name_resolution.hpp"
#include "language/number_token.hpp"
#include "language/schema.hpp"

namespace openmss::language::parsing {

void GroupParser::parseArguments(Statement& st, const StatementSpec& spec, bool needSeparator,
                                 bool hadSlash) {
  bool separatorPending = false;
  bool slashReported = false;
  CompactLocation separatorWhere;
  while (true) {
    skipBlanks(true);
    const CompactLocation before = here();
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

bool GroupParser::parseArgument(Statement& st, const StatementSpec& spec) {
  skipBlanks(true);
  const CompactLocation where = here();
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
  // A parenthesised list, as ADAMS writes keyword lists (INPUTS=(PRELOAD:REACTION_FORCE)): the
  // parentheses only group the values, which ',' or ':' separate, on one line.
  const bool parenthesised = peek() == '(';
  if (parenthesised) {
    ++c_.pos;
    inParenthesisedList_ = true;
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
    if (parenthesised) {
      skipBlanks(true);
      if (!atLineEnd() && peek() == ')') {
        ++c_.pos;
        break;
      }
      if (!atLineEnd() && (peek() == ',' || peek() == ':')) {
        arg.separators.push_back(peek());
        ++c_.pos;
        continue;
      }
      diags_.error(here(), st.subject(), "the list of " + as.name + " values is not closed",
                   "End the list with ')' on the same line, e.g. " + as.name + "=(A:B)");
      valuesOk = false;
      skipToDelimiter();
      break;
    }
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
  inParenthesisedList_ = false;
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
  v.text = v.written = trimmed(std::string(text().substr(c_.pos)));
  c_.pos = text().size();
  arg.values.push_back(std::move(v));
}

// Skips the values of an argument that could not be resolved, stopping before the next
// argument so that it is still read.

}  // namespace openmss::language::parsing

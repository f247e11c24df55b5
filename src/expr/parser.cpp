// Text to syntax tree: the grammar rules of the recursive-descent parser (expr/parser_detail.hpp)
// and the checks that need no model; the function-call rules are in parser_calls.cpp.
#include "expr/parser.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <string_view>
#include <utility>

#include "expr/compiler.hpp"
#include "expr/lexer.hpp"
#include "expr/name_catalog.hpp"
#include "expr/parser_detail.hpp"

namespace openmss::expr::parsing {

ParseResult Parser::run() {
  ParseResult result;
  if (tokens_.front().kind == TokenKind::End) {
    fail(1, "the expression is empty", "Write a number or a function expression, e.g. 0.");
  } else if (checkParentheses()) {
    Value root = expression();
    if (ok_ && current().kind != TokenKind::End) trailingToken();
    if (ok_ && root.isVector) {
      report(1, "the expression is a vector " + atColumn(1) + ", but a function must be a scalar",
             "Reduce it to a scalar with MAG(v), a dot product v*w, or a component function "
             "(DX, VX, ...).");
    }
    result.root = std::move(root.node);
  }
  result.hostCalls = std::move(hostCalls_);
  result.dataCalls = std::move(dataCalls_);
  result.user = std::move(user_);
  result.errors = std::move(errors_);
  return result;
}

// A syntax error: the rest of the text cannot be read reliably, so parsing stops.
void Parser::fail(int column, std::string message, std::string hint) {
  errors_.push_back({column, std::move(message), std::move(hint)});
  ok_ = false;
}

// A semantic error (unknown name, bad argument): parsing goes on to report more of them.
void Parser::report(int column, std::string message, std::string hint) {
  errors_.push_back({column, std::move(message), std::move(hint)});
}

bool Parser::checkParentheses() {
  std::vector<int> open;
  for (const Token& token : tokens_) {
    if (token.kind == TokenKind::LeftParen) open.push_back(token.column);
    if (token.kind == TokenKind::RightParen) {
      if (open.empty()) {
        fail(token.column,
             "unbalanced parentheses: ')' " + atColumn(token.column) + " has no matching '('",
             "Remove it or add the missing '('.");
        return false;
      }
      open.pop_back();
    }
  }
  if (!open.empty()) {
    fail(open.back(), "unbalanced parentheses: '(' " + atColumn(open.back()) + " is never closed",
         "Add the missing ')'.");
    return false;
  }
  return true;
}

void Parser::trailingToken() {
  const Token& token = current();
  if (token.kind == TokenKind::Comma || token.kind == TokenKind::Colon) {
    fail(token.column,
         describe(token) + " " + atColumn(token.column) + " is outside any argument list",
         "Separators belong inside a function's parentheses.");
    return;
  }
  fail(token.column,
       "expected an operator " + atColumn(token.column) + ", found " + describe(token),
       "Put an operator such as * between two operands; blanks do not multiply.");
}

SyntaxNode Parser::binary(NodeKind kind, int column, SyntaxNode left, SyntaxNode right) {
  return makeNode(kind, column, {std::move(left), std::move(right)});
}

void Parser::vectorMisuse(int column, const std::string& what, const std::string& hint) {
  report(column, what + " " + atColumn(column), hint);
}

// a + b, a - b: both scalars or both vectors.
Value Parser::addValues(NodeKind kind, int column, Value a, Value b) {
  if (a.isVector != b.isVector) {
    vectorMisuse(
        column,
        std::string("'") + (kind == NodeKind::Add ? '+' : '-') + "' between a scalar and a vector",
        "Add scalars to scalars and vectors to vectors.");
    return scalarValue(SyntaxNode{});
  }
  if (!a.isVector) return scalarValue(binary(kind, column, std::move(a.node), std::move(b.node)));
  for (int k = 0; k < 3; ++k) a.parts[k] = binary(kind, column, a.parts[k], b.parts[k]);
  return a;
}

// s*s, s*v, v*s (scaling), v*v (dot product); s/s and v/s.
Value Parser::multiplyValues(NodeKind kind, int column, Value a, Value b) {
  if (kind == NodeKind::Divide && b.isVector) {
    vectorMisuse(column, "'/' by a vector",
                 "Divide by a scalar only; ADAMS has no vector "
                 "division.");
    return scalarValue(SyntaxNode{});
  }
  if (!a.isVector && !b.isVector) {
    return scalarValue(binary(kind, column, std::move(a.node), std::move(b.node)));
  }
  if (a.isVector && b.isVector) return scalarValue(dotProduct(a.parts, b.parts, column));
  Value vector = a.isVector ? std::move(a) : std::move(b);
  const SyntaxNode& factor = a.isVector ? b.node : a.node;
  const bool vectorFirst = a.isVector || kind == NodeKind::Divide;
  for (int k = 0; k < 3; ++k) {
    vector.parts[k] = vectorFirst ? binary(kind, column, vector.parts[k], factor)
                                  : binary(kind, column, factor, vector.parts[k]);
  }
  return vector;
}

// v % w: the cross product.
Value Parser::crossValues(int column, const Value& a, const Value& b) {
  if (!a.isVector || !b.isVector) {
    vectorMisuse(column, "'%' needs a vector on both sides",
                 "'%' is the cross product of two vectors; use '*' for scalars.");
    return scalarValue(SyntaxNode{});
  }
  Value out;
  out.isVector = true;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    out.parts[k] = binary(NodeKind::Subtract, column,
                          binary(NodeKind::Multiply, column, a.parts[i], b.parts[j]),
                          binary(NodeKind::Multiply, column, a.parts[j], b.parts[i]));
  }
  return out;
}

Value Parser::expression() {
  Value left = term();
  while (ok_ && (current().kind == TokenKind::Plus || current().kind == TokenKind::Minus)) {
    const Token& op = advance();
    Value right = term();
    left = addValues(op.kind == TokenKind::Plus ? NodeKind::Add : NodeKind::Subtract, op.column,
                     std::move(left), std::move(right));
  }
  return left;
}

Value Parser::term() {
  Value left = unary();
  while (ok_) {
    const TokenKind kind = current().kind;
    if (kind != TokenKind::Star && kind != TokenKind::Slash && kind != TokenKind::Percent) break;
    const Token& op = advance();
    Value right = unary();
    if (kind == TokenKind::Percent) {
      left = crossValues(op.column, left, right);
    } else {
      left = multiplyValues(kind == TokenKind::Star ? NodeKind::Multiply : NodeKind::Divide,
                            op.column, std::move(left), std::move(right));
    }
  }
  return left;
}

Value Parser::unary() {
  if (current().kind == TokenKind::Plus) {
    advance();
    return unary();
  }
  if (current().kind == TokenKind::Minus) {
    const int column = advance().column;
    Value operand = unary();
    if (!operand.isVector) {
      return scalarValue(makeNode(NodeKind::Negate, column, {std::move(operand.node)}));
    }
    for (SyntaxNode& part : operand.parts) part = makeNode(NodeKind::Negate, column, {part});
    return operand;
  }
  return power();
}

Value Parser::power() {
  Value base = primary();
  if (ok_ && current().kind == TokenKind::Power) {
    const int column = advance().column;
    Value exponent = unary();
    if (base.isVector || exponent.isVector) {
      vectorMisuse(column, "'**' with a vector operand", "'**' works on scalars only.");
      return scalarValue(SyntaxNode{});
    }
    return scalarValue(
        binary(NodeKind::Power, column, std::move(base.node), std::move(exponent.node)));
  }
  return base;
}

Value Parser::primary() {
  const Token& token = current();
  switch (token.kind) {
    case TokenKind::Number: {
      advance();
      return scalarValue(numberNode(token.number, token.column));
    }
    case TokenKind::LeftParen: {
      advance();
      Value inner = expression();
      if (ok_ && current().kind != TokenKind::RightParen) {
        fail(current().column,
             "expected ')' " + atColumn(current().column) + ", found " + describe(current()),
             "Close the parenthesis opened at column " + std::to_string(token.column) + ".");
      }
      if (ok_) advance();
      return inner;
    }
    case TokenKind::Name:
      return name();
    case TokenKind::LeftBracket:
      return vectorLiteral();
    default:
      fail(token.column,
           "expected a number, a name or '(' " + atColumn(token.column) + ", found " +
               describe(token),
           "An operand is missing here.");
      return {};
  }
}

// [a, b, c]: three scalar expressions.
Value Parser::vectorLiteral() {
  const int open = advance().column;
  Value out;
  out.isVector = true;
  for (int k = 0; k < 3 && ok_; ++k) {
    const int column = current().column;
    Value component = expression();
    if (!ok_) break;
    if (component.isVector) {
      vectorMisuse(column,
                   "component " + std::to_string(k + 1) + " of '[' at column " +
                       std::to_string(open) + " is a vector",
                   "Each component of [a, b, c] is a scalar.");
    }
    out.parts[k] = std::move(component.node);
    const TokenKind want = k < 2 ? TokenKind::Comma : TokenKind::RightBracket;
    if (current().kind != want) {
      fail(current().column,
           std::string("expected ") + (k < 2 ? "','" : "']'") + " " + atColumn(current().column) +
               ", found " + describe(current()),
           "Write a vector as [a, b, c], three components in brackets.");
      break;
    }
    advance();
  }
  return out;
}

Value Parser::name() {
  const Token& token = advance();
  const NameInfo* info = findName(token.upper);
  if (token.blankBeforeParen > 0 && (info == nullptr || isCallable(info->kind))) {
    fail(token.blankBeforeParen,
         "blank between " + token.upper + " and '(' " + atColumn(token.blankBeforeParen),
         "ADAMS does not accept a blank between a function name and its '('; write " + token.upper +
             "(...).");
    return {};
  }
  if (token.callFollows) return call(token, info);

  SyntaxNode node;
  node.column = token.column;
  if (info == nullptr) {
    const std::string near = suggestion(token.upper, false);
    report(token.column, "unknown name '" + token.upper + "' " + atColumn(token.column),
           near.empty() ? "The names without arguments are PI, DTOR, RTOD, TIME, MODE, "
                          "HSIZE, ORDER, NJAC, NRHS and CPU; a function call needs '(' right "
                          "after its name."
                        : "Did you mean " + near + "?");
    return scalarValue(std::move(node));
  }
  switch (info->kind) {
    case NameKind::Constant:
      node.number = info->value;
      break;
    case NameKind::Time:
      node.kind = NodeKind::Time;
      break;
    case NameKind::HostVariable:
      node.kind = NodeKind::Host;
      node.hostIndex = hostIndex(HostCall{token.upper, {}, token.column});
      break;
    default:
      report(token.column,
             token.upper + " " + atColumn(token.column) + " needs its arguments in parentheses",
             "Write " + usageOf(*info) + ", with no blank before '('.");
      break;
  }
  return scalarValue(std::move(node));
}

// Reads '(' arguments ')'. Separators are ',' except the one after IF's first argument,
// which must be ':'.
std::vector<Argument> Parser::arguments(const Token& nameToken, bool isIf) {
  std::vector<Argument> args;
  advance();  // '('
  if (current().kind == TokenKind::RightParen) {
    advance();
    return args;
  }
  while (ok_) {
    Argument arg;
    arg.column = current().column;
    Value value = expression();
    if (!ok_) break;
    arg.node = std::move(value.node);
    arg.isVector = value.isVector;
    arg.parts = std::move(value.parts);
    args.push_back(std::move(arg));
    const Token& separator = current();
    if (separator.kind == TokenKind::RightParen) {
      advance();
      break;
    }
    const bool wantColon = isIf && args.size() == 1;
    if (separator.kind == TokenKind::Colon && !wantColon) {
      fail(separator.column,
           "':' " + atColumn(separator.column) + " is only allowed after the first argument of IF",
           "Separate arguments with ','.");
      break;
    }
    if (separator.kind == TokenKind::Comma && wantColon) {
      fail(separator.column,
           "IF " + atColumn(nameToken.column) + " needs ':' after its first argument",
           "Write IF(e1 : e2, e3, e4).");
      break;
    }
    if (separator.kind != TokenKind::Comma && separator.kind != TokenKind::Colon) {
      fail(separator.column,
           "expected ',' or ')' " + atColumn(separator.column) + ", found " + describe(separator),
           "Separate the arguments of " + nameToken.upper + " with ','.");
      break;
    }
    advance();
  }
  return args;
}

bool Parser::checkCount(const Token& nameToken, const NameInfo& info, std::size_t count) {
  const int n = static_cast<int>(count);
  if (n >= info.minArguments && n <= info.maxArguments) return true;
  report(nameToken.column,
         nameToken.upper + " " + atColumn(nameToken.column) + " has " + countPhrase(n) + ", but " +
             nameToken.upper + " takes " + allowedCounts(info),
         "Write " + usageOf(info) + ".");
  return false;
}

// Every argument of a scalar function must be a scalar.
bool Parser::scalarArguments(const Token& nameToken, const std::vector<Argument>& args) {
  bool ok = true;
  for (std::size_t k = 0; k < args.size(); ++k) {
    if (!args[k].isVector) continue;
    report(args[k].column,
           nameToken.upper + " argument " + std::to_string(k + 1) + " " + atColumn(args[k].column) +
               " is a vector, but " + nameToken.upper + " takes scalars",
           "Pass a scalar: MAG(v), a dot product v*w, or a component function.");
    ok = false;
  }
  return ok;
}

bool Parser::containsKind(const SyntaxNode& node, NodeKind kind) {
  if (node.kind == kind) return true;
  for (const SyntaxNode& child : node.children) {
    if (containsKind(child, kind)) return true;
  }
  return false;
}

bool Parser::integerConstant(const std::string& function, int position, const Argument& arg,
                             long& out) {
  const std::string subject =
      function + " argument " + std::to_string(position) + " " + atColumn(arg.column);
  const std::string hint =
      "Arguments of " + function +
      " are ids and flags: write integers, with 0 as the placeholder for an omitted one.";
  const SyntaxNode* literal = &arg.node;
  double sign = 1.0;
  if (literal->kind == NodeKind::Negate) {
    sign = -1.0;
    literal = &literal->children.front();
  }
  if (literal->kind != NodeKind::Number || !isLiteral(arg)) {
    report(arg.column, subject + " must be an integer constant", hint);
    return false;
  }
  const double value = sign * literal->number;
  const Token& first = tokenAtColumn(literal->column);
  if (first.degrees || value != std::trunc(value) || std::abs(value) > 1e15) {
    report(arg.column, subject + " is " + first.spelled + ", not an integer", hint);
    return false;
  }
  out = static_cast<long>(value);
  return true;
}

// True when the argument text is a single number, optionally signed; named constants such
// as PI parse to numbers too but are not ids.
bool Parser::isLiteral(const Argument& arg) const {
  std::size_t k = 0;
  while (k < tokens_.size() && tokens_[k].column < arg.column) ++k;
  if (k < tokens_.size() &&
      (tokens_[k].kind == TokenKind::Minus || tokens_[k].kind == TokenKind::Plus)) {
    ++k;
  }
  if (k + 1 >= tokens_.size() || tokens_[k].kind != TokenKind::Number) return false;
  const TokenKind next = tokens_[k + 1].kind;
  return next == TokenKind::Comma || next == TokenKind::RightParen;
}

const Token& Parser::tokenAtColumn(int column) const {
  for (const Token& token : tokens_) {
    if (token.column == column) return token;
  }
  return tokens_.back();
}

std::size_t Parser::hostIndex(HostCall call) {
  for (std::size_t k = 0; k < hostCalls_.size(); ++k) {
    if (hostCalls_[k].name == call.name && hostCalls_[k].args == call.args) return k;
  }
  hostCalls_.push_back(std::move(call));
  return hostCalls_.size() - 1;
}

}  // namespace openmss::expr::parsing

namespace openmss::expr {

ParseResult parseExpression(const std::string& text) {
  LexResult lexed = tokenize(text);
  if (lexed.error) {
    ParseResult result;
    result.errors.push_back(std::move(*lexed.error));
    return result;
  }
  return parsing::Parser(std::move(lexed.tokens)).run();
}

}  // namespace openmss::expr

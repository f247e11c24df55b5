// Over ~700 lines by intent: one recursive-descent Parser class whose grammar rules call each
// other; splitting it would expose its private state in a header for no reader's benefit.
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

namespace openmss::expr {
namespace {

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({above + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}

bool isCallable(NameKind kind) {
  return kind == NameKind::Builtin || kind == NameKind::Conditional ||
         kind == NameKind::HostFunction || kind == NameKind::Unsupported ||
         kind == NameKind::DataFunction ||
         kind == NameKind::VectorHost || kind == NameKind::VectorFunction ||
         kind == NameKind::User || kind == NameKind::Delay;
}

// The closest known name of the wanted sort, when it is close enough to be a likely typo.
std::string suggestion(const std::string& upper, bool wantCallable) {
  const std::size_t limit = upper.size() <= 3 ? 1 : 2;
  std::string best;
  std::size_t bestDistance = limit + 1;
  for (const NameInfo& info : allNames()) {
    if (isCallable(info.kind) != wantCallable) continue;
    const std::size_t distance = editDistance(upper, info.name);
    if (distance < bestDistance) {
      bestDistance = distance;
      best = std::string(info.name);
    }
  }
  return best;
}

std::string usageOf(const NameInfo& info) {
  if (!info.usage.empty() && info.usage.front() == '(') {
    return std::string(info.name) + std::string(info.usage);
  }
  return std::string(info.usage);
}

std::string countPhrase(int count) {
  return std::to_string(count) + (count == 1 ? " argument" : " arguments");
}

std::string allowedCounts(const NameInfo& info) {
  if (info.minArguments == info.maxArguments) return std::to_string(info.minArguments);
  return std::to_string(info.minArguments) + " to " + std::to_string(info.maxArguments);
}

// A parsed operand: a scalar, or a vector written out as its three scalar components. Vector
// operations (+, -, *, /, %, MAG, UV) expand into scalar trees here, so the compiler and the
// evaluators only ever see scalars.
struct Value {
  SyntaxNode node;                     // the scalar, when !isVector
  bool isVector = false;
  std::array<SyntaxNode, 3> parts;     // x, y, z components, when isVector
};

struct Argument {
  SyntaxNode node;
  int column = 0;  // first character of the argument
  bool isVector = false;
  std::array<SyntaxNode, 3> parts;
};

SyntaxNode numberNode(double value, int column) {
  SyntaxNode node;
  node.kind = NodeKind::Number;
  node.column = column;
  node.number = value;
  return node;
}

SyntaxNode makeNode(NodeKind kind, int column, std::vector<SyntaxNode> children) {
  SyntaxNode node;
  node.kind = kind;
  node.column = column;
  node.children = std::move(children);
  return node;
}

// True when a subtree reads neither TIME nor the host nor model data.
bool constantTree(const SyntaxNode& node) {
  if (node.kind == NodeKind::Time || node.kind == NodeKind::Host ||
      node.kind == NodeKind::DataCall || node.kind == NodeKind::Delay) {
    return false;
  }
  for (const SyntaxNode& child : node.children) {
    if (!constantTree(child)) return false;
  }
  return true;
}

Value scalarValue(SyntaxNode node) {
  Value v;
  v.node = std::move(node);
  return v;
}

SyntaxNode dotProduct(const std::array<SyntaxNode, 3>& a, const std::array<SyntaxNode, 3>& b,
                      int column) {
  SyntaxNode sum = makeNode(NodeKind::Multiply, column, {a[0], b[0]});
  for (int k = 1; k < 3; ++k) {
    sum = makeNode(NodeKind::Add, column,
                   {std::move(sum), makeNode(NodeKind::Multiply, column, {a[k], b[k]})});
  }
  return sum;
}

SyntaxNode magnitude(const std::array<SyntaxNode, 3>& a, int column) {
  SyntaxNode root = makeNode(NodeKind::Call, column, {dotProduct(a, a, column)});
  root.builtin = Builtin::Sqrt;
  return root;
}

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  ParseResult run() {
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

 private:
  const Token& current() const { return tokens_[pos_]; }
  const Token& advance() { return tokens_[pos_++]; }

  // A syntax error: the rest of the text cannot be read reliably, so parsing stops.
  void fail(int column, std::string message, std::string hint) {
    errors_.push_back({column, std::move(message), std::move(hint)});
    ok_ = false;
  }
  // A semantic error (unknown name, bad argument): parsing goes on to report more of them.
  void report(int column, std::string message, std::string hint) {
    errors_.push_back({column, std::move(message), std::move(hint)});
  }

  bool checkParentheses() {
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

  void trailingToken() {
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

  SyntaxNode binary(NodeKind kind, int column, SyntaxNode left, SyntaxNode right) {
    return makeNode(kind, column, {std::move(left), std::move(right)});
  }

  void vectorMisuse(int column, const std::string& what, const std::string& hint) {
    report(column, what + " " + atColumn(column), hint);
  }

  // a + b, a - b: both scalars or both vectors.
  Value addValues(NodeKind kind, int column, Value a, Value b) {
    if (a.isVector != b.isVector) {
      vectorMisuse(column, std::string("'") + (kind == NodeKind::Add ? '+' : '-') +
                               "' between a scalar and a vector",
                   "Add scalars to scalars and vectors to vectors.");
      return scalarValue(SyntaxNode{});
    }
    if (!a.isVector) return scalarValue(binary(kind, column, std::move(a.node), std::move(b.node)));
    for (int k = 0; k < 3; ++k) a.parts[k] = binary(kind, column, a.parts[k], b.parts[k]);
    return a;
  }

  // s*s, s*v, v*s (scaling), v*v (dot product); s/s and v/s.
  Value multiplyValues(NodeKind kind, int column, Value a, Value b) {
    if (kind == NodeKind::Divide && b.isVector) {
      vectorMisuse(column, "'/' by a vector", "Divide by a scalar only; ADAMS has no vector "
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
  Value crossValues(int column, const Value& a, const Value& b) {
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

  Value expression() {
    Value left = term();
    while (ok_ && (current().kind == TokenKind::Plus || current().kind == TokenKind::Minus)) {
      const Token& op = advance();
      Value right = term();
      left = addValues(op.kind == TokenKind::Plus ? NodeKind::Add : NodeKind::Subtract, op.column,
                       std::move(left), std::move(right));
    }
    return left;
  }

  Value term() {
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

  Value unary() {
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

  Value power() {
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

  Value primary() {
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
  Value vectorLiteral() {
    const int open = advance().column;
    Value out;
    out.isVector = true;
    for (int k = 0; k < 3 && ok_; ++k) {
      const int column = current().column;
      Value component = expression();
      if (!ok_) break;
      if (component.isVector) {
        vectorMisuse(column, "component " + std::to_string(k + 1) + " of '[' at column " +
                                 std::to_string(open) + " is a vector",
                     "Each component of [a, b, c] is a scalar.");
      }
      out.parts[k] = std::move(component.node);
      const TokenKind want = k < 2 ? TokenKind::Comma : TokenKind::RightBracket;
      if (current().kind != want) {
        fail(current().column,
             std::string("expected ") + (k < 2 ? "','" : "']'") + " " +
                 atColumn(current().column) + ", found " + describe(current()),
             "Write a vector as [a, b, c], three components in brackets.");
        break;
      }
      advance();
    }
    return out;
  }

  Value name() {
    const Token& token = advance();
    const NameInfo* info = findName(token.upper);
    if (token.blankBeforeParen > 0 && (info == nullptr || isCallable(info->kind))) {
      fail(token.blankBeforeParen,
           "blank between " + token.upper + " and '(' " + atColumn(token.blankBeforeParen),
           "ADAMS does not accept a blank between a function name and its '('; write " +
               token.upper + "(...).");
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
  std::vector<Argument> arguments(const Token& nameToken, bool isIf) {
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
        fail(
            separator.column,
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

  bool checkCount(const Token& nameToken, const NameInfo& info, std::size_t count) {
    const int n = static_cast<int>(count);
    if (n >= info.minArguments && n <= info.maxArguments) return true;
    report(nameToken.column,
           nameToken.upper + " " + atColumn(nameToken.column) + " has " + countPhrase(n) +
               ", but " + nameToken.upper + " takes " + allowedCounts(info),
           "Write " + usageOf(info) + ".");
    return false;
  }

  // Every argument of a scalar function must be a scalar.
  bool scalarArguments(const Token& nameToken, const std::vector<Argument>& args) {
    bool ok = true;
    for (std::size_t k = 0; k < args.size(); ++k) {
      if (!args[k].isVector) continue;
      report(args[k].column,
             nameToken.upper + " argument " + std::to_string(k + 1) + " " +
                 atColumn(args[k].column) + " is a vector, but " + nameToken.upper +
                 " takes scalars",
             "Pass a scalar: MAG(v), a dot product v*w, or a component function.");
      ok = false;
    }
    return ok;
  }

  Value call(const Token& nameToken, const NameInfo* info) {
    const bool isIf = info != nullptr && info->kind == NameKind::Conditional;
    std::vector<Argument> args = arguments(nameToken, isIf);
    SyntaxNode node;
    node.column = nameToken.column;
    if (!ok_) return scalarValue(std::move(node));
    if (info == nullptr) {
      const std::string near = suggestion(nameToken.upper, true);
      report(nameToken.column,
             "unknown function '" + nameToken.upper + "' " + atColumn(nameToken.column),
             near.empty() ? "See docs/expressions.md for the functions available."
                          : "Did you mean " + near + "?");
      return scalarValue(std::move(node));
    }
    if (info->kind == NameKind::VectorFunction) return vectorFunction(nameToken, *info, args);
    if (!scalarArguments(nameToken, args)) return scalarValue(std::move(node));
    switch (info->kind) {
      case NameKind::Builtin:
      case NameKind::Conditional:
        if (!checkCount(nameToken, *info, args.size())) break;
        node.kind = isIf ? NodeKind::If : NodeKind::Call;
        node.builtin = info->builtin;
        for (Argument& arg : args) node.children.push_back(std::move(arg.node));
        break;
      case NameKind::HostFunction:
        return scalarValue(hostCall(nameToken, *info, args));
      case NameKind::VectorHost:
        return vectorHost(nameToken, *info, args);
      case NameKind::DataFunction:
        return scalarValue(dataCall(nameToken, *info, args));
      case NameKind::User:
        return scalarValue(userCall(nameToken, *info, args));
      case NameKind::Delay:
        return scalarValue(delayCall(nameToken, *info, args));
      case NameKind::Unsupported:
        report(nameToken.column,
               nameToken.upper + " " + atColumn(nameToken.column) + " is not supported yet",
               "This function is not available to expressions yet; see "
               "docs/expressions.md for the functions available.");
        break;
      default:
        report(nameToken.column,
               nameToken.upper + " " + atColumn(nameToken.column) + " takes no arguments",
               "Write " + nameToken.upper + " without parentheses.");
        break;
    }
    return scalarValue(std::move(node));
  }

  // DXYZ(i[, j][, k]) = [DX(...), DY(...), DZ(...)], and likewise VXYZ, WXYZ, ACCXYZ, WDTXYZ,
  // FXYZ, TXYZ: three host calls with the same arguments.
  Value vectorHost(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args) {
    // A refused call still yields a (placeholder) vector, so MAG(DXYZ(1.5)) reports the id
    // only, not also "MAG of a scalar".
    Value out;
    out.isVector = true;
    if (!checkCount(nameToken, info, args.size())) return out;
    bool valid = true;  // check the ids once, under the name as written
    for (std::size_t k = 0; k < args.size(); ++k) {
      long id = 0;
      if (!integerConstant(nameToken.upper, static_cast<int>(k) + 1, args[k], id)) valid = false;
    }
    if (!valid) return out;
    const std::string stem = nameToken.upper.substr(0, nameToken.upper.size() - 3);
    const char* axes[3] = {"X", "Y", "Z"};
    for (int k = 0; k < 3; ++k) {
      Token component = nameToken;
      component.upper = stem + axes[k];
      const NameInfo* scalar = findName(component.upper);
      out.parts[k] = hostCall(component, *scalar, args);
    }
    return out;
  }

  // ORIENT(29, n, i[, j]): element n of the direction-cosine matrix R = A_jᵀ A_i, numbered
  // down the columns, so elements 3c+1..3c+3 are axis c of marker i resolved in marker j.
  // `ids` holds i and, when written, j; the call keeps the column of the function name.
  SyntaxNode directionCosine(const Token& nameToken, int element, const std::vector<long>& ids) {
    HostCall cosine{"ORIENT", {29, element}, nameToken.column};
    cosine.args.insert(cosine.args.end(), ids.begin(), ids.end());
    SyntaxNode node;
    node.column = nameToken.column;
    node.kind = NodeKind::Host;
    node.hostIndex = hostIndex(std::move(cosine));
    return node;
  }

  // The marker ids of UVX/UVY/UVZ(i[, k]) (from argument `first` on) or TRANS(v, i[, j]).
  bool markerIds(const Token& nameToken, std::vector<Argument>& args, std::size_t first,
                 std::vector<long>& ids) {
    bool valid = true;
    for (std::size_t k = first; k < args.size(); ++k) {
      long id = 0;
      if (args[k].isVector) {
        report(args[k].column,
               nameToken.upper + " argument " + std::to_string(k + 1) + " " +
                   atColumn(args[k].column) + " is a vector, but it must be a marker id",
               "Write " + std::string(findName(nameToken.upper)->usage) + ".");
        valid = false;
      } else if (!integerConstant(nameToken.upper, static_cast<int>(k) + 1, args[k], id)) {
        valid = false;
      } else {
        ids.push_back(id);
      }
    }
    return valid;
  }

  // UVX(i[, k]) = the x axis of marker i resolved in marker k (ground when k is omitted or 0);
  // UVY and UVZ likewise (ADAMS Solver C++ help, UVX). Three direction cosines.
  Value markerAxis(const Token& nameToken, std::vector<Argument>& args) {
    Value out;
    out.isVector = true;
    std::vector<long> ids;
    if (!markerIds(nameToken, args, 0, ids)) return out;
    const int axis = nameToken.upper[2] - 'X';
    for (int k = 0; k < 3; ++k) out.parts[k] = directionCosine(nameToken, 3 * axis + k + 1, ids);
    return out;
  }

  // TRANS(v, i[, j]): v, written in the axes of marker j (ground when omitted or 0), resolved
  // in the axes of marker i (ADAMS Solver C++ help, TRANS). Component c is UV{X,Y,Z}(i, j) * v.
  Value transform(const Token& nameToken, std::vector<Argument>& args) {
    Value out;
    out.isVector = true;
    std::vector<long> ids;
    if (!markerIds(nameToken, args, 1, ids)) return out;
    for (int c = 0; c < 3; ++c) {
      std::array<SyntaxNode, 3> axis;
      for (int k = 0; k < 3; ++k) axis[k] = directionCosine(nameToken, 3 * c + k + 1, ids);
      out.parts[c] = dotProduct(axis, args[0].parts, nameToken.column);
    }
    return out;
  }

  // MAG(v) = |v|; UV(v) = v / |v|, and the zero vector where v is zero (no direction: ADAMS
  // reuses the last valid one, docs/expressions.md); UVX/UVY/UVZ and TRANS above.
  Value vectorFunction(const Token& nameToken, const NameInfo& info,
                       std::vector<Argument>& args) {
    // A refused call still yields a placeholder of its kind (a vector except for MAG), so
    // the error is reported once, not again as a vector/scalar mismatch around it.
    Value refused;
    refused.isVector = nameToken.upper != "MAG";
    if (!checkCount(nameToken, info, args.size())) return refused;
    if (nameToken.upper.size() == 3 && nameToken.upper.starts_with("UV")) {
      return markerAxis(nameToken, args);
    }
    if (!args[0].isVector) {
      report(args[0].column,
             nameToken.upper + " argument 1 " + atColumn(args[0].column) +
                 " is a scalar, but " + nameToken.upper + " takes a vector",
             "Pass a vector such as DXYZ(i, j) or [a, b, c]; for a scalar use ABS.");
      return refused;
    }
    if (nameToken.upper == "TRANS") return transform(nameToken, args);
    SyntaxNode length = magnitude(args[0].parts, nameToken.column);
    if (nameToken.upper == "MAG") return scalarValue(std::move(length));
    // IF(v*v : -, 0, v_k/|v|): v*v is never negative; the branch taken alone gives the value
    // and the derivative, so the zero vector yields 0 with zero partials rather than 0/0.
    const SyntaxNode lengthSquared = dotProduct(args[0].parts, args[0].parts, nameToken.column);
    Value out;
    out.isVector = true;
    for (int k = 0; k < 3; ++k) {
      SyntaxNode zero = numberNode(0.0, nameToken.column);
      out.parts[k] = makeNode(
          NodeKind::If, nameToken.column,
          {lengthSquared, zero, zero,
           binary(NodeKind::Divide, nameToken.column, args[0].parts[k], length)});
    }
    return out;
  }

  // USER(r1, ..., r30): the constants handed to a user subroutine. It must be the whole
  // expression, as in ADAMS (FUNCTION=USER(...)). Its value comes from the subroutine, so the
  // node itself is a NaN placeholder; the model builder refuses an expression with a USER call
  // until a subroutine is loaded for it.
  SyntaxNode userCall(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args) {
    SyntaxNode node = numberNode(std::numeric_limits<double>::quiet_NaN(), nameToken.column);
    if (!checkCount(nameToken, info, args.size())) return node;
    if (tokens_.front().column != nameToken.column || current().kind != TokenKind::End) {
      report(nameToken.column,
             "USER " + atColumn(nameToken.column) + " must be the whole function",
             "Write FUNCTION=USER(r1, ..., r30) on its own; the subroutine computes the value.");
      return node;
    }
    UserCall user;
    user.column = nameToken.column;
    for (std::size_t k = 0; k < args.size(); ++k) {
      if (!constantTree(args[k].node)) {
        report(args[k].column,
               "USER argument " + std::to_string(k + 1) + " " + atColumn(args[k].column) +
                   " must be a constant",
               "USER passes constants to the subroutine; the subroutine reads the state "
               "itself.");
        continue;
      }
      user.arguments.push_back(foldConstant(args[k].node));
    }
    user_ = std::move(user);
    return node;
  }

  // Host-call arguments are ids and flags: integer constants, optionally signed.
  SyntaxNode hostCall(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args) {
    SyntaxNode node;
    node.column = nameToken.column;
    if (!checkCount(nameToken, info, args.size())) return node;
    HostCall hostCall{nameToken.upper, {}, nameToken.column};
    bool valid = true;
    for (std::size_t k = 0; k < args.size(); ++k) {
      long integer = 0;
      if (!integerConstant(nameToken.upper, static_cast<int>(k) + 1, args[k], integer)) {
        valid = false;
        continue;
      }
      hostCall.args.push_back(integer);
    }
    if (!valid) return node;
    node.kind = NodeKind::Host;
    node.hostIndex = hostIndex(std::move(hostCall));
    return node;
  }

  // AKISPL(x, z, id[, iord]), CUBSPL(x, z, id[, iord]), CURVE(alpha, iord, comp, id): x, z and
  // alpha are expressions; id, iord and comp are integer constants, checked for range here.
  // The id is resolved against the model's data later (Expression::bindSpline/bindCurve).
  SyntaxNode dataCall(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args) {
    SyntaxNode node;
    node.column = nameToken.column;
    if (!checkCount(nameToken, info, args.size())) return node;
    if (nameToken.upper == "INTERP") return interpCall(nameToken, args);
    if (nameToken.upper == "INVPSD") return psdCall(nameToken, args);
    const bool isCurve = nameToken.upper == "CURVE";
    DataCall call{nameToken.upper, 0, 0, 0, nameToken.column, {}};
    const std::vector<std::size_t> integers =
        isCurve ? std::vector<std::size_t>{1, 2, 3} : std::vector<std::size_t>{2, 3};
    bool valid = true;
    long values[4] = {0, 0, 0, 0};
    for (std::size_t k : integers) {
      if (k >= args.size()) continue;
      if (!integerConstant(nameToken.upper, static_cast<int>(k) + 1, args[k], values[k])) {
        valid = false;
      }
    }
    if (!valid) return node;
    const std::size_t orderAt = isCurve ? 1 : 3;
    call.id = values[isCurve ? 3 : 2];
    call.order = static_cast<int>(values[orderAt]);
    if (call.order < 0 || call.order > 2) {
      report(args[orderAt].column,
             nameToken.upper + " argument " + std::to_string(orderAt + 1) + " " +
                 atColumn(args[orderAt].column) + " (iord) is " + std::to_string(values[orderAt]) +
                 ", but it must be 0, 1 or 2",
             "Write 0 for the value, 1 or 2 for the first or second derivative.");
      valid = false;
    }
    if (isCurve) {
      call.component = static_cast<int>(values[2]);
      if (call.component < 1 || call.component > 3) {
        report(args[2].column,
               "CURVE argument 3 " + atColumn(args[2].column) + " (comp) is " +
                   std::to_string(values[2]) + ", but it must be 1, 2 or 3",
               "Write 1, 2 or 3 for the x, y or z component.");
        valid = false;
      }
    }
    if (call.id <= 0) {
      const std::size_t at = isCurve ? 3 : 2;
      report(args[at].column,
             nameToken.upper + " argument " + std::to_string(at + 1) + " " +
                 atColumn(args[at].column) + " must be the id of a " +
                 (isCurve ? "CURVE" : "SPLINE") + " statement",
             "Write the positive id of the data element.");
      valid = false;
    }
    if (!valid) return node;
    node.kind = NodeKind::DataCall;
    node.children.push_back(std::move(args[0].node));
    if (!isCurve) node.children.push_back(std::move(args[1].node));
    node.dataIndex = dataCalls_.size();
    dataCalls_.push_back(std::move(call));
    return node;
  }

  SyntaxNode finishDataCall(DataCall call, SyntaxNode x) {
    SyntaxNode node = makeNode(NodeKind::DataCall, call.column, {std::move(x)});
    node.dataIndex = dataCalls_.size();
    dataCalls_.push_back(std::move(call));
    return node;
  }

  bool positiveId(const std::string& function, std::size_t k, const Argument& arg, long id) {
    if (id > 0) return true;
    report(arg.column,
           function + " argument " + std::to_string(k + 1) + " " + atColumn(arg.column) +
               " must be the id of a SPLINE statement",
           "Write the positive id of the data element.");
    return false;
  }

  // INTERP(x, degree, id[, iord]): a time-series SPLINE read linearly (degree 1) or with a
  // cubic spline (degree 3).
  SyntaxNode interpCall(const Token& nameToken, std::vector<Argument>& args) {
    long values[4] = {0, 0, 0, 0};
    bool valid = true;
    for (std::size_t k = 1; k < args.size(); ++k) {
      if (!integerConstant("INTERP", static_cast<int>(k) + 1, args[k], values[k])) valid = false;
    }
    if (!valid) return SyntaxNode{};
    if (values[1] != 1 && values[1] != 3) {
      report(args[1].column,
             "INTERP argument 2 " + atColumn(args[1].column) + " (degree) is " +
                 std::to_string(values[1]) + ", but it must be 1 or 3",
             "Write 1 for linear or 3 for cubic interpolation.");
      valid = false;
    }
    if (values[3] < 0 || values[3] > 2) {
      report(args[3].column,
             "INTERP argument 4 " + atColumn(args[3].column) + " (iord) is " +
                 std::to_string(values[3]) + ", but it must be 0, 1 or 2",
             "Write 0 for the value, 1 or 2 for the first or second derivative.");
      valid = false;
    }
    if (!positiveId("INTERP", 2, args[2], values[2]) || !valid) return SyntaxNode{};
    DataCall call{"INTERP", values[2], static_cast<int>(values[3]), 0, nameToken.column,
                  {static_cast<double>(values[1])}};
    return finishDataCall(std::move(call), std::move(args[0].node));
  }

  // INVPSD(x, id, f0, f1, nf, linlog, seed): id, nf and linlog are integers; f0, f1 and seed
  // are constants.
  SyntaxNode psdCall(const Token& nameToken, std::vector<Argument>& args) {
    bool valid = true;
    long id = 0, count = 0, logarithmic = 0;
    if (!integerConstant("INVPSD", 2, args[1], id)) valid = false;
    if (!integerConstant("INVPSD", 5, args[4], count)) valid = false;
    if (!integerConstant("INVPSD", 6, args[5], logarithmic)) valid = false;
    double reals[3] = {0.0, 0.0, 0.0};
    const std::size_t realAt[3] = {2, 3, 6};
    for (int r = 0; r < 3; ++r) {
      const Argument& arg = args[realAt[r]];
      if (!constantTree(arg.node)) {
        report(arg.column,
               "INVPSD argument " + std::to_string(realAt[r] + 1) + " " + atColumn(arg.column) +
                   " must be a constant",
               "f0, f1 and seed are numbers fixed for the run.");
        valid = false;
        continue;
      }
      reals[r] = foldConstant(arg.node);
    }
    if (!valid) return SyntaxNode{};
    if (count < 2) {
      report(args[4].column,
             "INVPSD argument 5 " + atColumn(args[4].column) + " (nf) is " +
                 std::to_string(count) + ", but at least 2 frequencies are needed",
             "Give the number of frequencies between f0 and f1, 2 or more.");
      valid = false;
    }
    if (logarithmic != 0 && logarithmic != 1) {
      report(args[5].column,
             "INVPSD argument 6 " + atColumn(args[5].column) + " (linlog) is " +
                 std::to_string(logarithmic) + ", but it must be 0 or 1",
             "Write 0 to read the PSD linearly or 1 to read it in the logarithmic domain.");
      valid = false;
    }
    if (!(reals[0] >= 0.0 && reals[1] > reals[0])) {
      report(args[2].column,
             "INVPSD frequencies " + atColumn(args[2].column) + " must satisfy 0 <= f0 < f1",
             "Give the lowest and the highest frequency to regenerate, in increasing order.");
      valid = false;
    }
    if (!positiveId("INVPSD", 1, args[1], id) || !valid) return SyntaxNode{};
    DataCall call{"INVPSD", id, 0, 0, nameToken.column,
                  {reals[0], reals[1], static_cast<double>(count),
                   static_cast<double>(logarithmic), reals[2]}};
    return finishDataCall(std::move(call), std::move(args[0].node));
  }

  // DELAY(e_delayed, e_delay, e_history[, id]): e_delayed at TIME - max(0, e_delay), read from
  // the history the run records; e_history gives the values before the run's start and must
  // be a function of TIME alone. The id of an interpolation-options ARRAY is not supported:
  // only 0 (the default) is accepted. DELAY inside a DELAY argument is refused (its history
  // would need a history of its own).
  SyntaxNode delayCall(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args) {
    if (!checkCount(nameToken, info, args.size())) return SyntaxNode{};
    bool valid = true;
    if (args.size() == 4) {
      long id = 0;
      if (!integerConstant("DELAY", 4, args[3], id)) {
        valid = false;
      } else if (id != 0) {
        report(args[3].column,
               "DELAY argument 4 " + atColumn(args[3].column) + " names ARRAY/" +
                   std::to_string(id) + " of interpolation options, which is not supported yet",
               "Give 0 or omit the argument: OpenMSS interpolates the history with cubics "
               "(docs/expressions.md, \"DELAY\").");
        valid = false;
      }
    }
    for (std::size_t k = 0; k < 3; ++k) {
      if (!containsKind(args[k].node, NodeKind::Delay)) continue;
      report(args[k].column,
             "DELAY argument " + std::to_string(k + 1) + " " + atColumn(args[k].column) +
                 " contains another DELAY, which is not supported",
             "Delay a VARIABLE that holds the inner DELAY instead.");
      valid = false;
    }
    if (containsKind(args[2].node, NodeKind::Host) ||
        containsKind(args[2].node, NodeKind::DataCall)) {
      report(args[2].column,
             "DELAY argument 3 " + atColumn(args[2].column) +
                 " (the history before the start) must be a function of TIME or a constant",
             "Write the history with TIME, numbers and the general functions (STEP, SIN, ...), "
             "without measures or SPLINE data.");
      valid = false;
    }
    if (!valid) return SyntaxNode{};
    SyntaxNode node = makeNode(NodeKind::Delay, nameToken.column,
                               {std::move(args[0].node), std::move(args[1].node),
                                std::move(args[2].node)});
    node.delayIndex = delayCount_++;
    return node;
  }

  static bool containsKind(const SyntaxNode& node, NodeKind kind) {
    if (node.kind == kind) return true;
    for (const SyntaxNode& child : node.children) {
      if (containsKind(child, kind)) return true;
    }
    return false;
  }

  bool integerConstant(const std::string& function, int position, const Argument& arg, long& out) {
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
  bool isLiteral(const Argument& arg) const {
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

  const Token& tokenAtColumn(int column) const {
    for (const Token& token : tokens_) {
      if (token.column == column) return token;
    }
    return tokens_.back();
  }

  std::size_t hostIndex(HostCall call) {
    for (std::size_t k = 0; k < hostCalls_.size(); ++k) {
      if (hostCalls_[k].name == call.name && hostCalls_[k].args == call.args) return k;
    }
    hostCalls_.push_back(std::move(call));
    return hostCalls_.size() - 1;
  }

  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  bool ok_ = true;
  std::vector<ExpressionError> errors_;
  std::vector<HostCall> hostCalls_;
  std::vector<DataCall> dataCalls_;
  std::optional<UserCall> user_;
  std::size_t delayCount_ = 0;
};

}  // namespace

ParseResult parseExpression(const std::string& text) {
  LexResult lexed = tokenize(text);
  if (lexed.error) {
    ParseResult result;
    result.errors.push_back(std::move(*lexed.error));
    return result;
  }
  return Parser(std::move(lexed.tokens)).run();
}

}  // namespace openmss::expr

#include "expr/parser.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <utility>

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
         kind == NameKind::Vector || kind == NameKind::DataFunction;
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

struct Argument {
  SyntaxNode node;
  int column = 0;  // first character of the argument
};

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  ParseResult run() {
    ParseResult result;
    if (tokens_.front().kind == TokenKind::End) {
      fail(1, "the expression is empty", "Write a number or a function expression, e.g. 0.");
    } else if (checkParentheses()) {
      SyntaxNode root = expression();
      if (ok_ && current().kind != TokenKind::End) trailingToken();
      result.root = std::move(root);
    }
    result.hostCalls = std::move(hostCalls_);
    result.dataCalls = std::move(dataCalls_);
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
    SyntaxNode node;
    node.kind = kind;
    node.column = column;
    node.children.push_back(std::move(left));
    node.children.push_back(std::move(right));
    return node;
  }

  SyntaxNode expression() {
    SyntaxNode left = term();
    while (ok_ && (current().kind == TokenKind::Plus || current().kind == TokenKind::Minus)) {
      const Token& op = advance();
      SyntaxNode right = term();
      left = binary(op.kind == TokenKind::Plus ? NodeKind::Add : NodeKind::Subtract, op.column,
                    std::move(left), std::move(right));
    }
    return left;
  }

  SyntaxNode term() {
    SyntaxNode left = unary();
    while (ok_) {
      const TokenKind kind = current().kind;
      if (kind == TokenKind::Percent) {
        vectorsNotSupported(current().column, "'%'");
        break;
      }
      if (kind != TokenKind::Star && kind != TokenKind::Slash) break;
      const Token& op = advance();
      SyntaxNode right = unary();
      left = binary(kind == TokenKind::Star ? NodeKind::Multiply : NodeKind::Divide, op.column,
                    std::move(left), std::move(right));
    }
    return left;
  }

  SyntaxNode unary() {
    if (current().kind == TokenKind::Plus) {
      advance();
      return unary();
    }
    if (current().kind == TokenKind::Minus) {
      const int column = advance().column;
      SyntaxNode node;
      node.kind = NodeKind::Negate;
      node.column = column;
      node.children.push_back(unary());
      return node;
    }
    return power();
  }

  SyntaxNode power() {
    SyntaxNode base = primary();
    if (ok_ && current().kind == TokenKind::Power) {
      const int column = advance().column;
      SyntaxNode exponent = unary();
      return binary(NodeKind::Power, column, std::move(base), std::move(exponent));
    }
    return base;
  }

  SyntaxNode primary() {
    const Token& token = current();
    switch (token.kind) {
      case TokenKind::Number: {
        advance();
        SyntaxNode node;
        node.kind = NodeKind::Number;
        node.column = token.column;
        node.number = token.number;
        return node;
      }
      case TokenKind::LeftParen: {
        advance();
        SyntaxNode inner = expression();
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
        vectorsNotSupported(token.column, "'['");
        return {};
      default:
        fail(token.column,
             "expected a number, a name or '(' " + atColumn(token.column) + ", found " +
                 describe(token),
             "An operand is missing here.");
        return {};
    }
  }

  void vectorsNotSupported(int column, const std::string& what) {
    fail(column, "vector expressions are not supported yet: " + what + " " + atColumn(column),
         "Write the scalar components instead (DX, DY, DZ, VX, ...).");
  }

  SyntaxNode name() {
    const Token& token = advance();
    const NameInfo* info = findName(token.upper);
    if (token.blankBeforeParen > 0 && (info == nullptr || isCallable(info->kind))) {
      fail(token.blankBeforeParen,
           "blank between " + token.upper + " and '(' " + atColumn(token.blankBeforeParen),
           "ADAMS does not accept a blank between a function name and its '('; write " +
               token.upper + "(...).");
      return {};
    }
    if (info != nullptr && info->kind == NameKind::Vector) {
      vectorsNotSupported(token.column, token.upper);
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
      return node;
    }
    switch (info->kind) {
      case NameKind::Constant:
        node.number = info->value;
        return node;
      case NameKind::Time:
        node.kind = NodeKind::Time;
        return node;
      case NameKind::HostVariable:
        node.kind = NodeKind::Host;
        node.hostIndex = hostIndex(HostCall{token.upper, {}, token.column});
        return node;
      default:
        report(token.column,
               token.upper + " " + atColumn(token.column) + " needs its arguments in parentheses",
               "Write " + usageOf(*info) + ", with no blank before '('.");
        return node;
    }
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
      arg.node = expression();
      if (!ok_) break;
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

  SyntaxNode call(const Token& nameToken, const NameInfo* info) {
    const bool isIf = info != nullptr && info->kind == NameKind::Conditional;
    std::vector<Argument> args = arguments(nameToken, isIf);
    SyntaxNode node;
    node.column = nameToken.column;
    if (!ok_) return node;
    if (info == nullptr) {
      const std::string near = suggestion(nameToken.upper, true);
      report(nameToken.column,
             "unknown function '" + nameToken.upper + "' " + atColumn(nameToken.column),
             near.empty() ? "See docs/expressions.md for the functions available."
                          : "Did you mean " + near + "?");
      return node;
    }
    switch (info->kind) {
      case NameKind::Builtin:
      case NameKind::Conditional:
        if (!checkCount(nameToken, *info, args.size())) return node;
        node.kind = isIf ? NodeKind::If : NodeKind::Call;
        node.builtin = info->builtin;
        for (Argument& arg : args) node.children.push_back(std::move(arg.node));
        return node;
      case NameKind::HostFunction:
        return hostCall(nameToken, *info, args);
      case NameKind::DataFunction:
        return dataCall(nameToken, *info, args);
      case NameKind::Unsupported:
        report(nameToken.column,
               nameToken.upper + " " + atColumn(nameToken.column) + " is not supported yet",
               nameToken.upper == "USER"
                   ? "User subroutines are not available yet; write the force as an expression."
                   : "This function is not available to expressions yet; see "
                     "docs/expressions.md for the functions available.");
        return node;
      default:
        report(nameToken.column,
               nameToken.upper + " " + atColumn(nameToken.column) + " takes no arguments",
               "Write " + nameToken.upper + " without parentheses.");
        return node;
    }
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
    const bool isCurve = nameToken.upper == "CURVE";
    DataCall call{nameToken.upper, 0, 0, 0, nameToken.column};
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

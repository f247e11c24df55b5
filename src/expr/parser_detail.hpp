#pragma once
// Internal to expr/: the recursive-descent Parser behind parseExpression (expr/parser.hpp). Its
// grammar rules live in parser.cpp, the function-call rules (host, data, vector, user, DELAY,
// INTERP, PSD calls) in parser_calls.cpp, and the free helpers in parser_support.cpp. Nothing
// outside expr/ includes this header.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "expr/lexer.hpp"
#include "expr/name_catalog.hpp"
#include "expr/parser.hpp"

namespace openmss::expr::parsing {

// A parsed operand: a scalar, or a vector written out as its three scalar components. Vector
// operations (+, -, *, /, %, MAG, UV) expand into scalar trees here, so the compiler and the
// evaluators only ever see scalars.
struct Value {
  SyntaxNode node;  // the scalar, when !isVector
  bool isVector = false;
  std::array<SyntaxNode, 3> parts;  // x, y, z components, when isVector
};

struct Argument {
  SyntaxNode node;
  int column = 0;  // first character of the argument
  bool isVector = false;
  std::array<SyntaxNode, 3> parts;
};

std::size_t editDistance(std::string_view a, std::string_view b);
bool isCallable(NameKind kind);
std::string suggestion(const std::string& upper, bool wantCallable);
std::string usageOf(const NameInfo& info);
std::string countPhrase(int count);
std::string allowedCounts(const NameInfo& info);
SyntaxNode numberNode(double value, int column);
SyntaxNode makeNode(NodeKind kind, int column, std::vector<SyntaxNode> children);
bool constantTree(const SyntaxNode& node);
Value scalarValue(SyntaxNode node);
SyntaxNode dotProduct(const std::array<SyntaxNode, 3>& a, const std::array<SyntaxNode, 3>& b,
                      int column);
SyntaxNode magnitude(const std::array<SyntaxNode, 3>& a, int column);

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : tokens_(std::move(tokens)) {}

  ParseResult run();

 private:
  // Grammar rules and checks: parser.cpp. Call rules: parser_calls.cpp.
  const Token& current() const { return tokens_[pos_]; }
  const Token& advance() { return tokens_[pos_++]; }

  void fail(int column, std::string message, std::string hint);
  void report(int column, std::string message, std::string hint);
  bool checkParentheses();
  void trailingToken();
  SyntaxNode binary(NodeKind kind, int column, SyntaxNode left, SyntaxNode right);
  void vectorMisuse(int column, const std::string& what, const std::string& hint);
  Value addValues(NodeKind kind, int column, Value a, Value b);
  Value multiplyValues(NodeKind kind, int column, Value a, Value b);
  Value crossValues(int column, const Value& a, const Value& b);
  Value expression();
  Value term();
  Value unary();
  Value power();
  Value primary();
  Value vectorLiteral();
  Value name();
  std::vector<Argument> arguments(const Token& nameToken, bool isIf);
  bool checkCount(const Token& nameToken, const NameInfo& info, std::size_t count);
  bool scalarArguments(const Token& nameToken, const std::vector<Argument>& args);
  Value call(const Token& nameToken, const NameInfo* info);
  Value vectorHost(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args);
  SyntaxNode directionCosine(const Token& nameToken, int element, const std::vector<long>& ids);
  bool markerIds(const Token& nameToken, std::vector<Argument>& args, std::size_t first,
                 std::vector<long>& ids);
  Value markerAxis(const Token& nameToken, std::vector<Argument>& args);
  Value transform(const Token& nameToken, std::vector<Argument>& args);
  Value vectorFunction(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args);
  SyntaxNode userCall(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args);
  SyntaxNode hostCall(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args);
  SyntaxNode dataCall(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args);
  SyntaxNode finishDataCall(DataCall call, SyntaxNode x);
  bool positiveId(const std::string& function, std::size_t k, const Argument& arg, long id);
  SyntaxNode interpCall(const Token& nameToken, std::vector<Argument>& args);
  SyntaxNode psdCall(const Token& nameToken, std::vector<Argument>& args);
  SyntaxNode delayCall(const Token& nameToken, const NameInfo& info, std::vector<Argument>& args);
  static bool containsKind(const SyntaxNode& node, NodeKind kind);
  bool integerConstant(const std::string& function, int position, const Argument& arg, long& out);
  bool isLiteral(const Argument& arg) const;
  const Token& tokenAtColumn(int column) const;
  std::size_t hostIndex(HostCall call);
  std::vector<Token> tokens_;
  std::size_t pos_ = 0;
  bool ok_ = true;
  std::vector<ExpressionError> errors_;
  std::vector<HostCall> hostCalls_;
  std::vector<DataCall> dataCalls_;
  std::optional<UserCall> user_;
  std::size_t delayCount_ = 0;
};

}  // namespace openmss::expr::parsing

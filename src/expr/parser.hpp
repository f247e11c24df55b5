#pragma once
// Text to syntax tree. FORTRAN-77 precedence, ADAMS extensions (IF with ':', degrees suffix),
// name resolution against the catalog and the checks that need no model: argument counts,
// integer-constant arguments of host calls, unsupported and unknown names.

#include <optional>
#include <string>
#include <vector>

#include "expr/expression.hpp"
#include "expr/expression_error.hpp"
#include "expr/syntax_tree.hpp"

namespace openmss::expr {

struct ParseResult {
  SyntaxNode root;
  std::vector<HostCall> hostCalls;      // deduplicated, first-appearance order
  std::vector<DataCall> dataCalls;      // one per call, in order of appearance
  std::optional<UserCall> user;         // FUNCTION=USER(...)
  std::vector<ExpressionError> errors;  // empty on success

  bool ok() const { return errors.empty(); }
};

// Grammar (lowest to highest precedence):
//   expression := term { ('+' | '-') term }
//   term       := unary { ('*' | '/') unary }
//   unary      := ('+' | '-') unary | power
//   power      := primary [ '**' unary ]           right-associative through `unary`
//   primary    := number | name | name'(' arguments ')' | '(' expression ')'
// A sign on the left of ** applies to the whole power (-2**2 = -4); one on the right belongs to
// the exponent (2**-1 = 0.5), so -A**-B = -(A**(-B)).
ParseResult parseExpression(const std::string& text);

}  // namespace openmss::expr

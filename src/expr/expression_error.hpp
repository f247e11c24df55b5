#pragma once
// A problem found in an expression's text, located by its column inside the expression. The
// lexer and parser produce these without knowing where the expression sits in a file;
// Expression::parse turns them into Diagnostics at the caller's SourceLocation.

#include <string>

namespace openmss::expr {

struct ExpressionError {
  int column = 0;       // 1-based column of the offending character within the expression
  std::string message;  // names the column, e.g. "... at column 12 of the expression"
  std::string hint;     // what to change
};

// "at column 12 of the expression": the phrase every message uses, so that users can count
// columns the same way whether or not the file position is known.
inline std::string atColumn(int column) {
  return "at column " + std::to_string(column) + " of the expression";
}

}  // namespace openmss::expr

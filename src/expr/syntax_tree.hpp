#pragma once
// The parsed form of an expression, before compilation: a tree that keeps every operation as
// written (nothing is folded yet) and the columns needed for diagnostics.

#include <cstddef>
#include <vector>

#include "expr/builtin.hpp"

namespace openmss::expr {

enum class NodeKind {
  Number,    // a literal or a named constant (PI, DTOR, RTOD), already a double
  Time,      // TIME
  Host,      // a host call; hostIndex refers to the parser's deduplicated list
  Negate,    // -a
  Add,       // a + b
  Subtract,  // a - b
  Multiply,  // a * b
  Divide,    // a / b
  Power,     // a ** b
  Call,      // a built-in function, children are the arguments
  If,        // IF(e1 : e2, e3, e4), children in that order
  DataCall,  // AKISPL, CUBSPL, CURVE: children are the real arguments (x[, z] or alpha),
             // dataIndex refers to the parser's list of data calls
  Delay,     // DELAY(e_delayed, e_delay, e_history): children in that order; delayIndex
             // numbers the DELAY calls of the expression from 0 in order of appearance
};

struct SyntaxNode {
  NodeKind kind = NodeKind::Number;
  int column = 0;                  // where the construct starts in the expression
  double number = 0.0;             // Number
  Builtin builtin = Builtin::Abs;  // Call
  std::size_t hostIndex = 0;       // Host
  std::size_t dataIndex = 0;       // DataCall
  std::size_t delayIndex = 0;      // Delay
  std::vector<SyntaxNode> children;
};

}  // namespace openmss::expr

#pragma once
// Syntax tree to flat program. Subtrees that depend on neither TIME nor a host call are folded
// to one constant at compile time (IF with a constant condition keeps only the chosen branch),
// so evaluation touches only the parts that vary.

#include <cstddef>

#include "expr/program.hpp"
#include "expr/syntax_tree.hpp"

namespace openmss::expr {

// Host call k is loaded into slot k; `hostCount` is the size of the parser's host-call list.
ProgramCode compileProgram(const SyntaxNode& root, std::size_t hostCount);

// The value of a subtree that depends on neither TIME nor host values.
double foldConstant(const SyntaxNode& node);

}  // namespace openmss::expr

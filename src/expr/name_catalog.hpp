#pragma once
// Every name the expression language knows: constants, the functions evaluated here, the host
// calls whose values the mechanics supply, and names that are recognised but not supported yet.
// The parser consults it to resolve a name and check an argument count; nothing here is used
// during evaluation.

#include <string_view>
#include <vector>

#include "expr/builtin.hpp"

namespace openmss::expr {

enum class NameKind {
  Constant,      // PI, DTOR, RTOD: folded to a number
  Time,          // TIME
  Builtin,       // evaluated by this module
  Conditional,   // IF(e1 : e2, e3, e4)
  HostFunction,  // DX(...), JOINT(...), VARVAL(...): value supplied by the host
  HostVariable,  // MODE, HSIZE, ...: zero-argument host calls, written without parentheses
  DataFunction,  // AKISPL, CUBSPL, CURVE: expression arguments and the id of model data
  Unsupported,   // recognised, refused with "not supported yet" (DELAY, AO, ...)
  VectorHost,    // DXYZ, VXYZ, ...: the three components of a host measure (DX, DY, DZ, ...)
  VectorFunction,  // MAG(v), UV(v), TRANS(v, i[, j]), UVX/UVY/UVZ(i[, k]): vector functions
  User,          // USER(r1, ..., r30): constants for a user subroutine
  Delay,         // DELAY(e_delayed, e_delay, e_history[, id]): reads the run's history
};

struct NameInfo {
  std::string_view name;  // canonical upper case
  NameKind kind;
  int minArguments;
  int maxArguments;
  Builtin builtin;         // for NameKind::Builtin
  double value;            // for NameKind::Constant
  std::string_view usage;  // how to write a call, quoted in argument-count diagnostics
};

// The entry for an upper-case name, or nullptr.
const NameInfo* findName(std::string_view upperName);

// Every known name, for "did you mean" suggestions.
const std::vector<NameInfo>& allNames();

}  // namespace openmss::expr

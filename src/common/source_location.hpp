#pragma once
// Where a piece of input text came from: every statement, argument and diagnostic carries one.

#include <string>

namespace openmss {

struct SourceLocation {
  std::string file;  // path as the user gave it (or "<command line>", "<stdin>")
  int line = 0;      // 1-based physical line; 0 when unknown
  int column = 0;    // 1-based column; 0 when unknown

  bool known() const { return line > 0; }
};

}  // namespace openmss

#pragma once
// Diagnostics of the program's own steps (reading a command file, `check`, `eval`) printed on
// stderr, one per line as format() writes them. The Session echoes its own
// (commands/session.cpp).

#include <cstdio>

#include "common/diagnostics.hpp"

namespace openmss::app {

inline void printDiagnostics(const Diagnostics& d) {
  for (const auto& x : d.all()) std::fprintf(stderr, "%s\n", format(x).c_str());
}

}  // namespace openmss::app

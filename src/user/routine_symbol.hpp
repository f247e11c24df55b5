#pragma once
// Which symbol of which library runs an ADAMS routine (docs/user-subroutines.md, "Which
// library, which symbol"): ROUTINE=lib::name or the default library, and the C-style name
// tried before the FORTRAN spellings; the symbol found decides the calling convention.

#include <memory>
#include <string>

#include "user/user_library.hpp"

namespace openmss::user {

struct ResolvedRoutine {
  std::shared_ptr<Library> library;
  void* address = nullptr;
  bool fortran = false;
  std::string symbol;
};

// `adamsName` is ADAMS's default name in upper case (SFOSUB, FIESUB, SPLINE_READ). False with
// the reason in `error` (no library named, the library does not load, no such symbol).
bool resolveRoutine(const std::string& adamsName, const RoutineName& routine,
                    const std::string& baseDirectory, ResolvedRoutine& out, std::string& error);

}  // namespace openmss::user

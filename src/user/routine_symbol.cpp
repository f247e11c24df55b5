#include "user/routine_symbol.hpp"

#include <cctype>
#include <utility>
#include <vector>

#include "common/ascii_case.hpp"
#include "user/element_call.hpp"

namespace openmss::user {
namespace {

// ADAMS tells a C-style routine by its mixed-case name: first letter upper case, no other
// upper-case letter (docs/user-subroutines.md, "Which library, which symbol").
bool mixedCase(const std::string& n) {
  if (n.empty() || !std::isupper(static_cast<unsigned char>(n[0]))) return false;
  for (size_t k = 1; k < n.size(); ++k)
    if (std::isupper(static_cast<unsigned char>(n[k]))) return false;
  return true;
}

}  // namespace

bool resolveRoutine(const std::string& adamsName, const RoutineName& routine,
                    const std::string& baseDirectory, ResolvedRoutine& out, std::string& error) {
  const std::string libName = routine.library.empty() ? defaultLibrary() : routine.library;
  if (libName.empty()) {
    error = "FUNCTION=USER(...) needs the user subroutine " + adamsName +
            (routine.name.empty() ? "" : " (" + routine.name + ")") +
            ", and no user library is named: the statement has no ROUTINE=lib::name and no "
            "default library was given (openmss run --user-library LIB)";
    return false;
  }
  std::string why;
  detail::anchorUtilities();
  out.library = Library::open(libName, baseDirectory, why);
  if (!out.library) {
    error = "cannot load the user library " + libName + " for " + adamsName +
            (routine.name.empty() ? "" : " (" + routine.name + ")") + ": " + why;
    return false;
  }
  std::vector<std::pair<std::string, bool>> tried;  // (symbol, fortran), in order
  if (routine.name.empty()) {
    const std::string c = adamsName.substr(0, 1) + toLowerAscii(adamsName.substr(1));
    tried = {{c, false},
             {toLowerAscii(adamsName) + "_", true},
             {adamsName, true},
             {toLowerAscii(adamsName), true}};
  } else {
    const std::string& n = routine.name;
    tried = {{n, !mixedCase(n)}, {toLowerAscii(n) + "_", true}, {toUpperAscii(n), true}};
  }
  for (const auto& [name, fortran] : tried)
    if (void* p = out.library->symbol(name)) {
      out.address = p;
      out.fortran = fortran;
      out.symbol = name;
      return true;
    }
  std::string list;
  for (const auto& t : tried) list += (list.empty() ? "" : ", ") + t.first;
  error = "the user library " + out.library->path() + " exports no " + adamsName +
          " routine (looked for " + list + ")";
  return false;
}

}  // namespace openmss::user

#pragma once
// Shared libraries of user-written subroutines (docs/language.md, "User-written
// subroutines"): which library a statement names (ROUTINE=lib::name, INTERFACE=, or the
// default library of `openmss run --user-library`, ADAMS's run-user mode), and the POSIX
// loading of it. Only this module calls dlopen/dlsym.

#include <cstring>
#include <memory>
#include <string>
#include <vector>

namespace openmss::user {

// A symbol's address (Library::symbol) as the function it is.
template <class Fn>
Fn* asFunction(void* address) {
  Fn* f = nullptr;
  static_assert(sizeof f == sizeof address);
  std::memcpy(&f, &address, sizeof f);  // POSIX guarantees data and code pointers agree
  return f;
}

// ROUTINE=lib::name as ADAMS splits it: "lib::name", "::name" or "name" (default library),
// "lib::" (default routine name). Either part may come back empty.
struct RoutineName {
  std::string library;
  std::string name;
};
RoutineName splitRoutineName(const std::string& text);

// The default library: the one `openmss run --user-library PATH` names (empty: none). A
// process-wide setting, as ADAMS's run-user mode is for the solver process.
void setDefaultLibrary(const std::string& path);
const std::string& defaultLibrary();

class Library {
 public:
  // Opens library `name` for a data set in `baseDirectory`. `name` may be a path (absolute,
  // or relative to the data set's directory) or a bare name tried as NAME, NAME.so and
  // libNAME.so in the data set's directory, then in the working directory, then on the
  // dynamic loader's search path. On failure returns null and says why in `why`.
  static std::shared_ptr<Library> open(const std::string& name, const std::string& baseDirectory,
                                       std::string& why);
  ~Library();
  Library(const Library&) = delete;
  Library& operator=(const Library&) = delete;

  // The address of an exported symbol, or null.
  void* symbol(const std::string& name) const;
  const std::string& path() const { return path_; }

 private:
  Library(void* handle, std::string path) : handle_(handle), path_(std::move(path)) {}
  void* handle_;
  std::string path_;
};

}  // namespace openmss::user

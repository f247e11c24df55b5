#include "user/save_routines.hpp"

#include <unistd.h>

#include <cstdio>
#include <memory>

#include "user/element_call.hpp"
#include "user/routine_guard.hpp"
#include "user/user_library.hpp"

namespace openmss::user {
namespace {

using Routine = void(int, int*);

// The routine `name` of the default library, or null (no library, no such routine).
Routine* find(const char* name, const std::string& baseDirectory, std::shared_ptr<Library>& library,
              std::string& error) {
  if (defaultLibrary().empty()) return nullptr;
  detail::anchorUtilities();
  std::string why;
  library = Library::open(defaultLibrary(), baseDirectory, why);
  if (!library) {
    error = "cannot load the user library " + defaultLibrary() + " for " + name + ": " + why;
    return nullptr;
  }
  void* address = library->symbol(name);
  return address ? asFunction<Routine>(address) : nullptr;
}

// Calls `routine` with a descriptor on a scratch file holding `input`; returns what the file
// holds afterwards.
UserSaveData call(Routine* routine, const char* name, const std::string& input) {
  UserSaveData r;
  r.called = true;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::tmpfile(), &std::fclose);
  if (!file) {
    r.error = std::string("no scratch file for ") + name;
    return r;
  }
  const int fd = fileno(file.get());
  if (!input.empty() &&
      ::write(fd, input.data(), input.size()) != static_cast<ssize_t>(input.size())) {
    r.error = std::string("cannot write the scratch file for ") + name;
    return r;
  }
  ::lseek(fd, 0, SEEK_SET);
  int ierr = 0;
  installCrashGuard();
  const GuardResult g = guardedCall([&] { routine(fd, &ierr); }, name, 0.0);
  if (g.signal != 0) {
    r.error = std::string(name) + ": " + g.text;
    return r;
  }
  if (ierr != 0) {
    r.error = std::string(name) + " returned IERR = " + std::to_string(ierr);
    return r;
  }
  ::lseek(fd, 0, SEEK_SET);
  char buffer[4096];
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;)
    r.bytes.append(buffer, static_cast<std::size_t>(n));
  return r;
}

}  // namespace

UserSaveData callSavsub(const std::string& baseDirectory) {
  std::shared_ptr<Library> library;
  UserSaveData r;
  Routine* routine = find("Savsub", baseDirectory, library, r.error);
  return routine ? call(routine, "SAVSUB (Savsub)", "") : r;
}

UserSaveData callRelsub(const std::string& bytes, const std::string& baseDirectory) {
  std::shared_ptr<Library> library;
  UserSaveData r;
  Routine* routine = find("Relsub", baseDirectory, library, r.error);
  if (!routine) return r;
  r = call(routine, "RELSUB (Relsub)", bytes);
  r.bytes.clear();
  return r;
}

}  // namespace openmss::user

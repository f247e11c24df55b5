#include "user/save_routines.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "common/ascii_case.hpp"
#include "user/element_call.hpp"
#include "user/routine_guard.hpp"
#include "user/user_library.hpp"

namespace openmss::user {
namespace {

using CRoutine = void(int, int*);
using F77Routine = void(int*, int*);

// The FORTRAN unit OpenMSS connects for a FORTRAN SAVSUB/RELSUB (ADAMS's number is not
// public; 91 keeps clear of the preconnected 0, 5, 6 and of the small numbers user code picks).
constexpr int kFortranUnit = 91;

struct Found {
  std::shared_ptr<Library> library;
  void* address = nullptr;
  bool fortran = false;
  std::string symbol;
};

// The routine of the default library (`c`: "Savsub"; then `f77`: "savsub_", "SAVSUB",
// "savsub"), or no address (no library, no such routine).
Found find(const char* c, const char* f77, const std::string& baseDirectory, std::string& error) {
  Found f;
  if (defaultLibrary().empty()) return f;
  detail::anchorUtilities();
  std::string why;
  f.library = Library::open(defaultLibrary(), baseDirectory, why);
  if (!f.library) {
    error = "cannot load the user library " + defaultLibrary() + " for " + f77 + ": " + why;
    return f;
  }
  const std::string lower = toLowerAscii(f77);
  for (const auto& [name, fortran] :
       {std::pair{std::string(c), false}, std::pair{lower + "_", true},
        std::pair{std::string(f77), true}, std::pair{lower, true}})
    if (void* p = f.library->symbol(name)) {
      f.address = p;
      f.fortran = fortran;
      f.symbol = name;
      return f;
    }
  return f;
}

std::string readAll(int fd) {
  std::string bytes;
  ::lseek(fd, 0, SEEK_SET);
  char buffer[4096];
  for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;)
    bytes.append(buffer, static_cast<std::size_t>(n));
  return bytes;
}

// Runs the routine under the crash guard with IUNIT `unit`; the error text, empty when done.
std::string guarded(const Found& f, const std::string& name, int unit) {
  int ierr = 0;
  installCrashGuard();
  const GuardResult g = guardedCall(
      [&] {
        if (f.fortran) {
          int u = unit;
          asFunction<F77Routine>(f.address)(&u, &ierr);
        } else {
          asFunction<CRoutine>(f.address)(unit, &ierr);
        }
      },
      name, 0.0);
  if (g.signal != 0) return name + ": " + g.text;
  if (ierr != 0) return name + " returned IERR = " + std::to_string(ierr);
  return {};
}

// The scratch file holding `input`, for both conventions: a named file (a FORTRAN unit is
// connected by name), open for reading and writing, removed when done.
struct Scratch {
  std::string path;
  int fd = -1;
  explicit Scratch(const std::string& input) {
    std::string pattern = (std::filesystem::temp_directory_path() / "openmss-user-XXXXXX").string();
    fd = ::mkstemp(pattern.data());
    if (fd < 0) return;
    path = pattern;
    if (!input.empty() &&
        ::write(fd, input.data(), input.size()) != static_cast<ssize_t>(input.size())) {
      ::close(fd);
      fd = -1;
    }
    if (fd >= 0) ::lseek(fd, 0, SEEK_SET);
  }
  ~Scratch() {
    if (fd >= 0) ::close(fd);
    if (!path.empty()) ::unlink(path.c_str());
  }
};

// A FORTRAN routine: the unit connected to the scratch file by the FORTRAN units module
// (src/user/fortran_units/unit_shim.f), closed after the call so that its records reach the
// file.
std::string callFortran(const Found& f, const std::string& name, const Scratch& file) {
#ifdef OPENMSS_FORTRAN_UNITS
  using Open = void(int*, const char*, int*, std::size_t);
  using Close = void(int*);
  std::string why;
  static const std::shared_ptr<Library> units = Library::open(OPENMSS_FORTRAN_UNITS, ".", why);
  void* open = units ? units->symbol("omssop_") : nullptr;
  void* close = units ? units->symbol("omsscl_") : nullptr;
  if (!open || !close)
    return name + ": the FORTRAN units module " + OPENMSS_FORTRAN_UNITS + " did not load: " + why;
  int unit = kFortranUnit, iostat = 0;
  asFunction<Open>(open)(&unit, file.path.c_str(), &iostat, file.path.size());
  if (iostat != 0)
    return name + ": FORTRAN unit " + std::to_string(unit) + " could not be connected (IOSTAT " +
           std::to_string(iostat) + ")";
  std::string error = guarded(f, name, unit);
  asFunction<Close>(close)(&unit);
  return error;
#else
  (void)f;
  (void)file;
  return name +
         ": this OpenMSS was built without a FORTRAN compiler, so it cannot connect a "
         "FORTRAN unit; write SAVSUB/RELSUB in C (docs/user-subroutines.md)";
#endif
}

// Calls the routine with IUNIT on a scratch file holding `input`; returns what the file holds
// afterwards.
UserSaveData call(const Found& f, const std::string& adamsName, const std::string& input) {
  UserSaveData r;
  r.called = true;
  const std::string name = adamsName + " (" + f.symbol + ")";
  Scratch file(input);
  if (file.fd < 0) {
    r.error = "no scratch file for " + name;
    return r;
  }
  r.error = f.fortran ? callFortran(f, name, file) : guarded(f, name, file.fd);
  if (r.error.empty()) r.bytes = readAll(file.fd);
  return r;
}

}  // namespace

UserSaveData callSavsub(const std::string& baseDirectory) {
  UserSaveData r;
  const Found f = find("Savsub", "SAVSUB", baseDirectory, r.error);
  return f.address ? call(f, "SAVSUB", "") : r;
}

UserSaveData callRelsub(const std::string& bytes, const std::string& baseDirectory) {
  UserSaveData r;
  const Found f = find("Relsub", "RELSUB", baseDirectory, r.error);
  if (!f.address) return r;
  r = call(f, "RELSUB", bytes);
  r.bytes.clear();
  return r;
}

}  // namespace openmss::user

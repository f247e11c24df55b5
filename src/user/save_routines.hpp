#pragma once
// SAVSUB and RELSUB (docs/user-subroutines.md, "SAVSUB and RELSUB"): SAVE/STATES and
// SAVE/SYSTEM call the default user library's SAVSUB so that the user's code can put its own
// data into the save file; RELOAD calls RELSUB with those bytes. ADAMS passes a FORTRAN unit
// number. C style (`void Savsub(int IUNIT, int* IERR)`, `void Relsub(int IUNIT, int* IERR)`,
// tried first): IUNIT is a POSIX file descriptor open on a scratch file, from its start, for
// write(2) (SAVSUB) or read(2) (RELSUB). FORTRAN (`SAVSUB(IUNIT, IERR)`, gfortran): IUNIT is a
// FORTRAN unit connected to that file (FORM='UNFORMATTED', ACCESS='SEQUENTIAL') by the FORTRAN
// units module and closed after the call. Each call runs under the crash guard.

#include <optional>
#include <string>

namespace openmss::user {

struct UserSaveData {
  bool called = false;  // the default library has the routine
  std::string bytes;    // SAVSUB: what it wrote
  std::string error;    // IERR nonzero, a crash, or the library did not load
};

// SAVSUB of the default library (none: called = false).
UserSaveData callSavsub(const std::string& baseDirectory);
// RELSUB of the default library with `bytes` to read (none: called = false).
UserSaveData callRelsub(const std::string& bytes, const std::string& baseDirectory);

}  // namespace openmss::user

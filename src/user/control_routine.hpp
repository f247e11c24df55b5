#pragma once
// CONSUB, the driver subroutine of the CONTROL command (docs/user-subroutines.md, "CONSUB"):
// loaded from a user library, C style (`void Consub(const struct sAdamsControl*)`) or
// FORTRAN 77 (`SUBROUTINE CONSUB(PAR, NPAR)`), and run under the crash guard. While it runs,
// the utilities ANALYS, DATOUT and MODIFY (utility_subroutines.cpp) reach the session through
// the ControlHooks given here; outside CONSUB they fail as before. ERRMES with a stopping end
// flag (STOP, ERROR, ABORT, FATAL) inside CONSUB ends the control sequence: the routine runs
// on, but every later ANALYS, DATOUT and MODIFY does nothing and returns istat = 1, and the
// CONTROL command fails with the message.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "user/user_library.hpp"

namespace openmss::user {

// What ANALYS, DATOUT and MODIFY do (the session supplies them); each returns istat (0: done).
struct ControlHooks {
  std::function<int(const std::string& antype, const std::string& cid, double timbeg, double timend,
                    bool init)>
      analys;
  std::function<int()> datout;
  std::function<int(const std::string& command)> modify;
};

class ControlRoutine {
 public:
  // Loads CONSUB from ROUTINE=lib::name (or the default library and name). Null with the
  // reason in `error`.
  static std::shared_ptr<ControlRoutine> load(const RoutineName& routine,
                                              const std::string& baseDirectory, std::string& error);
  // Calls CONSUB with `par` (the USER(...) constants) and the hooks. Returns the fatal
  // condition that ended it (ERRMES STOP, a crash), or "" when it returned normally.
  std::string run(const std::vector<double>& par, const ControlHooks& hooks) const;
  const std::string& symbolName() const { return symbol_; }

 private:
  std::shared_ptr<Library> library_;
  void* address_ = nullptr;
  bool fortran_ = false;
  std::string symbol_;
};

namespace detail {
// For utility_subroutines.cpp: whether CONSUB runs on this thread, and its utilities.
bool controlCallActive();
void controlAnalys(const std::string& antype, const std::string& cid, double timbeg, double timend,
                   int init, int* istat);
void controlDatout(int* istat);
void controlModify(const std::string& command, int* istat);
// ERRMES inside CONSUB: a stopping flag ends the control sequence with `text`.
void controlFatal(const std::string& text);
}  // namespace detail

}  // namespace openmss::user

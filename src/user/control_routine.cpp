#include "user/control_routine.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <utility>

#include "common/ascii_case.hpp"
#include "user/element_call.hpp"
#include "user/openmss_usersub.h"
#include "user/routine_guard.hpp"

namespace openmss::user {
namespace {

struct ControlCall {
  const ControlHooks* hooks = nullptr;
  std::string fatal;  // set by ERRMES STOP: later utilities do nothing
};
thread_local ControlCall* current = nullptr;

bool mixedCase(const std::string& n) {
  if (n.empty() || !std::isupper(static_cast<unsigned char>(n[0]))) return false;
  for (std::size_t k = 1; k < n.size(); ++k)
    if (std::isupper(static_cast<unsigned char>(n[k]))) return false;
  return true;
}

// A utility called after ERRMES ended the sequence: nothing happens.
bool ended(int* istat) {
  if (current && current->fatal.empty()) return false;
  *istat = 1;
  return true;
}

}  // namespace

std::shared_ptr<ControlRoutine> ControlRoutine::load(const RoutineName& routine,
                                                     const std::string& baseDirectory,
                                                     std::string& error) {
  const std::string libName = routine.library.empty() ? defaultLibrary() : routine.library;
  if (libName.empty()) {
    error =
        "CONTROL needs the user subroutine CONSUB, and no user library is named: give "
        "ROUTINE=lib::name or run with --user-library LIB";
    return nullptr;
  }
  std::string why;
  detail::anchorUtilities();
  auto r = std::make_shared<ControlRoutine>();
  r->library_ = Library::open(libName, baseDirectory, why);
  if (!r->library_) {
    error = "cannot load the user library " + libName + " for CONSUB: " + why;
    return nullptr;
  }
  // The same symbol search as the evaluation subroutines (docs/user-subroutines.md).
  std::vector<std::pair<std::string, bool>> tried;  // (symbol, fortran)
  if (routine.name.empty())
    tried = {{"Consub", false}, {"consub_", true}, {"CONSUB", true}, {"consub", true}};
  else
    tried = {{routine.name, !mixedCase(routine.name)},
             {toLowerAscii(routine.name) + "_", true},
             {toUpperAscii(routine.name), true}};
  for (const auto& [name, fortran] : tried)
    if (void* p = r->library_->symbol(name)) {
      r->address_ = p;
      r->fortran_ = fortran;
      r->symbol_ = name;
      break;
    }
  if (!r->address_) {
    std::string list;
    for (const auto& t : tried) list += (list.empty() ? "" : ", ") + t.first;
    error = "the user library " + r->library_->path() + " exports no CONSUB routine (looked for " +
            list + ")";
    return nullptr;
  }
  installCrashGuard();
  return r;
}

std::string ControlRoutine::run(const std::vector<double>& par, const ControlHooks& hooks) const {
  ControlCall call;
  call.hooks = &hooks;
  ControlCall* const outer = std::exchange(current, &call);
  const int npar = static_cast<int>(par.size());
  const GuardResult g = guardedCall(
      [&] {
        if (fortran_) {
          asFunction<void(const double*, const int*)>(address_)(par.data(), &npar);
        } else {
          const sAdamsControl control{npar, par.data()};
          asFunction<void(const sAdamsControl*)>(address_)(&control);
        }
      },
      "CONSUB (" + symbol_ + ")", 0.0);
  current = outer;
  if (g.signal != 0) return "CONSUB (" + symbol_ + "): " + g.text;
  return call.fatal;
}

namespace detail {

bool controlCallActive() { return current != nullptr; }

void controlAnalys(const std::string& antype, const std::string& cid, double timbeg, double timend,
                   int init, int* istat) {
  if (ended(istat)) return;
  *istat = current->hooks->analys(antype, cid, timbeg, timend, init != 0);
}

void controlDatout(int* istat) {
  if (ended(istat)) return;
  *istat = current->hooks->datout();
}

void controlModify(const std::string& command, int* istat) {
  if (ended(istat)) return;
  *istat = current->hooks->modify(command);
}

void controlFatal(const std::string& text) {
  if (current && current->fatal.empty()) current->fatal = text;
}

}  // namespace detail
}  // namespace openmss::user

#pragma once
// A crash inside user code must not lose the run's outputs (docs/user-subroutines.md, "Bad
// user code"). Every call of a user routine runs under a guard: a synchronous fault (SIGSEGV,
// SIGBUS, SIGFPE, SIGILL) raised while it runs jumps back to the guard, which reports it; the
// routine is then marked stopped, its values become NaN, and the run ends through its ordinary
// failure path, which closes every output file. A fault anywhere else keeps the default
// action. The guard names the routine and the time on stderr at once, so even a second fault
// outside user code leaves those as the last words.

#include <csetjmp>
#include <csignal>
#include <string>

namespace openmss::user {

struct GuardResult {
  int signal = 0;    // 0: the routine returned
  std::string text;  // what happened, for the routine's fatal message
};

// Installs the fault handlers (once per process).
void installCrashGuard();

namespace detail {
// The jump target of the innermost guarded call on this thread (null: none).
sigjmp_buf*& guardTarget();
void announceCrash(int signal, const std::string& who, double time);
std::string signalText(int signal);
}  // namespace detail

// Calls f() under the guard. `who` and `time` name the call in the crash message.
template <class F>
GuardResult guardedCall(const F& f, const std::string& who, double time) {
  sigjmp_buf here;
  sigjmp_buf* const outer = detail::guardTarget();
  const int sig = sigsetjmp(here, 1);
  if (sig != 0) {
    detail::guardTarget() = outer;
    detail::announceCrash(sig, who, time);
    return {sig, detail::signalText(sig)};
  }
  detail::guardTarget() = &here;
  f();
  detail::guardTarget() = outer;
  return {};
}

}  // namespace openmss::user

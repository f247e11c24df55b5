#include "user/routine_guard.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <mutex>

namespace openmss::user {
namespace detail {

sigjmp_buf*& guardTarget() {
  thread_local sigjmp_buf* target = nullptr;
  return target;
}

std::string signalText(int signal) {
  const char* name = signal == SIGSEGV  ? "SIGSEGV, invalid memory access"
                     : signal == SIGBUS ? "SIGBUS, bus error"
                     : signal == SIGFPE ? "SIGFPE, arithmetic fault"
                     : signal == SIGILL ? "SIGILL, illegal instruction"
                                        : "a fatal signal";
  return std::string("the routine crashed (") + name +
         "); the outputs up to the last accepted step are complete";
}

void announceCrash(int signal, const std::string& who, double time) {
  std::fprintf(stderr, "openmss: error: %s crashed at TIME = %.9g (%s)\n", who.c_str(), time,
               signalText(signal).c_str());
  std::fflush(stderr);
}

}  // namespace detail

namespace {

void onFault(int signal, siginfo_t*, void*) {
  if (sigjmp_buf* target = detail::guardTarget()) siglongjmp(*target, signal);
  // Not inside a user routine: the default action (core dump, status), as without the guard.
  std::signal(signal, SIG_DFL);
  raise(signal);
}

}  // namespace

void installCrashGuard() {
  static std::once_flag once;
  std::call_once(once, [] {
    struct sigaction action;
    std::memset(&action, 0, sizeof action);
    action.sa_sigaction = onFault;
    action.sa_flags = SA_SIGINFO;
    sigemptyset(&action.sa_mask);
    for (int s : {SIGSEGV, SIGBUS, SIGFPE, SIGILL}) sigaction(s, &action, nullptr);
  });
}

}  // namespace openmss::user

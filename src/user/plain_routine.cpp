#include "user/plain_routine.hpp"

#include <cmath>
#include <cstdio>

namespace openmss::user {
namespace {
thread_local const PlainRoutine* running = nullptr;
thread_local double runningTime = 0.0;
}  // namespace

namespace detail {
const PlainRoutine* plainCurrent() { return running; }
double plainTime() { return runningTime; }
}  // namespace detail

PlainRoutine::PlainRoutine(std::string adamsName, std::string subject, ResolvedRoutine resolved,
                           std::shared_ptr<const ModelData> data)
    : adamsName_(std::move(adamsName)),
      subject_(std::move(subject)),
      resolved_(std::move(resolved)),
      data_(std::move(data)) {
  installCrashGuard();
}

PlainRoutine::Scope::Scope(const PlainRoutine* r, double time)
    : saved(running), savedTime(runningTime) {
  running = r;
  // TIMGET from a routine called without the time (CURSUB: its argument is ALPHA) gives 0.
  runningTime = r->argumentName_ == "TIME" ? time : 0.0;
}
PlainRoutine::Scope::~Scope() {
  running = saved;
  runningTime = savedTime;
}

std::string PlainRoutine::who() const {
  return adamsName_ + " (" + resolved_.symbol + ") of " + subject_;
}

bool PlainRoutine::finite(const double* v, int n, double time) const {
  for (int k = 0; k < n; ++k)
    if (!std::isfinite(v[k])) {
      fatal("it returned a value that is not a finite number (NaN or infinity)", time);
      return false;
    }
  return true;
}

void PlainRoutine::fatal(const std::string& text, double time) const {
  std::string message;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!fatal_.empty()) return;
    char t[64];
    std::snprintf(t, sizeof t, "%.9g", time);
    fatal_ = who() + " stopped the run at " + argumentName_ + " = " + t + ": " + text;
    message = fatal_;
  }
  std::fprintf(stderr, "openmss: error: %s\n", message.c_str());
  std::fflush(stderr);
  detail::recordProcessFatal(message);
}

std::string PlainRoutine::fatalError() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return fatal_;
}

}  // namespace openmss::user

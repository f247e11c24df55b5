#pragma once
// A user routine called with explicit arguments (FIESUB, CURSUB, COUSUB/COUXX/COUXX2,
// SPLINE_READ): the mechanics passes its inputs, so it declares no dependencies and may not
// call SYSFNC or SYSARY (docs/user-subroutines.md). What it shares with the evaluation
// subroutines: the crash guard, the first-fatal-condition rule (NaN, ERRMES with a stopping end
// flag, a crash stop the run, and every later call returns NaN without running the routine),
// and the utilities (ERRMES, TIMGET, GTCURV, ...), which serve it while it runs.

#include <memory>
#include <mutex>
#include <string>

#include "user/element_routine.hpp"
#include "user/routine_guard.hpp"
#include "user/routine_symbol.hpp"

namespace openmss::user {

class PlainRoutine {
 public:
  // `adamsName`: "FIESUB"; `subject`: "FIELD/3".
  PlainRoutine(std::string adamsName, std::string subject, ResolvedRoutine resolved,
               std::shared_ptr<const ModelData> data);
  virtual ~PlainRoutine() = default;

  std::string who() const;  // "FIESUB (Fiesub) of FIELD/3"
  bool fortran() const { return resolved_.fortran; }
  template <class Fn>
  Fn* function() const {
    return asFunction<Fn>(resolved_.address);
  }
  const ModelData* data() const { return data_.get(); }

  // Runs f() under the crash guard, the utilities serving this routine. False, without
  // running f, once the routine has stopped; false too when this call stops it.
  template <class F>
  bool call(double time, const F& f) const {
    if (!fatalError().empty()) return false;
    Scope scope(this, time);
    const GuardResult g = guardedCall(f, who(), time);
    if (g.signal != 0) fatal(g.text, time);
    return fatalError().empty();
  }
  // False (and the routine stopped) when one of v[0..n) is NaN or infinite.
  bool finite(const double* v, int n, double time) const;
  void fatal(const std::string& text, double time) const;
  std::string fatalError() const;
  // What the time argument of call() is, for messages: "TIME" (default) or "ALPHA".
  void setArgumentName(std::string name) { argumentName_ = std::move(name); }

 private:
  struct Scope {
    Scope(const PlainRoutine* r, double time);
    ~Scope();
    const PlainRoutine* saved;
    double savedTime;
  };
  std::string adamsName_, subject_, argumentName_ = "TIME";
  ResolvedRoutine resolved_;
  std::shared_ptr<const ModelData> data_;
  mutable std::mutex mutex_;
  mutable std::string fatal_;
};

namespace detail {
// The plain routine running on this thread (null: none) and the time it was called with.
const PlainRoutine* plainCurrent();
double plainTime();
// Records the process's first fatal message (firstUserFatal).
void recordProcessFatal(const std::string& text);
}  // namespace detail

}  // namespace openmss::user

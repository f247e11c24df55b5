#include "user/element_routine.hpp"

#include <atomic>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <mutex>

#include "user/element_call.hpp"
#include "user/openmss_usersub.h"
#include "user/difference_step.hpp"
#include "user/plain_routine.hpp"
#include "user/routine_guard.hpp"
#include "user/routine_symbol.hpp"
#include "user/sysary_names.hpp"

namespace openmss::user {
namespace {

using expr::HostCall;

struct KindInfo {
  const char* name;  // ADAMS default name, FORTRAN spelling
  int outputs;
  bool hasDflag;  // the (…, dflag, iflag, result) argument list; else (…, iflag, result)
};
KindInfo info(RoutineKind k) {
  switch (k) {
    case RoutineKind::Sfosub:
      return {"SFOSUB", 1, true};
    case RoutineKind::Vfosub:
      return {"VFOSUB", 3, true};
    case RoutineKind::Vtosub:
      return {"VTOSUB", 3, true};
    case RoutineKind::Gfosub:
      return {"GFOSUB", 6, true};
    case RoutineKind::Varsub:
      return {"VARSUB", 1, true};
    case RoutineKind::Difsub:
      return {"DIFSUB", 1, true};
    case RoutineKind::Motsub:
      return {"MOTSUB", 1, true};  // IORD in the DFLAG slot
    case RoutineKind::Reqsub:
      return {"REQSUB", 8, false};
    case RoutineKind::Sensub:
      return {"SENSUB", 1, false};
    case RoutineKind::Sevsub:
      return {"SEVSUB", 1, false};
  }
  return {"?", 1, true};
}

// FORTRAN-77 argument lists (gfortran: everything by reference, LOGICAL as a 4-byte int).
using F77WithDflag = void(int* id, double* time, double* par, int* npar, int* dflag, int* iflag,
                          double* result);
using F77NoDflag = void(int* id, double* time, double* par, int* npar, int* iflag, double* result);
using CWithDflag = void(const void* element, double time, int dflag, int iflag, double* result);
using CNoDflag = void(const void* element, double time, int iflag, double* result);

std::mutex fatalMutex;
std::string& processFatal() {
  static std::string text;
  return text;
}

class Routine;

// The routine running on this thread and what it may read.
struct Call {
  const Routine* routine = nullptr;
  bool recording = false;        // dependency pass: record measures, return zeros
  const double* host = nullptr;  // evaluation: the declared measures' values
  double time = 0.0;
  bool needsPartials = false;
  std::vector<double>* provided = nullptr;  // SYSPAR target: outputs x n, row-major
  std::vector<char>* providedColumns = nullptr;
};
thread_local Call* current = nullptr;

class Routine final : public ElementRoutine {
 public:
  Routine(RoutineKind kind, const ElementData& e) : kind_(kind), e_(e), serial_(++serials) {
    par_ = e_.par;
    npar_ = static_cast<int>(par_.size());
    fillStructs();
  }

  void* address = nullptr;
  bool fortran = false;
  std::string symbolName;
  std::shared_ptr<Library> library;

  const std::vector<HostCall>& dependencies() const override { return deps_; }
  std::shared_ptr<const expr::UserFunction> component(int c) const override;
  std::string fatalError() const override {
    std::lock_guard<std::mutex> lock(fatalMutex);
    return fatal_;
  }
  RoutineKind kind() const { return kind_; }
  // Unique for the process's life (an address may be reused by a later routine).
  unsigned long serial() const { return serial_; }
  const ElementData& element() const { return e_; }
  int outputs() const { return info(kind_).outputs; }
  std::string who() const {
    return std::string(info(kind_).name) + " (" + symbolName + ") of " + e_.subject;
  }

  // The dependency pass: IFLAG = 1 (initialization) then 3 (dependencies), both recorded.
  std::string dependencyPass() {
    std::vector<double> out(static_cast<size_t>(outputs()), 0.0);
    for (int iflag : {1, 3}) {
      Call c;
      c.routine = this;
      c.recording = true;
      invoke(c, 0.0, 0, iflag, out.data());
      if (!fatalError().empty()) return fatalError();
    }
    if (kind_ == RoutineKind::Motsub && !deps_.empty())
      return who() + " read " + deps_[0].name +
             " in its dependency pass; a MOTION is a function of time only (MOTSUB may not "
             "call SYSFNC or SYSARY)";
    return {};
  }

  // Evaluates every output at (host, time); with partials, also d out / d host (row-major
  // outputs x n) and d out / d time. NaN outputs when the routine has stopped.
  void evaluate(const double* host, double time, bool withPartials, std::vector<double>& out,
                std::vector<double>& dHost, std::vector<double>& dTime) const {
    const size_t n = deps_.size(), m = static_cast<size_t>(outputs());
    out.assign(m, 0.0);
    std::vector<char> given(n, 0);
    if (withPartials) {
      dHost.assign(m * n, 0.0);
      dTime.assign(m, 0.0);
    }
    Call c;
    c.routine = this;
    c.host = host;
    c.time = time;
    c.needsPartials = withPartials;
    c.provided = withPartials ? &dHost : nullptr;
    c.providedColumns = withPartials ? &given : nullptr;
    invoke(c, time, 0, 0, out.data());
    if (!checkFinite(out, time)) return;
    if (!withPartials) return;
    // Central differences over the inputs the routine gave no SYSPAR partials for, and over
    // TIME; the step cbrt(eps) * max(1, |x|) balances truncation (h^2) and rounding (eps/h)
    // (differenceStep).
    const int perturbed = fdFlag();
    std::vector<double> x(host, host + n), plus(m), minus(m);
    auto difference = [&](size_t k) {
      const double base = host[k];
      const double h = differenceStep(base);
      Call p = c;
      p.needsPartials = false;
      p.provided = nullptr;
      p.providedColumns = nullptr;
      p.host = x.data();
      x[k] = base + h;
      invoke(p, time, perturbed, 0, plus.data());
      x[k] = base - h;
      invoke(p, time, perturbed, 0, minus.data());
      x[k] = base;
      for (size_t r = 0; r < m; ++r) dHost[r * n + k] = (plus[r] - minus[r]) / (2.0 * h);
    };
    for (size_t k = 0; k < n; ++k)
      if (!given[k]) difference(k);
    timeDifference(c, time, x, plus, minus, dTime);
    if (!checkFinite(dHost, time)) return;
  }

  // MOTSUB: value, velocity and acceleration from IORD = 0, 1, 2.
  expr::TimeJet timeJet(double time) const {
    double v[3] = {0.0, 0.0, 0.0};
    Call c;
    c.routine = this;
    c.time = time;
    for (int iord = 0; iord < 3; ++iord) invoke(c, time, iord, 0, &v[iord]);
    std::vector<double> all(v, v + 3);
    if (!checkFinite(all, time)) return {all[0], all[1], all[2]};
    return {v[0], v[1], v[2]};
  }

  void fatal(const std::string& text, double time) const {
    std::lock_guard<std::mutex> lock(fatalMutex);
    if (!fatal_.empty()) return;
    char t[64];
    std::snprintf(t, sizeof t, "%.9g", time);
    fatal_ = who() + " stopped the run at TIME = " + t + ": " + text;
    std::fprintf(stderr, "openmss: error: %s\n", fatal_.c_str());
    std::fflush(stderr);
    if (processFatal().empty()) processFatal() = fatal_;
  }

  // The host index of a recorded measure, recording it in the dependency pass (-1: unknown).
  int measure(const HostCall& call) const {
    for (size_t k = 0; k < deps_.size(); ++k)
      if (deps_[k].name == call.name && deps_[k].args == call.args) return static_cast<int>(k);
    if (!current || !current->recording) return -1;
    deps_.push_back(call);
    return static_cast<int>(deps_.size() - 1);
  }

 private:
  // DFLAG of the perturbed calls; MOTSUB's slot is IORD, which stays 0 (the value).
  int fdFlag() const { return kind_ == RoutineKind::Motsub ? 0 : 1; }

  void timeDifference(const Call& c, double t, const std::vector<double>& x,
                      std::vector<double>& plus, std::vector<double>& minus,
                      std::vector<double>& dTime) const {
    const double h = differenceStep(t);
    Call p = c;
    p.needsPartials = false;
    p.provided = nullptr;
    p.providedColumns = nullptr;
    p.host = x.data();
    p.time = t + h;
    invoke(p, t + h, fdFlag(), 0, plus.data());
    p.time = t - h;
    invoke(p, t - h, fdFlag(), 0, minus.data());
    for (size_t r = 0; r < plus.size(); ++r) dTime[r] = (plus[r] - minus[r]) / (2.0 * h);
  }

  bool checkFinite(std::vector<double>& values, double time) const {
    for (double v : values)
      if (!std::isfinite(v)) {
        fatal("it returned a value that is not a finite number (NaN or infinity)", time);
        break;
      }
    if (fatalError().empty()) return true;
    std::fill(values.begin(), values.end(), std::numeric_limits<double>::quiet_NaN());
    return false;
  }

  // One call of the routine with the calling convention its symbol chose, under the crash
  // guard (routine_guard.hpp). A routine that has stopped is not called again.
  void invoke(Call& c, double time, int dflag, int iflag, double* out) const {
    if (!fatalError().empty()) {
      for (int r = 0; r < outputs(); ++r) out[r] = std::numeric_limits<double>::quiet_NaN();
      return;
    }
    Call* saved = current;
    current = &c;
    const GuardResult g = guardedCall([&] { callRaw(time, dflag, iflag, out); }, who(), time);
    current = saved;
    if (g.signal != 0) fatal(g.text, time);
  }

  void callRaw(double time, int dflag, int iflag, double* out) const {
    const bool withDflag = info(kind_).hasDflag;
    if (fortran) {
      int id = static_cast<int>(e_.id), npar = npar_, df = dflag, ifl = iflag;
      double t = time;
      std::vector<double> par = par_;  // a FORTRAN routine may write its arguments
      if (par.empty()) par.push_back(0.0);
      if (withDflag)
        asFunction<F77WithDflag>(address)(&id, &t, par.data(), &npar, &df, &ifl, out);
      else
        asFunction<F77NoDflag>(address)(&id, &t, par.data(), &npar, &ifl, out);
      return;
    }
    const void* s = structFor();
    if (withDflag)
      asFunction<CWithDflag>(address)(s, time, dflag, iflag, out);
    else
      asFunction<CNoDflag>(address)(s, time, iflag, out);
  }

  const void* structFor() const {
    switch (kind_) {
      case RoutineKind::Sfosub:
        return &sforce_;
      case RoutineKind::Vfosub:
        return &vforce_;
      case RoutineKind::Vtosub:
        return &vtorque_;
      case RoutineKind::Gfosub:
        return &gforce_;
      case RoutineKind::Varsub:
        return &variable_;
      case RoutineKind::Difsub:
        return &diff_;
      case RoutineKind::Motsub:
        return &motion_;
      case RoutineKind::Reqsub:
        return &request_;
      case RoutineKind::Sensub:
      case RoutineKind::Sevsub:
        return &sensor_;
    }
    return nullptr;
  }

  void fillStructs() {
    const int id = static_cast<int>(e_.id);
    const double* par = par_.empty() ? nullptr : par_.data();
    auto i32 = [](long v) { return static_cast<int>(v); };
    typeText_ = e_.rotation ? "ROTATION" : "TRANSLATION";
    sforce_ = {id, npar_, par, i32(e_.i), i32(e_.j), e_.actionOnly ? 1 : 0, typeText_.c_str()};
    vforce_ = {id, npar_, par, i32(e_.i), i32(e_.jfloat), i32(e_.rm)};
    vtorque_ = {id, npar_, par, i32(e_.i), i32(e_.jfloat), i32(e_.rm)};
    gforce_ = {id, npar_, par, i32(e_.i), i32(e_.rm), i32(e_.jfloat)};
    variable_ = {id, npar_, par, e_.ic};
    diff_ = {id, npar_, par, e_.staticHold ? 1 : 0, e_.implicit ? 1 : 0, e_.ic, e_.icDerivative};
    motion_ = sAdamsMotion{};
    motion_.ID = id;
    motion_.NPAR = npar_;
    motion_.PAR = par;
    motion_.JOINT = i32(e_.joint);
    motion_.Type = e_.motionType.c_str();
    motion_.I = i32(e_.i);
    motion_.J = i32(e_.j);
    motion_.Which[0] = e_.motionWhich;
    motion_.DVA = e_.motionDva.c_str();
    request_ = sAdamsRequest{};
    request_.ID = id;
    request_.NPAR = npar_;
    request_.PAR = par;
    request_.COMMENT = e_.comment.c_str();
    for (auto& t : request_.TITLE) t = "";
    sensor_ = sAdamsSensor{};
    sensor_.ID = id;
    sensor_.NPAR = npar_;
    sensor_.PAR = par;
    sensor_.VALUE = e_.sensorValue;
    sensor_.Error = e_.sensorError;
    sensor_.Logic[0] = e_.sensorLogic;
  }

  static inline std::atomic<unsigned long> serials{0};
  RoutineKind kind_;
  ElementData e_;
  unsigned long serial_;
  std::vector<double> par_;
  int npar_ = 0;
  std::string typeText_;
  sAdamsSforce sforce_{};
  sAdamsVforce vforce_{};
  sAdamsVtorque vtorque_{};
  sAdamsGforce gforce_{};
  sAdamsVariable variable_{};
  sAdamsDiff diff_{};
  sAdamsMotion motion_{};
  sAdamsRequest request_{};
  sAdamsSensor sensor_{};
  mutable std::vector<HostCall> deps_;  // grows only in the dependency pass
  mutable std::string fatal_;
};

// The last full evaluation on this thread: the components of a VFOSUB/GFOSUB/REQSUB read
// one evaluation instead of calling the routine once each.
struct Cache {
  unsigned long routine = 0;  // Routine::serial()
  double time = 0.0;
  bool withPartials = false;
  std::vector<double> host, out, dHost, dTime;
};
thread_local Cache cache;

const Cache& evaluated(const Routine& r, const double* host, double time, bool withPartials) {
  const size_t n = r.dependencies().size();
  const bool hit = cache.routine == r.serial() && cache.time == time &&
                   (cache.withPartials || !withPartials) && cache.host.size() == n &&
                   (n == 0 || std::memcmp(cache.host.data(), host, n * sizeof(double)) == 0);
  if (hit) return cache;
  cache.routine = 0;
  std::vector<double> out, dHost, dTime;
  r.evaluate(host, time, withPartials, out, dHost, dTime);
  cache.routine = r.serial();
  cache.time = time;
  cache.withPartials = withPartials;
  cache.host.assign(host, host + n);
  cache.out = std::move(out);
  cache.dHost = std::move(dHost);
  cache.dTime = std::move(dTime);
  return cache;
}

class Component final : public expr::UserFunction {
 public:
  Component(std::shared_ptr<const Routine> r, int c) : r_(std::move(r)), c_(c) {}
  double value(const double* host, double time) const override {
    return evaluated(*r_, host, time, false).out[static_cast<size_t>(c_)];
  }
  double partials(const double* host, double time, double* dHost, double* dTime) const override {
    const Cache& e = evaluated(*r_, host, time, true);
    const size_t n = r_->dependencies().size(), c = static_cast<size_t>(c_);
    for (size_t k = 0; k < n; ++k) dHost[k] = e.dHost[c * n + k];
    *dTime = e.dTime[c];
    return e.out[c];
  }
  expr::TimeJet timeJet(double time) const override { return r_->timeJet(time); }

 private:
  std::shared_ptr<const Routine> r_;
  int c_;
};

std::shared_ptr<const expr::UserFunction> Routine::component(int c) const {
  return std::make_shared<Component>(std::static_pointer_cast<const Routine>(shared_from_this()),
                                     c);
}

}  // namespace

const char* routineName(RoutineKind kind) { return info(kind).name; }
int routineOutputs(RoutineKind kind) { return info(kind).outputs; }

std::string firstUserFatal() {
  std::lock_guard<std::mutex> lock(fatalMutex);
  return processFatal();
}

std::shared_ptr<ElementRoutine> loadElementRoutine(RoutineKind kind, const ElementData& element,
                                                   const RoutineName& routine,
                                                   const std::string& baseDirectory,
                                                   std::string& error) {
  ResolvedRoutine resolved;
  if (!resolveRoutine(info(kind).name, routine, baseDirectory, resolved, error)) return nullptr;
  auto r = std::make_shared<Routine>(kind, element);
  r->library = resolved.library;
  r->address = resolved.address;
  r->fortran = resolved.fortran;
  r->symbolName = resolved.symbol;
  installCrashGuard();
  const std::string fatal = r->dependencyPass();
  if (!fatal.empty()) {
    error = fatal;
    return nullptr;
  }
  return r;
}

// ---- What the utilities read (element_call.hpp) ------------------------------------------

namespace detail {

// An evaluation subroutine (current) or a routine with explicit arguments (plainCurrent).
bool elementCallActive() { return current != nullptr || plainCurrent() != nullptr; }

const ModelData* elementModelData() {
  if (current) return current->routine->element().data.get();
  return plainCurrent() ? plainCurrent()->data() : nullptr;
}

bool elementNeedsPartials() { return current && current->needsPartials; }

double elementTime() { return current ? current->time : plainTime(); }

std::string elementWho() {
  if (current) return current->routine->who();
  return plainCurrent() ? plainCurrent()->who() : std::string();
}

void elementFatal(const std::string& text) {
  if (current)
    current->routine->fatal(text, current->time);
  else if (plainCurrent())
    plainCurrent()->fatal(text, plainTime());
}

void recordProcessFatal(const std::string& text) {
  std::lock_guard<std::mutex> lock(fatalMutex);
  if (processFatal().empty()) processFatal() = text;
}

namespace {
// SYSFNC/SYSARY from a routine whose inputs are passed explicitly (ADAMS allows them only in
// the evaluation subroutines, docs/user-subroutines.md): stops it, naming the utility.
bool refusedInPlain(const char* utility) {
  if (!plainCurrent()) return false;
  plainCurrent()->fatal(
      std::string(utility) + " may not be called from this routine: its inputs are its arguments",
      plainTime());
  return true;
}
}  // namespace

namespace {
bool measures(const std::string& name, const int* ipar, int nsize, bool array,
              std::vector<int>& index) {
  std::vector<HostCall> calls;
  std::string why;
  if (!(array ? sysaryCalls(name, ipar, nsize, calls, why)
              : sysfncCall(name, ipar, nsize, calls, why))) {
    elementFatal(std::string(array ? "SYSARY" : "SYSFNC") + "(\"" + name + "\"): " + why);
    return false;
  }
  for (const HostCall& c : calls) {
    const int k = current->routine->measure(c);
    if (k < 0) {
      std::string args;
      for (long a : c.args) args += (args.empty() ? "" : ",") + std::to_string(a);
      elementFatal(std::string(array ? "SYSARY" : "SYSFNC") + " read " + c.name + "(" + args +
                   "), which the routine did not read in its dependency pass (IFLAG = 1 or 3); "
                   "make the same SYSFNC/SYSARY calls when IFLAG is set");
      return false;
    }
    index.push_back(k);
  }
  return true;
}
}  // namespace

bool elementMode(double* mode) {
  *mode = 0.0;
  if (!current) return false;
  const int k = current->routine->measure(HostCall{"MODE", {}, 0});
  if (k < 0) {
    elementFatal(
        "GETMOD/GETINM read MODE, which the routine did not read in its dependency pass "
        "(IFLAG = 1 or 3); make the same calls when IFLAG is set");
    return false;
  }
  if (!current->recording) *mode = current->host[k];
  return true;
}

bool elementSysfnc(const std::string& name, const int* ipar, int nsize, double* value) {
  std::vector<int> index;
  *value = 0.0;
  if (refusedInPlain("SYSFNC")) return false;
  if (!current || !measures(name, ipar, nsize, false, index)) return false;
  if (!current->recording) *value = current->host[index[0]];
  return true;
}

bool elementSysary(const std::string& name, const int* ipar, int nsize, double* values,
                   int* count) {
  std::vector<int> index;
  *count = 0;
  if (refusedInPlain("SYSARY")) return false;
  if (!current || !measures(name, ipar, nsize, true, index)) return false;
  for (size_t k = 0; k < index.size(); ++k)
    values[k] = current->recording ? 0.0 : current->host[index[k]];
  *count = static_cast<int>(index.size());
  return true;
}

bool elementSyspar(const std::string& name, const int* ipar, int nsize, const double* partials,
                   int npartl) {
  if (!current || !current->provided) return false;
  std::vector<int> index;
  if (!measures(name, ipar, nsize, isSysaryName(name), index)) return false;
  const int m = current->routine->outputs();
  const size_t n = current->routine->dependencies().size();
  if (npartl != m * static_cast<int>(index.size())) return false;
  // Column-major outputs x states, as MSC's SYSPAR examples pass them.
  for (size_t col = 0; col < index.size(); ++col) {
    for (int r = 0; r < m; ++r)
      (*current->provided)[static_cast<size_t>(r) * n + static_cast<size_t>(index[col])] =
          partials[static_cast<size_t>(r) + static_cast<size_t>(m) * col];
    (*current->providedColumns)[static_cast<size_t>(index[col])] = 1;
  }
  return true;
}

}  // namespace detail
}  // namespace openmss::user

#pragma once
// The compiled form of an expression: a flat list of instructions in single-assignment form.
// Instruction i writes slot i of a work array, and its operands are indices of earlier slots,
// so one list serves three evaluators:
//  * values only (T = double);
//  * value and exact first partials by reverse mode: a forward sweep stores each executed
//    instruction's local partials, a backward sweep accumulates adjoints into the host values
//    and TIME;
//  * time jets (T = Jet2): value, d/dt and d2/dt2 propagated forward.
// IF is compiled to Branch / Jump / Join so that only the selected branch runs.
//
// Work arrays: programs of up to kStackSlots instructions use arrays on the caller's stack, so
// evaluation allocates nothing and any number of threads may evaluate one Program at once.
// Larger programs use a scratch buffer owned by the Program and sized at compile time; a
// thread that finds it in use by another thread falls back to a temporary buffer (allocating)
// rather than waiting.

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/bspline_curve.hpp"
#include "common/spline.hpp"
#include "expr/builtin.hpp"
#include "expr/data_functions.hpp"
#include "expr/expression.hpp"
#include "expr/jet.hpp"
#include "expr/run_context.hpp"
#include "expr/user_function.hpp"

namespace openmss::expr {

enum class OpCode : std::uint8_t {
  Constant,  // constants[aux]
  LoadHost,  // hostValues[aux]
  LoadTime,  // TIME
  Negate,
  Add,
  Subtract,
  Multiply,
  Divide,
  Power,
  Call,      // builtin applied to the operands
  Branch,    // operand 0 is IF's e1; jumps to jumpTargets[aux + choice], choice 0/1/2 for <0/=0/>0
  Jump,      // to instruction aux
  Join,      // operands e2, e3, e4 roots and the Branch; takes the value of the chosen root
  DataCall,  // AKISPL/CUBSPL (operands x, z) or CURVE (operand alpha); data binding aux
  Delay,     // DELAY: operands e_delayed, e_delay, TIME; delay call aux (Program::DelayCall)
};

// A data call bound to its data. The shared pointers keep the data alive; evaluation goes
// through the plain pointers and non-virtual member functions.
struct DataBinding {
  // InterpLinear/InterpCubic: INTERP with degree 1 or 3; Psd: INVPSD (data_functions.hpp).
  enum class Kind : std::uint8_t { Akima, Cubic, Curve, InterpLinear, InterpCubic, Psd };
  Kind kind = Kind::Akima;
  int order = 0;      // iord
  int component = 0;  // CURVE: 0, 1, 2
  const Spline* spline = nullptr;
  const BSplineCurve* curve = nullptr;
  std::shared_ptr<const Spline> splineOwner;
  std::shared_ptr<const BSplineCurve> curveOwner;
  std::shared_ptr<const LinearTable> table;  // INTERP degree 1
  std::shared_ptr<const PsdSignal> psd;      // INVPSD
  std::vector<double> parameters;            // DataCall::parameters

  // The call's value g(a, b) (a = x or alpha, b = z) with its first and second partials.
  BinaryPartials partials(double a, double b) const {
    if (psd != nullptr) {
      const ScalarJet j = psd->evaluate(a);
      return {j.g, j.gx, 0.0, j.gxx, 0.0, 0.0};
    }
    if (table != nullptr) {
      const ScalarJet j = table->evaluate(a);
      const double d[5] = {j.g, j.gx, 0.0, 0.0, 0.0};  // a line: no second or third derivative
      return {d[order], d[order + 1], 0.0, d[order + 2], 0.0, 0.0};
    }
    if (spline != nullptr && kind == Kind::InterpCubic) {
      // A time series: one curve, read at its own z.
      const double z = spline->z().empty() ? 0.0 : spline->z().front();
      const SplinePartials p = spline->evaluate(SplineMethod::Cubic, a, z, order);
      return {p.g, p.gx, 0.0, p.gxx, 0.0, 0.0};
    }
    if (spline != nullptr) {
      const SplinePartials p = spline->evaluate(
          kind == Kind::Akima ? SplineMethod::Akima : SplineMethod::Cubic, a, b, order);
      return {p.g, p.gx, p.gz, p.gxx, p.gxz, p.gzz};
    }
    if (curve != nullptr) {
      double d[BSplineCurve::kDerivatives];
      curve->derivatives(a, component, d);
      return {d[order], d[order + 1], 0.0, d[order + 2], 0.0, 0.0};
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan, nan, nan};
  }
};

struct Instruction {
  OpCode op = OpCode::Constant;
  Builtin builtin = Builtin::Abs;
  std::uint16_t operandCount = 0;
  std::uint32_t firstOperand = 0;     // into ProgramCode::operands
  std::uint32_t firstPartial = 0;     // into the partials work array
  std::uint32_t aux = 0;              // see OpCode
  std::uint64_t varyingOperands = 0;  // bit j: operand j is not a compile-time constant
};

struct ProgramCode {
  std::vector<Instruction> instructions;
  std::vector<std::uint32_t> operands;
  std::vector<double> constants;
  std::vector<std::uint32_t> jumpTargets;
  std::uint32_t result = 0;        // slot holding the expression's value
  std::uint32_t partialCount = 0;  // size of the partials work array
  std::uint32_t timeSlot = 0;      // slot of LoadTime
  bool usesTime = false;           // TIME survives constant folding
  // Host value k is loaded into slot k (the loads come first, so a host call used inside one IF
  // branch and again outside it has a value whichever branch ran).
};

class Program {
 public:
  Program(std::string text, std::vector<HostCall> hostCalls, ProgramCode code);
  Program(const Program& other);
  Program& operator=(const Program&) = delete;
  ~Program();

  const std::string& text() const { return text_; }
  const std::vector<HostCall>& hostCalls() const { return hostCalls_; }
  bool dependsOnTime() const { return code_.usesTime; }
  std::size_t instructionCount() const { return code_.instructions.size(); }

  double evaluate(const double* hostValues, double time, const RunContext* run = nullptr) const;
  double evaluate(const double* hostValues, double time, double* dHost, double* dTime,
                  const RunContext* run = nullptr) const;
  TimeJet evaluateTimeJet(double time) const;
  TimeJet evaluateJet(const TimeJet* hostJets, double time) const;

  const std::vector<DataCall>& dataCalls() const { return dataCalls_; }
  const UserCall* userCall() const { return user_ ? &*user_ : nullptr; }
  void setUserCall(UserCall call) { user_ = std::move(call); }
  // A USER(...) bound to its subroutine (expr/user_function.hpp): the host calls become the
  // subroutine's declared measures and every evaluation goes to `f`.
  void bindUser(std::shared_ptr<const UserFunction> f, std::vector<HostCall> dependencies);
  void setDataCalls(std::vector<DataCall> calls);
  void bindSpline(std::size_t call, std::shared_ptr<const Spline> spline);
  void bindCurve(std::size_t call, std::shared_ptr<const BSplineCurve> curve);

  // DELAY call k: its e_delayed as a program of its own (over this program's host values, so
  // the run can record it at accepted states) and its e_history (TIME only). Shared by copies:
  // both are immutable, and the e_delayed program's address is the key of the call's history.
  struct DelayCall {
    std::shared_ptr<const Program> delayed;
    std::shared_ptr<const Program> history;
  };
  void setDelayCalls(std::vector<DelayCall> calls) { delays_ = std::move(calls); }
  const std::vector<DelayCall>& delayCalls() const { return delays_; }

  static constexpr std::size_t kStackSlots = 256;
  static constexpr std::size_t kStackPartials = 512;

 private:
  struct Scratch;
  class ScratchLease;

  template <typename T, typename Host>
  T forward(T* values, const Host* hostValues, const T& time,
            const RunContext* run = nullptr) const;
  double forwardWithPartials(double* values, double* partials, std::uint32_t* trace,
                             std::uint32_t& traceLength, const double* hostValues, double time,
                             const RunContext* run) const;
  // DELAY call k at TIME `time` with a positive delay: the recorded history at time - delay,
  // or e_history there when that is before the history's start (or there is none).
  DelayLookup delayedValue(std::uint32_t k, double delay, double time,
                           const RunContext* run) const;
  void backward(const double* partials, double* adjoints, const std::uint32_t* trace,
                std::uint32_t traceLength, double* dHost, double* dTime) const;
  double evaluateDerivatives(double* values, double* partials, double* adjoints,
                             std::uint32_t* trace, const double* hostValues, double time,
                             double* dHost, double* dTime, const RunContext* run) const;
  bool fitsOnStack() const;

  std::string text_;
  std::vector<HostCall> hostCalls_;
  std::vector<DataCall> dataCalls_;
  std::vector<DataBinding> bindings_;  // bindings_[k] serves dataCalls_[k]
  std::optional<UserCall> user_;
  std::shared_ptr<const UserFunction> userFunction_;
  std::vector<DelayCall> delays_;
  ProgramCode code_;
  std::unique_ptr<Scratch> scratch_;  // only for programs too large for the stack arrays
};

}  // namespace openmss::expr

#include "expr/program.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "expr/intrinsics.hpp"

namespace openmss::expr {

// Work arrays for programs larger than the stack arrays.
struct Program::Scratch {
  explicit Scratch(const ProgramCode& code)
      : values(code.instructions.size()),
        partials(std::max<std::size_t>(code.partialCount, 1)),
        adjoints(code.instructions.size()),
        trace(code.instructions.size()),
        jets(code.instructions.size()) {}

  std::vector<double> values;
  std::vector<double> partials;
  std::vector<double> adjoints;
  std::vector<std::uint32_t> trace;
  std::vector<Jet2> jets;
  std::atomic<bool> busy{false};
};

// Borrows the Program's scratch, or builds a private one when another thread holds it.
class Program::ScratchLease {
 public:
  ScratchLease(Scratch& shared, const ProgramCode& code) : shared_(shared) {
    if (!shared_.busy.exchange(true, std::memory_order_acquire)) {
      scratch_ = &shared_;
    } else {
      private_ = std::make_unique<Scratch>(code);
      scratch_ = private_.get();
    }
  }
  ~ScratchLease() {
    if (scratch_ == &shared_) shared_.busy.store(false, std::memory_order_release);
  }
  ScratchLease(const ScratchLease&) = delete;
  ScratchLease& operator=(const ScratchLease&) = delete;

  Scratch& get() { return *scratch_; }

 private:
  Scratch& shared_;
  std::unique_ptr<Scratch> private_;
  Scratch* scratch_ = nullptr;
};

Program::Program(std::string text, std::vector<HostCall> hostCalls, ProgramCode code)
    : text_(std::move(text)), hostCalls_(std::move(hostCalls)), code_(std::move(code)) {
  if (!fitsOnStack()) scratch_ = std::make_unique<Scratch>(code_);
}

Program::Program(const Program& other)
    : text_(other.text_),
      hostCalls_(other.hostCalls_),
      dataCalls_(other.dataCalls_),
      bindings_(other.bindings_),
      user_(other.user_),
      userFunction_(other.userFunction_),
      delays_(other.delays_),
      code_(other.code_) {
  if (!fitsOnStack()) scratch_ = std::make_unique<Scratch>(code_);
}

Program::~Program() = default;

void Program::setDataCalls(std::vector<DataCall> calls) {
  dataCalls_ = std::move(calls);
  bindings_.assign(dataCalls_.size(), DataBinding{});
  for (std::size_t k = 0; k < dataCalls_.size(); ++k) {
    const DataCall& call = dataCalls_[k];
    DataBinding& b = bindings_[k];
    b.kind = call.name == "AKISPL"   ? DataBinding::Kind::Akima
             : call.name == "CUBSPL" ? DataBinding::Kind::Cubic
             : call.name == "INVPSD" ? DataBinding::Kind::Psd
             : call.name == "INTERP" ? (call.parameters.at(0) == 1.0 ? DataBinding::Kind::InterpLinear
                                                                     : DataBinding::Kind::InterpCubic)
                                     : DataBinding::Kind::Curve;
    b.parameters = call.parameters;
    b.order = call.order;
    b.component = call.component > 0 ? call.component - 1 : 0;
  }
}

void Program::bindSpline(std::size_t call, std::shared_ptr<const Spline> spline) {
  DataBinding& b = bindings_.at(call);
  // INTERP and INVPSD precompute their tables from the SPLINE once, here.
  if (b.kind == DataBinding::Kind::InterpLinear && spline) {
    b.table = std::make_shared<const LinearTable>(*spline);
  } else if (b.kind == DataBinding::Kind::Psd && spline) {
    const std::vector<double>& q = b.parameters;
    b.psd = std::make_shared<const PsdSignal>(*spline, q.at(0), q.at(1), static_cast<int>(q.at(2)),
                                              static_cast<int>(q.at(3)), q.at(4));
  }
  b.spline = spline.get();
  b.splineOwner = std::move(spline);
}

void Program::bindCurve(std::size_t call, std::shared_ptr<const BSplineCurve> curve) {
  DataBinding& b = bindings_.at(call);
  b.curve = curve.get();
  b.curveOwner = std::move(curve);
}

bool Program::fitsOnStack() const {
  return code_.instructions.size() <= kStackSlots && code_.partialCount <= kStackPartials;
}

namespace {
// A host value as a number of type T: plain values are constants, time jets are jets along s.
template <typename T>
T hostNumber(double x) {
  return constant<T>(x);
}
template <typename T>
T hostNumber(const TimeJet& x) {
  static_assert(std::is_same_v<T, Jet2>, "host jets feed jet evaluation only");
  return {x.value, x.d1, x.d2};
}
}  // namespace

DelayLookup Program::delayedValue(std::uint32_t k, double delay, double time,
                                  const RunContext* run) const {
  const double s = time - delay;
  const DelayCall& call = delays_[k];
  const DelayHistory* h = run != nullptr ? run->delayHistory(call.delayed.get()) : nullptr;
  if (h != nullptr && !h->empty() && s >= h->startTime()) return h->at(s);
  const TimeJet before = call.history->evaluateTimeJet(s);
  return {before.value, before.d1};
}

template <typename T, typename Host>
T Program::forward(T* v, const Host* hostValues, const T& time, const RunContext* run) const {
  const Instruction* code = code_.instructions.data();
  const std::uint32_t* operands = code_.operands.data();
  const auto count = static_cast<std::uint32_t>(code_.instructions.size());
  std::uint32_t pc = 0;
  while (pc < count) {
    const Instruction& ins = code[pc];
    const std::uint32_t* in = operands + ins.firstOperand;
    switch (ins.op) {
      case OpCode::Constant:
        v[pc] = constant<T>(code_.constants[ins.aux]);
        break;
      case OpCode::LoadHost:
        v[pc] = hostNumber<T>(hostValues[ins.aux]);
        break;
      case OpCode::LoadTime:
        v[pc] = time;
        break;
      case OpCode::Negate:
        v[pc] = -v[in[0]];
        break;
      case OpCode::Add:
        v[pc] = v[in[0]] + v[in[1]];
        break;
      case OpCode::Subtract:
        v[pc] = v[in[0]] - v[in[1]];
        break;
      case OpCode::Multiply:
        v[pc] = v[in[0]] * v[in[1]];
        break;
      case OpCode::Divide:
        v[pc] = v[in[0]] / v[in[1]];
        break;
      case OpCode::Power:
        v[pc] = intrinsic::power(v[in[0]], v[in[1]]);
        break;
      case OpCode::Call: {
        T args[kMaxBuiltinArguments];
        for (std::uint16_t j = 0; j < ins.operandCount; ++j) args[j] = v[in[j]];
        v[pc] = applyBuiltin(ins.builtin, args, ins.operandCount);
        break;
      }
      case OpCode::Branch: {
        // A NaN condition is neither negative nor zero, so it selects e4.
        const double condition = valueOf(v[in[0]]);
        const std::uint32_t choice = condition < 0.0 ? 0 : (condition == 0.0 ? 1 : 2);
        v[pc] = constant<T>(static_cast<double>(choice));
        pc = code_.jumpTargets[ins.aux + choice];
        continue;
      }
      case OpCode::Jump:
        pc = ins.aux;
        continue;
      case OpCode::Join:
        v[pc] = v[in[static_cast<std::uint32_t>(valueOf(v[in[3]]))]];
        break;
      case OpCode::DataCall: {
        // Chain rule through g(x, z) with its exact first and second partials, so time jets of
        // AKISPL(TIME, ...) carry the spline's own second derivative.
        const T& a = v[in[0]];
        const T b = ins.operandCount > 1 ? v[in[1]] : constant<T>(0.0);
        v[pc] = chain2(a, b, bindings_[ins.aux].partials(valueOf(a), valueOf(b)));
        break;
      }
      case OpCode::Delay:
        // Values only: jets (MOTION, GCON) are refused DELAY when the model is built.
        if constexpr (std::is_same_v<T, double>) {
          const double delay = v[in[1]];
          v[pc] = delay > 0.0 ? delayedValue(ins.aux, delay, time, run).value : v[in[0]];
        } else {
          v[pc] = constant<T>(std::numeric_limits<double>::quiet_NaN());
        }
        break;
    }
    ++pc;
  }
  return v[code_.result];
}

void Program::bindUser(std::shared_ptr<const UserFunction> f, std::vector<HostCall> dependencies) {
  userFunction_ = std::move(f);
  hostCalls_ = std::move(dependencies);
  user_.reset();
  code_.usesTime = true;  // a subroutine receives TIME
}

double Program::evaluate(const double* hostValues, double time, const RunContext* run) const {
  if (userFunction_) return userFunction_->value(hostValues, time);
  if (fitsOnStack()) {
    double values[kStackSlots];
    return forward(values, hostValues, time, run);
  }
  ScratchLease lease(*scratch_, code_);
  return forward(lease.get().values.data(), hostValues, time, run);
}

// Forward sweep that also stores, for every executed instruction with operands, the partial
// derivative of its value with respect to each operand, and records the executed order.
double Program::forwardWithPartials(double* v, double* p, std::uint32_t* trace,
                                    std::uint32_t& traceLength, const double* hostValues,
                                    double time, const RunContext* run) const {
  const Instruction* code = code_.instructions.data();
  const std::uint32_t* operands = code_.operands.data();
  const auto count = static_cast<std::uint32_t>(code_.instructions.size());
  traceLength = 0;
  std::uint32_t pc = 0;
  while (pc < count) {
    const Instruction& ins = code[pc];
    const std::uint32_t* in = operands + ins.firstOperand;
    double* partial = p + ins.firstPartial;
    switch (ins.op) {
      case OpCode::Constant:
        v[pc] = code_.constants[ins.aux];
        ++pc;
        continue;
      case OpCode::LoadHost:
        v[pc] = hostValues[ins.aux];
        ++pc;
        continue;
      case OpCode::LoadTime:
        v[pc] = time;
        ++pc;
        continue;
      case OpCode::Negate:
        v[pc] = -v[in[0]];
        partial[0] = -1.0;
        break;
      case OpCode::Add:
        v[pc] = v[in[0]] + v[in[1]];
        partial[0] = 1.0;
        partial[1] = 1.0;
        break;
      case OpCode::Subtract:
        v[pc] = v[in[0]] - v[in[1]];
        partial[0] = 1.0;
        partial[1] = -1.0;
        break;
      case OpCode::Multiply:
        v[pc] = v[in[0]] * v[in[1]];
        partial[0] = v[in[1]];
        partial[1] = v[in[0]];
        break;
      case OpCode::Divide:
        v[pc] = v[in[0]] / v[in[1]];
        partial[0] = 1.0 / v[in[1]];
        partial[1] = -v[pc] / v[in[1]];
        break;
      case OpCode::Power: {
        const double base = v[in[0]];
        const double exponent = v[in[1]];
        v[pc] = std::pow(base, exponent);
        // The logarithm of the base is formed only for a varying exponent, so x**2 at x < 0
        // keeps a finite partial.
        if ((ins.varyingOperands & 1u) == 0 || exponent == 0.0) {
          partial[0] = 0.0;
        } else {
          partial[0] =
              base != 0.0 ? exponent * v[pc] / base : exponent * std::pow(base, exponent - 1.0);
        }
        partial[1] = (ins.varyingOperands & 2u) != 0 ? v[pc] * std::log(base) : 0.0;
        break;
      }
      case OpCode::Call: {
        // One dual-number evaluation per varying argument gives that argument's exact partial
        // (POLY(TIME, ...) needs one, IMPACT(x, xdot, ...) two).
        Jet1 args[kMaxBuiltinArguments];
        for (std::uint16_t j = 0; j < ins.operandCount; ++j) args[j] = {v[in[j]], 0.0};
        double value = 0.0;
        bool valueKnown = false;
        for (std::uint16_t j = 0; j < ins.operandCount; ++j) {
          if ((ins.varyingOperands >> j & 1u) == 0) {
            partial[j] = 0.0;
            continue;
          }
          args[j].d = 1.0;
          const Jet1 result = applyBuiltin(ins.builtin, args, ins.operandCount);
          args[j].d = 0.0;
          partial[j] = result.d;
          value = result.v;
          valueKnown = true;
        }
        if (!valueKnown) {
          double plain[kMaxBuiltinArguments];
          for (std::uint16_t j = 0; j < ins.operandCount; ++j) plain[j] = args[j].v;
          value = applyBuiltin(ins.builtin, plain, ins.operandCount);
        }
        v[pc] = value;
        break;
      }
      case OpCode::Branch: {
        const double condition = v[in[0]];
        const std::uint32_t choice = condition < 0.0 ? 0 : (condition == 0.0 ? 1 : 2);
        v[pc] = static_cast<double>(choice);
        pc = code_.jumpTargets[ins.aux + choice];
        continue;
      }
      case OpCode::Jump:
        pc = ins.aux;
        continue;
      case OpCode::Join: {
        const auto choice = static_cast<std::uint32_t>(v[in[3]]);
        v[pc] = v[in[choice]];
        for (std::uint32_t j = 0; j < 4; ++j) partial[j] = j == choice ? 1.0 : 0.0;
        break;
      }
      case OpCode::DataCall: {
        const BinaryPartials g =
            bindings_[ins.aux].partials(v[in[0]], ins.operandCount > 1 ? v[in[1]] : 0.0);
        v[pc] = g.g;
        partial[0] = g.ga;
        if (ins.operandCount > 1) partial[1] = g.gb;
        break;
      }
      case OpCode::Delay: {
        // A positive delay reads the past only: no partial with respect to e_delayed (the
        // current state); d/d(delay) = -slope of the history at TIME - delay. A delay <= 0
        // is taken as 0 (ADAMS): the value is e_delayed itself.
        const double delay = v[in[1]];
        if (delay > 0.0) {
          const DelayLookup past = delayedValue(ins.aux, delay, time, run);
          v[pc] = past.value;
          partial[0] = 0.0;
          partial[1] = -past.slope;
          partial[2] = past.slope;
        } else {
          v[pc] = v[in[0]];
          partial[0] = 1.0;
          partial[1] = 0.0;
          partial[2] = 0.0;
        }
        break;
      }
    }
    trace[traceLength++] = pc;
    ++pc;
  }
  return v[code_.result];
}

void Program::backward(const double* p, double* adjoints, const std::uint32_t* trace,
                       std::uint32_t traceLength, double* dHost, double* dTime) const {
  const Instruction* code = code_.instructions.data();
  const std::uint32_t* operands = code_.operands.data();
  std::fill(adjoints, adjoints + code_.instructions.size(), 0.0);
  adjoints[code_.result] = 1.0;
  for (std::uint32_t t = traceLength; t-- > 0;) {
    const std::uint32_t i = trace[t];
    const double adjoint = adjoints[i];
    // Skipping a zero adjoint keeps an infinite local partial (SQRT at 0 under a zero factor)
    // from turning a zero contribution into NaN.
    if (adjoint == 0.0) continue;
    const Instruction& ins = code[i];
    const std::uint32_t* in = operands + ins.firstOperand;
    const double* partial = p + ins.firstPartial;
    for (std::uint16_t j = 0; j < ins.operandCount; ++j) {
      if ((ins.varyingOperands >> j & 1u) != 0) adjoints[in[j]] += adjoint * partial[j];
    }
  }
  if (dHost != nullptr) {
    for (std::size_t k = 0; k < hostCalls_.size(); ++k) dHost[k] = adjoints[k];
  }
  if (dTime != nullptr) *dTime = code_.usesTime ? adjoints[code_.timeSlot] : 0.0;
}

double Program::evaluateDerivatives(double* values, double* partials, double* adjoints,
                                    std::uint32_t* trace, const double* hostValues, double time,
                                    double* dHost, double* dTime, const RunContext* run) const {
  std::uint32_t traceLength = 0;
  const double value =
      forwardWithPartials(values, partials, trace, traceLength, hostValues, time, run);
  backward(partials, adjoints, trace, traceLength, dHost, dTime);
  return value;
}

double Program::evaluate(const double* hostValues, double time, double* dHost, double* dTime,
                         const RunContext* run) const {
  if (userFunction_) {
    double dt = 0.0;
    const double v = userFunction_->partials(hostValues, time, dHost, &dt);
    if (dTime != nullptr) *dTime = dt;
    return v;
  }
  if (fitsOnStack()) {
    double values[kStackSlots];
    double partials[kStackPartials];
    double adjoints[kStackSlots];
    std::uint32_t trace[kStackSlots];
    return evaluateDerivatives(values, partials, adjoints, trace, hostValues, time, dHost, dTime,
                               run);
  }
  ScratchLease lease(*scratch_, code_);
  Scratch& s = lease.get();
  return evaluateDerivatives(s.values.data(), s.partials.data(), s.adjoints.data(), s.trace.data(),
                             hostValues, time, dHost, dTime, run);
}

TimeJet Program::evaluateTimeJet(double time) const {
  if (userFunction_ && hostCalls_.empty()) return userFunction_->timeJet(time);
  if (!hostCalls_.empty()) {
    // Precondition violated: a host value has no time jet here.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
  const Jet2 t{time, 1.0, 0.0};
  Jet2 result{};
  if (fitsOnStack()) {
    Jet2 values[kStackSlots];
    result = forward(values, static_cast<const double*>(nullptr), t);
  } else {
    ScratchLease lease(*scratch_, code_);
    result = forward(lease.get().jets.data(), static_cast<const double*>(nullptr), t);
  }
  return {result.v, result.d1, result.d2};
}

TimeJet Program::evaluateJet(const TimeJet* hostJets, double time) const {
  if (userFunction_) {
    // No second derivatives along a path through a subroutine (GCONs take no USER).
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
  const Jet2 t{time, 0.0, 0.0};
  Jet2 result{};
  if (fitsOnStack()) {
    Jet2 values[kStackSlots];
    result = forward(values, hostJets, t);
  } else {
    ScratchLease lease(*scratch_, code_);
    result = forward(lease.get().jets.data(), hostJets, t);
  }
  return {result.v, result.d1, result.d2};
}

}  // namespace openmss::expr

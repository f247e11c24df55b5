#pragma once
// ADAMS function expressions (FUNCTION=, F2=, ...): parsed once, compiled to a flat program,
// evaluated in the integrator's inner loop with exact first derivatives.
//
// Split of work between this module and its host (the mechanics):
//  * This module owns the language (FORTRAN-77 operators and precedence, ADAMS constants, the
//    math intrinsics and the general-purpose functions STEP, POLY, IMPACT, IF, ...), and the
//    chain rule through them.
//  * Functions whose value depends on the model (marker measures DX, DM, VR, WZ, ORIENT, PSI,
//    ...; force measures JOINT, SFORCE, FX, ...; system-element access VARVAL, DIF, ...; the
//    analysis variables MODE, HSIZE, ...) are "host calls": leaves whose value the host supplies
//    at evaluation, together with their derivatives. All arguments of a host call are integer
//    constants (identifiers and flags) and are kept as written.

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "common/diagnostics.hpp"

namespace openmss {
class Spline;
class BSplineCurve;
}  // namespace openmss

namespace openmss::expr {

struct HostCall {
  std::string name;        // canonical upper-case name: "DM", "JOINT", "ORIENT", "MODE", ...
  std::vector<long> args;  // integer arguments as written; omitted trailing ones are absent
  int column = 0;          // 1-based column of the function name within the expression text
};

// A function of model data: AKISPL(x, z, id[, iord]), CUBSPL(x, z, id[, iord]) or
// CURVE(alpha, iord, comp, id). Its real arguments (x, z, alpha) are expressions compiled into
// the program; the id and flags are integer constants kept here. Each call is bound to its data
// after parsing (Expression::bindSpline / bindCurve); an unbound call evaluates to NaN.
struct DataCall {
  std::string name;   // "AKISPL", "CUBSPL" or "CURVE"
  long id = 0;        // SPLINE or CURVE id
  int order = 0;      // iord: 0 value, 1 first, 2 second derivative (in x or alpha)
  int component = 0;  // CURVE: 1, 2, 3 = x, y, z; 0 otherwise
  int column = 0;     // 1-based column of the function name within the expression text
  // Constant arguments of INTERP (degree: 1 or 3) and INVPSD (f0, f1, nf, linlog, seed).
  std::vector<double> parameters;
};

// FUNCTION=USER(r1, ..., r30): the constants for a user subroutine, kept as written (folded to
// numbers). The expression's own value is NaN: the subroutine supplies it.
struct UserCall {
  std::vector<double> arguments;
  int column = 0;  // column of USER within the expression text
};

// Value and first two time derivatives of an expression that depends on TIME only.
struct TimeJet {
  double value = 0.0;
  double d1 = 0.0;  // d/dt
  double d2 = 0.0;  // d2/dt2
};

class Program;     // the compiled form (private to the module)
class UserFunction;  // a subroutine behind USER(...) (expr/user_function.hpp)
class RunContext;  // the run's history that DELAY reads (expr/run_context.hpp)

// Evaluation allocates nothing and keeps no mutable state in the object, so const methods may
// be called concurrently on one Expression (work arrays live on the caller's stack; see
// program.hpp for the rare expression too long for them).
class Expression {
 public:
  Expression();
  ~Expression();
  Expression(Expression&&) noexcept;
  Expression& operator=(Expression&&) noexcept;
  Expression(const Expression&);
  Expression& operator=(const Expression&);

  // Parses `text`. On failure returns false and adds one or more diagnostics to `diags`, each
  // located at `where` with the column inside the expression, naming `subject`
  // (e.g. "SFORCE/104") and saying what to change. Unknown functions, wrong argument counts,
  // unbalanced parentheses, non-integer arguments of host calls are all errors.
  static bool parse(const std::string& text, const SourceLocation& where,
                    const std::string& subject, Diagnostics& diags, Expression& out);

  const std::string& text() const;

  // Distinct host calls in first-appearance order. Host value k is hostValues[k] below.
  const std::vector<HostCall>& hostCalls() const;
  bool dependsOnTime() const;

  // Data calls in order of appearance, and their binding to model data. The expression shares
  // ownership of the data, so it stays valid however the model is copied or moved. Evaluation
  // calls the data through a plain pointer (no virtual call, no allocation).
  const std::vector<DataCall>& dataCalls() const;
  void bindSpline(std::size_t call, std::shared_ptr<const Spline> spline);
  void bindCurve(std::size_t call, std::shared_ptr<const BSplineCurve> curve);

  // The USER(...) call when the expression is one, else nullptr.
  const UserCall* userCall() const;

  // Value. hostValues has hostCalls().size() entries. No allocation. `run` supplies the
  // history of DELAY arguments; without it DELAY reads its e_history at TIME - delay.
  double evaluate(const double* hostValues, double time, const RunContext* run = nullptr) const;

  // Value and exact partial derivatives: dHost[k] = d value / d hostValues[k] (size
  // hostCalls().size()), *dTime = d value / d TIME (explicit dependence only). No allocation.
  double evaluate(const double* hostValues, double time, double* dHost, double* dTime,
                  const RunContext* run = nullptr) const;

  // DELAY calls, in order of appearance. The run records delayArgument(k, ...) (e_delayed on
  // the same host values as the whole expression) after each accepted step, under the key
  // delayKey(k), which copies of the expression share.
  std::size_t delayCount() const;
  const void* delayKey(std::size_t k) const;
  double delayArgument(std::size_t k, const double* hostValues, double time) const;

  // For expressions without host calls: value and first and second derivatives in TIME
  // (MOTION functions need velocity and acceleration). Precondition: hostCalls().empty().
  // Data calls are allowed (AKISPL(TIME, 0, id)): their second derivative in x enters.
  TimeJet evaluateTimeJet(double time) const;

  // Value and first and second derivatives along one path parameter s, given each host value's
  // jet along s (hostJets[k] = h_k, dh_k/ds, d2h_k/ds2); TIME is held at `time`. Second
  // derivatives of constraint equations (GCON) come from two such passes. No allocation.
  TimeJet evaluateJet(const TimeJet* hostJets, double time) const;

 private:
  // Binds USER(...) to its subroutine in place (expr/user_function.hpp).
  friend void bindUserFunction(Expression& e, std::shared_ptr<const UserFunction> f,
                               std::vector<HostCall> dependencies);

  std::unique_ptr<Program> program_;
};

}  // namespace openmss::expr

#include "expr/standalone.hpp"

#include "expr/expression.hpp"
#include "expr/expression_error.hpp"

namespace openmss::expr {

bool evaluateStandalone(const std::string& text, double time, double* value, double* dvalueDtime,
                        Diagnostics& diags) {
  const SourceLocation where{"<command line>", 0, 0};
  Expression expression;
  if (!Expression::parse(text, where, "", diags, expression)) return false;
  if (!expression.hostCalls().empty() || !expression.dataCalls().empty()) {
    for (const HostCall& call : expression.hostCalls()) {
      diags.error(where, "",
                  call.name + " " + atColumn(call.column) +
                      " needs a model, and the calculator evaluates expressions without one",
                  "Use numbers, constants, TIME and functions such as STEP or POLY.");
    }
    // AKISPL, CUBSPL, CURVE read SPLINE or CURVE data, which only a model has.
    for (const DataCall& call : expression.dataCalls()) {
      diags.error(where, "",
                  call.name + " " + atColumn(call.column) +
                      " needs a model, and the calculator evaluates expressions without one",
                  "Use numbers, constants, TIME and functions such as STEP or POLY.");
    }
    return false;
  }
  if (const UserCall* user = expression.userCall()) {
    diags.error(where, "",
                "USER " + atColumn(user->column) +
                    " needs a user subroutine, and the calculator loads none",
                "Use numbers, constants, TIME and functions such as STEP or POLY.");
    return false;
  }
  if (expression.delayCount() > 0) {
    diags.error(where, "",
                "DELAY needs the history of a run, and the calculator evaluates one instant",
                "Evaluate the delayed expression at TIME - delay instead.");
    return false;
  }
  double derivative = 0.0;
  const double result = expression.evaluate(nullptr, time, nullptr, &derivative);
  if (value != nullptr) *value = result;
  if (dvalueDtime != nullptr) *dvalueDtime = derivative;
  return true;
}

}  // namespace openmss::expr

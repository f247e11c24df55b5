#pragma once
// FUNCTION=USER(r1, ..., r30) bound to a user-written subroutine (docs/user-subroutines.md).
// The expression module knows nothing of libraries: the user layer implements this interface
// and binds it to the expression together with the host calls the subroutine declared in its
// dependency pass (SYSFNC/SYSARY with IFLAG set). The host then supplies those measures and
// their exact derivatives like for any expression, and the chain rule through the subroutine
// needs only d value / d host value, which the subroutine gives through SYSPAR or which is
// central-differenced over the host values.

#include <memory>
#include <vector>

#include "expr/expression.hpp"

namespace openmss::expr {

class UserFunction {
 public:
  virtual ~UserFunction() = default;
  // Value at the declared host values (one per host call the expression now has).
  virtual double value(const double* hostValues, double time) const = 0;
  // Value and dHost[k] = d value / d hostValues[k]; *dTime the explicit time derivative.
  virtual double partials(const double* hostValues, double time, double* dHost,
                          double* dTime) const = 0;
  // Value and first two time derivatives (MOTSUB's IORD 0, 1, 2); only for routines that
  // declare no host calls.
  virtual TimeJet timeJet(double time) const = 0;
};

// Binds the USER(...) expression `e` to its subroutine: from now on e.hostCalls() are the
// calls the subroutine declared (`dependencies`), every evaluation calls `f`, dependsOnTime()
// is true, and userCall() is null (nothing is left unbound). Copies share `f`. No effect on an
// expression that is not USER(...).
void bindUserFunction(Expression& e, std::shared_ptr<const UserFunction> f,
                      std::vector<HostCall> dependencies);

}  // namespace openmss::expr

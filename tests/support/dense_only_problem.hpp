#pragma once
// A DAE problem with its sparse Newton matrix hidden, so that an integrator takes its dense
// path: the tests that compare the KLU path with dense LU on the same equations (I3 and SI2)
// wrap the problem in this.

#include "support/forwarding_problem.hpp"

namespace openmss::testing {

class DenseOnlyProblem final : public ForwardingProblem {
 public:
  using ForwardingProblem::ForwardingProblem;
};

}  // namespace openmss::testing

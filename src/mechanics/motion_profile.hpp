#pragma once
// The displacement a MOTION prescribes, with its first and second time derivatives, for the
// three forms of the MOTION statement (docs/theory.md §5, "Velocity and acceleration motions"):
//   DISPLACEMENT  q(t) = f(t)
//   VELOCITY      q(t) = ICDISP + integral_0^t f
//   ACCELERATION  q(t) = ICDISP + ICVEL t + integral_0^t (t - s) f(s) ds
// The integrals are computed by adaptive Gauss-Legendre quadrature of f (a function of TIME
// only); the derivatives come from f itself (and from its time jet), so they are exact.

#include "expr/expression.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

expr::TimeJet motionProfile(const model::Motion& motion, double t);

}  // namespace openmss::mechanics

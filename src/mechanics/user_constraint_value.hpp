#pragma once
// The equation of a UCON (docs/theory.md §5f, docs/user-subroutines.md "UCON"): UCOSUB's
// F(q) = 0 over the part variables q that UCOVAR declared, each a coordinate of a part's body
// frame (the frame of a marker placed there, eq.measureSlots[k][0]): codes 11..13 its origin's
// x, y, z, code 100 a + 10 + c component c of its axis a, all in ground. The q are computed on
// the caller's scalar S; the routine gives F, ARRAY = dF/dq and XMATRX = d2F/dq2 at the values
// of q, and on a dual scalar of depth <= 2 the second-order Taylor polynomial of F in
// (q - value(q)) carries exactly the first and second derivatives along the state (its terms
// of third order vanish at that depth), as for COUPLER's COUSUB (user_coupler_value.hpp).

#include <type_traits>

#include "common/dual.hpp"
#include "mechanics/constraint_set.hpp"
#include "mechanics/user_coupler_value.hpp"
#include "user/ucon_routine.hpp"

namespace openmss::mechanics {

// The derivative order a scalar carries: 0 for double, 2 for a second-order dual, 1 for any
// other first-order scalar (Dual<double>, the element-local Newton matrix's DualVec).
template <class S>
constexpr int uconOrder() {
  if constexpr (std::is_same_v<S, double>)
    return 0;
  else if constexpr (DualDepth<S>::value >= 2)
    return 2;
  else
    return 1;
}

template <class S>
S userConstraintValue(const ConstraintEquation& eq, const Frame<S>* frames) {
  constexpr int order = uconOrder<S>();
  static_assert(DualDepth<S>::value <= 2, "XMATRX gives second partials only");
  constexpr int kMax = user::kMaxUconVariables;
  const int n = static_cast<int>(eq.measureSlots.size());
  S q[kMax];
  double x[kMax] = {};
  for (int k = 0; k < n; ++k) {
    const Frame<S>& f = frames[eq.measureSlots[k][0]];
    const int code = eq.measureSlots[k][1];
    q[k] = code < 100 ? f.p[code - 11] : f.a.c[code / 100 - 1][code % 10 - 1];
    x[k] = valueOf(q[k]);
  }
  double value = 0.0, first[kMax] = {}, second[kMax * kMax] = {};
  // TIME: the latest residual evaluation's (userCouplerClock); the equation is scleronomic.
  eq.userConstraint->evaluate(userCouplerClock().load(std::memory_order_relaxed), x, n, order,
                              &value, first, second);
  S out(value);
  if constexpr (order >= 1) {
    S delta[kMax];
    for (int k = 0; k < n; ++k) delta[k] = q[k] - x[k];
    for (int k = 0; k < n; ++k) out = out + first[k] * delta[k];
    if constexpr (order >= 2)
      for (int k = 0; k < n; ++k)
        for (int l = 0; l < n; ++l)
          if (second[k + n * l] != 0.0)
            out = out + (0.5 * second[k + n * l]) * (delta[k] * delta[l]);
  }
  return out;
}

}  // namespace openmss::mechanics

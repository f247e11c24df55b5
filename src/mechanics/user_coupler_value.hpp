#pragma once
// COUPLER with FUNCTION=USER(...): the equation phi(d) = 0 over the coupled joints'
// displacements d (docs/theory.md §5b, docs/user-subroutines.md "COUPLER"). The routine gives
// phi, its first partials (COUXX) and its second partials (COUXX2) at the values of d; on a
// dual scalar of depth <= 2 the second-order Taylor polynomial in (d - value(d)) carries them
// exactly (its terms of third order vanish: every product of three dual parts is zero at that
// depth), so the equation's row and its acceleration term use the user's partials.

#include <atomic>

#include "common/dual.hpp"
#include "user/element_interfaces.hpp"

namespace openmss::mechanics {

// The TIME argument of COUSUB/COUXX/COUXX2: the time of the latest residual evaluation
// (MultibodySystem::residual sets it). The coupler's equation has no time derivative (ADAMS
// gives the routines no time partial), so TIME serves the routine's messages and TIMGET only.
inline std::atomic<double>& userCouplerClock() {
  static std::atomic<double> clock{0.0};
  return clock;
}

template <class S>
struct DualDepth {
  static constexpr int value = 0;
};
template <class T>
struct DualDepth<Dual<T>> {
  static constexpr int value = 1 + DualDepth<T>::value;
};

template <class S>
S userCouplerValue(const user::CouplerRoutine& routine, const S* d, int n) {
  constexpr int order = DualDepth<S>::value;
  static_assert(order <= 2, "COUXX2 gives second partials only");
  double x[3] = {}, phi = 0.0, first[3] = {}, second[9] = {};
  for (int k = 0; k < n; ++k) x[k] = valueOf(d[k]);
  routine.evaluate(userCouplerClock().load(std::memory_order_relaxed), x, n, order, &phi, first,
                   second);
  S out(phi);
  if constexpr (order >= 1) {
    S delta[3];
    for (int k = 0; k < n; ++k) delta[k] = d[k] - x[k];
    for (int k = 0; k < n; ++k) out = out + first[k] * delta[k];
    if constexpr (order >= 2)
      for (int k = 0; k < n; ++k)
        for (int l = 0; l < n; ++l) out = out + (0.5 * second[k + n * l]) * (delta[k] * delta[l]);
  }
  return out;
}

}  // namespace openmss::mechanics

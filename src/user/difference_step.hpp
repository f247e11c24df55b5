// What the evaluation subroutines' partials protocol shares (docs/user-subroutines.md, "The
// protocol"): the central-difference step for a partial the routine does not give, and the
// marker NaN that tells an unwritten output from one the routine computed.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace openmss::user {

// Step `rel` max(1, |x|), rounded to a representable difference; rel = cbrt(eps) for first
// differences, which balances truncation (h^2) and rounding (eps / h).
inline double differenceStep(double x, double rel = std::cbrt(DBL_EPSILON)) {
  return (x + rel * std::max(1.0, std::abs(x))) - x;
}

// A partial the routine did not write keeps this NaN (its payload tells it from a NaN the
// routine computed): that partial then comes from central differences.
inline constexpr std::uint64_t kUnsetPartialBits = 0x7ff8dead0000beefULL;
inline double unsetPartial() {
  double v;
  std::memcpy(&v, &kUnsetPartialBits, sizeof v);
  return v;
}
inline bool isUnsetPartial(double v) {
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b == kUnsetPartialBits;
}

}  // namespace openmss::user

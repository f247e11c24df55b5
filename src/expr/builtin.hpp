#pragma once
// The functions this module evaluates itself, and the single dispatch from an identifier to
// their templated definitions (one instantiation per number type of jet.hpp).

#include <cstdint>

#include "expr/general_functions.hpp"
#include "expr/intrinsics.hpp"

namespace openmss::expr {

enum class Builtin : std::uint8_t {
  Abs,
  Sqrt,
  Exp,
  Log,
  Log10,
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Atan2,
  Sinh,
  Cosh,
  Tanh,
  Max,
  Min,
  Mod,
  Sign,
  Dim,
  Aint,
  Anint,
  Step,
  Step5,
  Havsin,
  Shf,
  Poly,
  Cheby,
  Forcos,
  Forsin,
  Sweep,
  Impact,
  Bistop,
};

// The largest argument count of any built-in (FORCOS/FORSIN: x, x0, w and 31 coefficients).
// Evaluators gather arguments into fixed arrays of this size.
inline constexpr int kMaxBuiltinArguments = 34;

// Applies `id` to `count` arguments; the count has been checked against the catalog.
template <typename T>
T applyBuiltin(Builtin id, const T* a, int count) {
  switch (id) {
    case Builtin::Abs:
      return intrinsic::abs(a[0]);
    case Builtin::Sqrt:
      return intrinsic::sqrt(a[0]);
    case Builtin::Exp:
      return intrinsic::exp(a[0]);
    case Builtin::Log:
      return intrinsic::log(a[0]);
    case Builtin::Log10:
      return intrinsic::log10(a[0]);
    case Builtin::Sin:
      return intrinsic::sin(a[0]);
    case Builtin::Cos:
      return intrinsic::cos(a[0]);
    case Builtin::Tan:
      return intrinsic::tan(a[0]);
    case Builtin::Asin:
      return intrinsic::asin(a[0]);
    case Builtin::Acos:
      return intrinsic::acos(a[0]);
    case Builtin::Atan:
      return intrinsic::atan(a[0]);
    case Builtin::Atan2:
      return intrinsic::atan2(a[0], a[1]);
    case Builtin::Sinh:
      return intrinsic::sinh(a[0]);
    case Builtin::Cosh:
      return intrinsic::cosh(a[0]);
    case Builtin::Tanh:
      return intrinsic::tanh(a[0]);
    case Builtin::Max:
      return intrinsic::maximum(a, count);
    case Builtin::Min:
      return intrinsic::minimum(a, count);
    case Builtin::Mod:
      return intrinsic::mod(a[0], a[1]);
    case Builtin::Sign:
      return intrinsic::sign(a[0], a[1]);
    case Builtin::Dim:
      return intrinsic::dim(a[0], a[1]);
    case Builtin::Aint:
      return intrinsic::aint(a[0]);
    case Builtin::Anint:
      return intrinsic::anint(a[0]);
    case Builtin::Step:
      return general::step(a[0], a[1], a[2], a[3], a[4]);
    case Builtin::Step5:
      return general::step5(a[0], a[1], a[2], a[3], a[4]);
    case Builtin::Havsin:
      return general::havsin(a[0], a[1], a[2], a[3], a[4]);
    case Builtin::Shf:
      return general::shf(a[0], a[1], a[2], a[3], a[4], a[5]);
    case Builtin::Poly:
      return general::poly(a, count);
    case Builtin::Cheby:
      return general::cheby(a, count);
    case Builtin::Forcos:
      return general::fourierCosine(a, count);
    case Builtin::Forsin:
      return general::fourierSine(a, count);
    case Builtin::Sweep:
      return general::sweep(a[0], a[1], a[2], a[3], a[4], a[5], a[6]);
    case Builtin::Impact:
      return general::impact(a[0], a[1], a[2], a[3], a[4], a[5], a[6]);
    case Builtin::Bistop:
      return general::bistop(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]);
  }
  return constant<T>(0.0);
}

}  // namespace openmss::expr

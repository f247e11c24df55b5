#pragma once
// Reading an ADAMS number: [+|-]digits[.digits][E[+|-]digits][D]. A trailing D means degrees
// (the value is scaled by pi/180); it is not FORTRAN double precision.

#include <optional>
#include <string_view>

namespace openmss::language {

struct NumberToken {
  double value = 0.0;      // already scaled to radians when degrees
  bool isInteger = false;  // written with neither '.' nor exponent nor D
  bool degrees = false;
};

// nullopt when `token` (the whole of it) is not a number.
std::optional<NumberToken> parseNumber(std::string_view token);

inline bool startsNumber(char c) {
  return (c >= '0' && c <= '9') || c == '.' || c == '+' || c == '-';
}

}  // namespace openmss::language

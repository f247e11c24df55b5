#include "language/number_token.hpp"

#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

namespace openmss::language {

namespace {
bool isDigit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

std::optional<NumberToken> parseNumber(std::string_view token) {
  size_t i = 0;
  const size_t n = token.size();
  if (i < n && (token[i] == '+' || token[i] == '-')) ++i;
  size_t digits = 0;
  while (i < n && isDigit(token[i])) ++i, ++digits;
  bool point = false;
  if (i < n && token[i] == '.') {
    point = true;
    ++i;
    while (i < n && isDigit(token[i])) ++i, ++digits;
  }
  if (digits == 0) return std::nullopt;
  bool exponent = false;
  if (i < n && (token[i] == 'E' || token[i] == 'e')) {
    exponent = true;
    ++i;
    if (i < n && (token[i] == '+' || token[i] == '-')) ++i;
    size_t expDigits = 0;
    while (i < n && isDigit(token[i])) ++i, ++expDigits;
    if (expDigits == 0) return std::nullopt;
  }
  const size_t mantissaEnd = i;
  bool degrees = false;
  if (i < n && (token[i] == 'D' || token[i] == 'd')) {
    degrees = true;
    ++i;
  }
  if (i != n) return std::nullopt;

  std::string_view number = token.substr(0, mantissaEnd);
  if (!number.empty() && number.front() == '+') number.remove_prefix(1);
  double value = 0.0;
  auto [ptr, ec] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (ec != std::errc() || ptr != number.data() + number.size()) return std::nullopt;
  NumberToken t;
  t.degrees = degrees;
  t.isInteger = !point && !exponent && !degrees;
  t.value = degrees ? value * std::numbers::pi / 180.0 : value;
  return t;
}

}  // namespace openmss::language

#pragma once
// Small constructors that keep the statement and command tables readable. Internal to the
// language module (used by statement_table.cpp and command_table.cpp).

#include <string>
#include <utility>
#include <vector>

#include "language/schema.hpp"

namespace openmss::language::schema_builder {

inline ArgumentSpec makeArgument(std::string name, ValueType type, int minValues, int maxValues) {
  ArgumentSpec a;
  a.name = std::move(name);
  a.type = type;
  a.minValues = minValues;
  a.maxValues = maxValues;
  return a;
}

inline ArgumentSpec flag(std::string name) {
  return makeArgument(std::move(name), ValueType::Flag, 0, 0);
}
inline ArgumentSpec integer(std::string name, int minValues = 1, int maxValues = 1) {
  return makeArgument(std::move(name), ValueType::Integer, minValues, maxValues);
}
inline ArgumentSpec integers(std::string name, int maxValues = kUnlimited) {
  return integer(std::move(name), 1, maxValues);
}
inline ArgumentSpec real(std::string name, int minValues = 1, int maxValues = 1) {
  return makeArgument(std::move(name), ValueType::Real, minValues, maxValues);
}
inline ArgumentSpec reals(std::string name, int maxValues = kUnlimited) {
  return real(std::move(name), 1, maxValues);
}
// Three coordinates or three angles.
inline ArgumentSpec triple(std::string name) { return real(std::move(name), 3, 3); }
inline ArgumentSpec word(std::string name, std::vector<std::string> allowed = {}, int minValues = 1,
                         int maxValues = 1) {
  ArgumentSpec a = makeArgument(std::move(name), ValueType::Word, minValues, maxValues);
  a.allowedWords = std::move(allowed);
  return a;
}
inline ArgumentSpec words(std::string name, int maxValues = kUnlimited) {
  return word(std::move(name), {}, 1, maxValues);
}
inline ArgumentSpec wordOrNumber(std::string name, int minValues = 1, int maxValues = 1) {
  return makeArgument(std::move(name), ValueType::WordOrNumber, minValues, maxValues);
}
inline ArgumentSpec expression(std::string name) {
  return makeArgument(std::move(name), ValueType::Expression, 1, 1);
}
inline ArgumentSpec text(std::string name) {
  return makeArgument(std::move(name), ValueType::Text, 1, 1);
}

inline StatementSpec statement(std::string name, IdRule idRule,
                               std::vector<ArgumentSpec> arguments) {
  StatementSpec s;
  s.name = std::move(name);
  s.idRule = idRule;
  s.arguments = std::move(arguments);
  return s;
}

inline void append(std::vector<ArgumentSpec>& to, const std::vector<ArgumentSpec>& more) {
  to.insert(to.end(), more.begin(), more.end());
}

}  // namespace openmss::language::schema_builder

#pragma once
// The value of a command's numeric argument (NAME=number), or nullopt when it is absent or
// not a number. One of the argument helpers the single statement-argument reader of
// src/model replaces (issue 23).

#include <optional>

#include "language/dataset.hpp"

namespace openmss::commands {

inline std::optional<double> number(const language::Statement& s, const char* name) {
  const language::Argument* a = s.find(name);
  if (!a || a->values.empty() || a->values[0].kind != language::Value::Kind::Number)
    return std::nullopt;
  return a->values[0].number;
}

}  // namespace openmss::commands

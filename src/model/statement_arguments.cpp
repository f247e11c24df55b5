#include "model/statement_arguments.hpp"

#include <cmath>

#include "language/schema.hpp"

namespace openmss::model {
namespace {

bool allNumbers(const language::Argument& a) {
  for (const auto& v : a.values)
    if (v.kind != language::Value::Kind::Number) return false;
  return true;
}

// One value that is a number (the common precondition of the single-value reads).
bool oneNumber(const language::Argument& a) {
  return a.values.size() == 1 && a.values[0].kind == language::Value::Kind::Number;
}

bool firstIsNumber(const language::Argument& a) {
  return !a.values.empty() && a.values[0].kind == language::Value::Kind::Number;
}

}  // namespace

std::optional<double> StatementArguments::real(const char* name) {
  const language::Argument* a = s_.find(name);
  if (!a) return std::nullopt;
  if (!oneNumber(*a)) {
    error(a->where, std::string(name) + " needs one number",
          "Write " + std::string(name) + "=<number>.");
    return std::nullopt;
  }
  return a->values[0].number;
}

std::optional<std::vector<double>> StatementArguments::numbers(const char* name, size_t count) {
  const language::Argument* a = s_.find(name);
  if (!a) return std::nullopt;
  if (a->values.size() != count || !allNumbers(*a)) {
    error(a->where, std::string(name) + " needs " + std::to_string(count) + " numbers",
          "Write " + std::string(name) + "=r1,...,r" + std::to_string(count) + ".");
    return std::nullopt;
  }
  std::vector<double> out;
  for (const auto& v : a->values) out.push_back(v.number);
  return out;
}

std::optional<Eigen::Vector3d> StatementArguments::vec3(const char* name) {
  const language::Argument* a = s_.find(name);
  if (!a) return std::nullopt;
  if (a->values.size() != 3 || !allNumbers(*a)) {
    error(a->where, std::string(name) + " needs three numbers",
          "Write " + std::string(name) + "=x,y,z.");
    return std::nullopt;
  }
  return Eigen::Vector3d(a->values[0].number, a->values[1].number, a->values[2].number);
}

std::optional<long> StatementArguments::id(const char* name) {
  const language::Argument* a = s_.find(name);
  if (!a) return std::nullopt;
  if (!oneNumber(*a) || a->values[0].number != std::floor(a->values[0].number) ||
      a->values[0].number <= 0) {
    error(a->where, std::string(name) + " needs one positive identifier",
          "Write " + std::string(name) + "=<id>.");
    return std::nullopt;
  }
  return static_cast<long>(a->values[0].number);
}

std::optional<long> StatementArguments::integer(const char* name, bool allowZero) {
  const language::Argument* a = s_.find(name);
  if (!a) return std::nullopt;
  if (!oneNumber(*a) || a->values[0].number != std::floor(a->values[0].number) ||
      a->values[0].number < (allowZero ? 0.0 : 1.0)) {
    error(
        a->where,
        std::string(name) + " needs one " + (allowZero ? "non-negative" : "positive") + " integer",
        "Write " + std::string(name) + "=<integer>.");
    return std::nullopt;
  }
  return static_cast<long>(a->values[0].number);
}

std::optional<std::string> StatementArguments::word(const char* name) {
  const language::Argument* a = s_.find(name);
  if (!a) return std::nullopt;
  if (a->values.size() != 1 || a->values[0].kind != language::Value::Kind::Word) {
    error(a->where, std::string(name) + " needs one word", "");
    return std::nullopt;
  }
  return a->values[0].text;
}

std::optional<double> StatementArguments::firstNumber(const char* name) const {
  const language::Argument* a = s_.find(name);
  if (!a || !firstIsNumber(*a)) return std::nullopt;
  return a->values[0].number;
}

void StatementArguments::require(const char* name, const char* what) {
  if (const language::StatementSpec* spec = language::findStatementSpec(s_.name))
    for (const auto& arg : spec->arguments)
      if (arg.name == name && arg.required) return;
  if (!s_.has(name))
    error(s_.where, std::string("missing required argument ") + name,
          std::string("Add ") + name + "=" + what + ".");
}

bool StatementArguments::positive(const language::Argument& a, double& out) {
  if (!firstIsNumber(a) || !(a.values[0].number > 0.0)) {
    error(a, a.name + " must be a positive number", "Write " + a.name + "=<value > 0>.");
    return false;
  }
  out = a.values[0].number;
  return true;
}

bool StatementArguments::count(const language::Argument& a, int& out) {
  if (!firstIsNumber(a) || a.values[0].number < 1.0 || a.values[0].number > 1e6) {
    error(a, a.name + " must be a positive whole number", "Write " + a.name + "=<count >= 1>.");
    return false;
  }
  out = static_cast<int>(a.values[0].number);
  return true;
}

bool StatementArguments::within(const language::Argument& a, double low, double high,
                                const std::string& what, double& out) {
  if (!firstIsNumber(a) || !(a.values[0].number >= low && a.values[0].number <= high)) {
    error(a, a.name + " must be " + what, "Write " + a.name + "=<value " + what + ">.");
    return false;
  }
  out = a.values[0].number;
  return true;
}

std::optional<std::vector<double>> StatementArguments::numbers(const language::Argument& a) {
  std::vector<double> out;
  for (const auto& v : a.values) {
    if (v.kind != language::Value::Kind::Number) {
      error(v.where.line > 0 ? v.where : a.where, a.name + " needs numbers, found '" + v.text + "'",
            "Write numeric constants.");
      return std::nullopt;
    }
    out.push_back(v.number);
  }
  return out;
}

void StatementArguments::unsupported(const language::Argument& a, const std::string& hint) {
  error(a, a.name + " is not supported yet", hint);
}

void StatementArguments::error(const language::Argument& a, const std::string& message,
                               const std::string& hint) {
  error(a.where, message, hint);
}

void StatementArguments::error(const SourceLocation& at, const std::string& message,
                               const std::string& hint) {
  diags_.error(at, s_.subject(), message, hint);
  ok_ = false;
}

}  // namespace openmss::model

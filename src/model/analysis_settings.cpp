#include "model/analysis_settings.hpp"

#include <string>

namespace openmss::model {
namespace {

// Reads one positive number (reals) or positive integer; reports what is wrong otherwise.
class ArgumentReader {
 public:
  ArgumentReader(const language::Statement& s, Diagnostics& diags) : s_(s), diags_(diags) {}

  void positive(const language::Argument& a, double& out) {
    if (a.values.empty() || a.values[0].kind != language::Value::Kind::Number ||
        !(a.values[0].number > 0.0)) {
      fail(a, a.name + " must be a positive number", "Write " + a.name + "=<value > 0>.");
      return;
    }
    out = a.values[0].number;
  }
  void count(const language::Argument& a, int& out) {
    if (a.values.empty() || a.values[0].kind != language::Value::Kind::Number ||
        a.values[0].number < 1.0 || a.values[0].number > 1e6) {
      fail(a, a.name + " must be a positive whole number", "Write " + a.name + "=<count >= 1>.");
      return;
    }
    out = static_cast<int>(a.values[0].number);
  }
  void pattern(const language::Argument& a, JacobianPattern& out) {
    if (a.values.empty() || a.values.size() > 10) {
      fail(a, a.name + " takes 1 to 10 of T and F", "Write " + a.name + "=T:F:F:F, for example.");
      return;
    }
    // The values given repeat until MAXIT (digest §1.7): T:F means every other iteration.
    std::array<bool, 10> flags{};
    for (size_t k = 0; k < 10; ++k) {
      const std::string& w = a.values[k % a.values.size()].text;
      flags[k] = w == "T" || w == "TRUE";
    }
    out.evaluate = flags;
  }
  void unsupported(const language::Argument& a, const std::string& hint) {
    fail(a, a.name + " is not supported yet", hint);
  }
  bool ok() const { return ok_; }

 private:
  void fail(const language::Argument& a, const std::string& message, const std::string& hint) {
    diags_.error(a.where, s_.subject(), message, hint);
    ok_ = false;
  }
  const language::Statement& s_;
  Diagnostics& diags_;
  bool ok_ = true;
};

}  // namespace

bool applyEquilibriumArguments(const language::Statement& s, EquilibriumSettings& settings,
                               Diagnostics& diags) {
  ArgumentReader r(s, diags);
  if (s.has("DEFAULT")) settings = {};
  for (const language::Argument& a : s.args) {
    if (a.name == "DEFAULT" || a.name == "LIST" || a.name == "STATIC") continue;
    if (a.name == "ALIMIT")
      r.positive(a, settings.angleLimit);
    else if (a.name == "ERROR")
      r.positive(a, settings.error);
    else if (a.name == "IMBALANCE")
      r.positive(a, settings.imbalance);
    else if (a.name == "MAXIT")
      r.count(a, settings.maxit);
    else if (a.name == "PATTERN")
      r.pattern(a, settings.pattern);
    else if (a.name == "STABILITY")
      r.positive(a, settings.stability);
    else if (a.name == "TLIMIT")
      r.positive(a, settings.translationLimit);
    else
      r.unsupported(a,
                    "Static equilibrium is found by Newton-Raphson on the balance equations "
                    "(docs/theory.md, Statics); dynamic relaxation and its parameters are not "
                    "implemented. Remove " +
                        a.name + ".");
  }
  return r.ok();
}

bool applyInitialConditionArguments(const language::Statement& s,
                                    InitialConditionSettings& settings, Diagnostics& diags) {
  ArgumentReader r(s, diags);
  if (s.has("DEFAULT")) settings = {};
  for (const language::Argument& a : s.args) {
    if (a.name == "DEFAULT" || a.name == "LIST") continue;
    if (a.name == "AERROR")
      r.positive(a, settings.accelerationError);
    else if (a.name == "ALIMIT")
      r.positive(a, settings.angleLimit);
    else if (a.name == "AMAXIT")
      r.count(a, settings.accelerationMaxit);
    else if (a.name == "APATTERN")
      r.pattern(a, settings.accelerationPattern);
    else if (a.name == "ERROR")
      r.positive(a, settings.error);
    else if (a.name == "MAXIT")
      r.count(a, settings.maxit);
    else if (a.name == "PATTERN")
      r.pattern(a, settings.pattern);
    else if (a.name == "TLIMIT")
      r.positive(a, settings.translationLimit);
    else if (a.name == "VERROR")
      r.positive(a, settings.velocityError);
    else
      r.unsupported(a, "Remove " + a.name + ".");
  }
  return r.ok();
}

}  // namespace openmss::model

#include "model/motion_variables.hpp"

#include <algorithm>
#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "expr/expression.hpp"

namespace openmss::model {
namespace {

using language::Statement;

// VARIABLEs read each other at most this deep (a deeper chain is taken for a cycle).
constexpr int kMaxDepth = 16;

// [begin, end) of the call whose name starts near column `column` (1-based) of `text`: from
// the name to its matching closing bracket; npos when it cannot be found.
std::pair<size_t, size_t> callSpan(const std::string& text, int column, const std::string& name) {
  auto upper = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
    return s;
  };
  const std::string up = upper(text);
  size_t begin = column > 0 ? static_cast<size_t>(column - 1) : 0;
  if (up.compare(begin, name.size(), name) != 0) begin = up.find(name);
  if (begin == std::string::npos) return {std::string::npos, std::string::npos};
  size_t p = up.find('(', begin + name.size());
  if (p == std::string::npos) return {std::string::npos, std::string::npos};
  int depth = 0;
  for (; p < up.size(); ++p) {
    if (up[p] == '(') ++depth;
    if (up[p] == ')' && --depth == 0) return {begin, p + 1};
  }
  return {std::string::npos, std::string::npos};
}

const Statement* variableStatement(const std::vector<const Statement*>& variables, long id) {
  for (const Statement* s : variables)
    if (s->name == "VARIABLE" && s->id && *s->id == id) return s;
  return nullptr;
}

struct Inliner {
  const Statement& motion;
  const SourceLocation& where;
  const std::vector<const Statement*>& variables;
  Diagnostics& diags;

  void refuse(const std::string& message) {
    diags.error(where, motion.subject(), message,
                "ADAMS requires a motion to be a function of time only: write the function (or "
                "the VARIABLEs it reads) in terms of TIME, or drive the joint with a force "
                "(SFORCE, GFORCE) when it must follow the system's state.");
  }

  // `text` is a function already parsed without error; `via` names the VARIABLE it belongs to
  // ("" for the motion's own function).
  bool expand(std::string& text, const std::string& via, int depth) {
    Diagnostics quiet;
    expr::Expression e;
    if (!expr::Expression::parse(text, where, motion.subject(), quiet, e)) return false;
    std::vector<expr::HostCall> calls = e.hostCalls();
    // Right to left, so that the columns of the calls still to replace stay valid.
    std::sort(calls.begin(), calls.end(),
              [](const expr::HostCall& a, const expr::HostCall& b) { return a.column > b.column; });
    for (const expr::HostCall& call : calls) {
      if (call.name != "VARVAL" || call.args.empty()) {
        refuse("a MOTION function may depend on TIME only, but " +
               (via.empty() ? std::string("it") : via) + " calls " + call.name);
        return false;
      }
      const long id = call.args[0];
      const std::string name = "VARIABLE/" + std::to_string(id);
      const Statement* v = variableStatement(variables, id);
      const language::Argument* f = v ? v->find("FUNCTION") : nullptr;
      if (!f) {
        refuse("VARVAL(" + std::to_string(id) + ") names no VARIABLE with a FUNCTION");
        return false;
      }
      std::string inner = f->expression;
      if (inner.rfind("USER", 0) == 0) {
        refuse("VARVAL(" + std::to_string(id) + ") reads " + name +
               ", a user-written VARIABLE: its dependence on the state is unknown");
        return false;
      }
      if (depth >= kMaxDepth) {
        refuse("the VARIABLEs read through VARVAL refer to each other in a cycle (at " + name +
               ")");
        return false;
      }
      // The VARIABLE's own syntax errors are reported at its statement.
      expr::Expression check;
      if (!expr::Expression::parse(inner, f->valueWhere, v->subject(), diags, check)) return false;
      if (!expand(inner, "VARVAL(" + std::to_string(id) + ") through " + name, depth + 1))
        return false;
      const auto [begin, end] = callSpan(text, call.column, "VARVAL");
      if (begin == std::string::npos) {
        refuse("VARVAL(" + std::to_string(id) + ") could not be located in the function text");
        return false;
      }
      text.replace(begin, end - begin, "(" + inner + ")");
    }
    return true;
  }
};

}  // namespace

bool inlineTimeVariables(const Statement& motion, const SourceLocation& where,
                         const std::vector<const Statement*>& variables, Diagnostics& diags,
                         std::string& text) {
  Inliner in{motion, where, variables, diags};
  return in.expand(text, "", 0);
}

}  // namespace openmss::model

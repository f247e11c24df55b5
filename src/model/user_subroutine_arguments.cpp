#include "model/user_subroutine_arguments.hpp"

#include <cctype>

#include "expr/expression.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// The argument's values as written (case kept), joined with the delimiters between them.
std::vector<std::string> writtenValues(const Argument& a) {
  std::vector<std::string> out;
  for (const auto& v : a.values) out.push_back(v.written.empty() ? v.text : v.written);
  return out;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t");
  return s.substr(b, e - b + 1);
}

}  // namespace

std::optional<std::vector<double>> userParameters(const Statement& s, Diagnostics& diags,
                                                  const char* argument) {
  const std::string name = argument;
  const Argument* fn = s.find(name);
  if (!fn) {
    diags.error(s.where, s.subject(), "missing required argument " + name,
                "Add " + name + "=USER(r1[,...,r30]): the constants the routines receive as PAR.");
    return std::nullopt;
  }
  const std::string text = trim(fn->expression);
  std::string head;
  for (size_t k = 0; k < text.size() && std::isalpha(static_cast<unsigned char>(text[k])); ++k)
    head += static_cast<char>(std::toupper(static_cast<unsigned char>(text[k])));
  const auto open = text.find('(');
  if (head != "USER" || open == std::string::npos || text.back() != ')') {
    diags.error(fn->valueWhere, s.subject(),
                name + " must be USER(r1[,...,r30]): " + s.name +
                    " takes its equations from user-written routines only",
                "Write " + name + "=USER(...) with the constants the routines read as PAR.");
    return std::nullopt;
  }
  // Split the list at top-level commas.
  std::vector<std::string> items;
  std::string item;
  int depth = 0;
  for (size_t k = open + 1; k + 1 < text.size(); ++k) {
    const char ch = text[k];
    if (ch == '(') ++depth;
    if (ch == ')') --depth;
    if (ch == ',' && depth == 0) {
      items.push_back(item);
      item.clear();
    } else {
      item += ch;
    }
  }
  if (!trim(item).empty() || !items.empty()) items.push_back(item);
  if (items.size() > 30) {
    diags.error(fn->valueWhere, s.subject(),
                "USER(...) has " + std::to_string(items.size()) + " values; at most 30 are allowed",
                "Pass at most 30 constants (ADAMS's limit).");
    return std::nullopt;
  }
  std::vector<double> par;
  bool ok = true;
  for (const std::string& it : items) {
    expr::Expression e;
    if (!expr::Expression::parse(trim(it), fn->valueWhere, s.subject(), diags, e)) {
      ok = false;
      continue;
    }
    if (!e.hostCalls().empty() || e.dependsOnTime()) {
      diags.error(fn->valueWhere, s.subject(),
                  "USER(...) value '" + trim(it) + "' is not a constant",
                  "USER(...) passes constants only; the routines read states through SYSARY.");
      ok = false;
      continue;
    }
    par.push_back(e.evaluate(nullptr, 0.0));
  }
  if (!ok) return std::nullopt;
  return par;
}

user::RoutineName elementRoutineName(const Statement& s, const char* argument) {
  const Argument* r = s.find(argument);
  if (!r || r->values.empty()) return {};
  return user::splitRoutineName(writtenValues(*r).at(0));
}

user::GseRoutineNames gseRoutineNames(const Statement& s, Diagnostics& diags, bool& ok) {
  user::GseRoutineNames names;
  if (const Argument* r = s.find("ROUTINE")) {
    const user::RoutineName rn = user::splitRoutineName(writtenValues(*r).at(0));
    if (!rn.name.empty()) {
      diags.error(r->valueWhere, s.subject(),
                  "ROUTINE=" + writtenValues(*r).at(0) +
                      " names one routine, but a GSE has four (DERIV, OUTPUT, UPDATE, SAMP)",
                  "Write ROUTINE=lib:: for the default names Gse_deriv, Gse_output, Gse_update "
                  "and Gse_sample from library lib, or INTERFACE=lib::deriv, lib::output, "
                  "lib::update, lib::samp.");
      ok = false;
    }
    for (user::RoutineName* n : {&names.deriv, &names.output, &names.update, &names.sample})
      n->library = rn.library;
  }
  if (const Argument* in = s.find("INTERFACE")) {
    if (s.has("ROUTINE")) {
      diags.error(in->where, s.subject(), "ROUTINE and INTERFACE exclude each other",
                  "Keep INTERFACE= (one lib::name per routine) or ROUTINE=lib::.");
      ok = false;
    }
    const std::vector<std::string> v = writtenValues(*in);
    if (v.size() > 4) {
      diags.error(in->valueWhere, s.subject(),
                  "INTERFACE= has " + std::to_string(v.size()) +
                      " entries; a GSE has four "
                      "routines",
                  "List at most DERIV, OUTPUT, UPDATE and SAMP, in that order.");
      ok = false;
    }
    user::RoutineName* slots[] = {&names.deriv, &names.output, &names.update, &names.sample};
    for (size_t k = 0; k < v.size() && k < 4; ++k) *slots[k] = user::splitRoutineName(v[k]);
  }
  return names;
}

}  // namespace openmss::model

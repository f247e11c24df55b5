#include "commands/model_edits.hpp"

#include <algorithm>
#include <vector>

namespace openmss::commands {
namespace {

// Arguments that exclude one another within one statement: giving one in a command removes
// the others (docs/commands.md). FUNCTION and ROUTINE are alternatives of every element; the
// others are the kind switches of MOTION, SFORCE, SPRINGDAMPER, SENSOR and ARRAY.
const std::vector<std::vector<std::string>>& exclusiveGroups() {
  static const std::vector<std::vector<std::string>> g = {
      {"FUNCTION", "ROUTINE"},
      {"DISPLACEMENT", "VELOCITY", "ACCELERATION"},
      {"TRANSLATION", "ROTATION", "X", "Y", "Z", "B1", "B2", "B3"},
      {"EQ", "GE", "LE"},
      {"U", "Y", "IC"},
      {"ACTIONONLY", "ACTION_ONLY"}};
  return g;
}

bool excludes(const std::string& given, const std::string& existing) {
  if (given == existing) return true;
  for (const auto& group : exclusiveGroups()) {
    const bool a = std::find(group.begin(), group.end(), given) != group.end();
    const bool b = std::find(group.begin(), group.end(), existing) != group.end();
    if (a && b) return true;
  }
  return false;
}

bool sameElement(const language::Statement& s, const std::string& kind, long id) {
  return s.name == kind && s.id.value_or(0) == id;
}

}  // namespace

bool isSingletonStatement(const std::string& kind) {
  return kind == "ACCGRAV" || kind == "UNITS" || kind == "OUTPUT" || kind == "EQUILIBRIUM" ||
         kind == "IC" || kind == "INTEGRATOR" || kind == "KINEMATICS" || kind == "DEBUG" ||
         kind == "LSOLVER" || kind == "PREFERENCES";
}

void mergeArguments(const language::Statement& command, language::Statement& target) {
  for (const language::Argument& a : command.args) {
    if (a.name == "LIST") continue;
    auto& args = target.args;
    args.erase(
        std::remove_if(args.begin(), args.end(),
                       [&](const language::Argument& old) { return excludes(a.name, old.name); }),
        args.end());
    args.push_back(a);
  }
}

std::vector<long> statementIds(const language::Dataset& dataset, const std::string& kind) {
  std::vector<long> ids;
  for (const auto& s : dataset.statements)
    if (s.name == kind && s.id) ids.push_back(*s.id);
  return ids;
}

language::Dataset editedDataset(const language::Dataset& dataset, const ModelEdits& edits) {
  language::Dataset out;
  out.file = dataset.file;
  out.title = dataset.title;
  out.sawEnd = dataset.sawEnd;
  out.statements.reserve(dataset.statements.size());
  for (const auto& s : dataset.statements)
    if (!edits.inactive.count({s.name, s.id.value_or(0)})) out.statements.push_back(s);
  for (const auto& c : edits.redefinitions) {
    const long id = c.id.value_or(0);
    bool found = false;
    for (auto& s : out.statements)
      if (sameElement(s, c.name, id)) {
        mergeArguments(c, s);
        found = true;
      }
    // A singleton the data set lacks: the command supplies it (ACCGRAV/ KGRAV=-9.81 on a data
    // set without gravity); the builder reads such statements in any order.
    if (!found && isSingletonStatement(c.name)) {
      language::Statement added = c;
      added.args.clear();
      mergeArguments(c, added);
      out.statements.push_back(std::move(added));
    }
  }
  return out;
}

}  // namespace openmss::commands

#include "language/schema.hpp"

#include <algorithm>

#include "language/name_resolution.hpp"
#include "language/statement_table.hpp"

namespace openmss::language {

namespace {

// Names left at 0 get the shortest prefix that no other name of the same table shares, so
// every canonical name can be abbreviated as far as it stays unambiguous.
void assignAutomaticAbbreviations(std::vector<StatementSpec>& table) {
  std::vector<std::string_view> names;
  for (const auto& s : table) names.push_back(s.name);
  for (auto& s : table) {
    if (s.minAbbreviation == 0) s.minAbbreviation = shortestUniquePrefix(s.name, names);
    std::vector<std::string_view> argumentNames;
    for (const auto& a : s.arguments) argumentNames.push_back(a.name);
    for (auto& a : s.arguments)
      if (a.minAbbreviation == 0) a.minAbbreviation = shortestUniquePrefix(a.name, argumentNames);
  }
}

void markSupported(std::vector<StatementSpec>& table, const std::vector<std::string>& names) {
  for (auto& s : table)
    s.solverSupported = std::find(names.begin(), names.end(), s.name) != names.end();
}

std::vector<StatementSpec> finalStatementTable() {
  auto t = buildStatementTable();
  assignAutomaticAbbreviations(t);
  markSupported(t, {"TITLE", "UNITS", "PART", "MARKER", "JOINT", "MOTION", "SFORCE", "ACCGRAV",
                    "REQUEST", "GRAPHICS", "OUTPUT", "END", "SPRINGDAMPER", "BUSHING", "FIELD",
                    "BEAM", "VFORCE", "VTORQUE", "GFORCE", "EQUILIBRIUM", "IC", "INTEGRATOR",
                    "KINEMATICS", "DEBUG", "MATERIAL", "CONTACT",
                    // what model/model_builder.cpp builds besides (its supportedStatements)
                    "NFORCE", "JPRIM", "GCON", "UCON", "PTCV", "CVCV", "COUPLER", "GEAR",
                    "FRICTION", "VARIABLE", "DIFF", "ARRAY", "LSE", "TFSISO", "PINPUT", "POUTPUT",
                    "GSE", "SENSOR", "RESULTS", "SPLINE", "CURVE", "MATRIX", "STRING"});
  return t;
}

std::vector<StatementSpec> finalCommandTable() {
  auto t = buildCommandTable(buildStatementTable());
  assignAutomaticAbbreviations(t);
  // FILE (MODEL, COMMAND) and HELP are carried out by the program around the session.
  markSupported(
      t, {"OUTPUT", "INTEGRATOR", "GSTIFF", "WSTIFF", "DSTIFF", "SIMULATE", "STOP", "FILE", "HELP",
          "EQUILIBRIUM", "IC", "KINEMATICS", "LINEAR", "DEBUG", "SAVE", "RELOAD",
          // commands/element_commands.cpp and info_commands.cpp
          "ACTIVATE", "DEACTIVATE", "PART", "MARKER", "JOINT", "MOTION", "GCON", "ACCGRAV", "BEAM",
          "BUSHING", "FIELD", "GFORCE", "SFORCE", "SPRINGDAMPER", "VFORCE", "VTORQUE", "ARRAY",
          "SPLINE", "STRING", "VARIABLE", "DIFF", "SENSOR", "REQUEST", "INFO", "SHOW", "TIME",
          "MENU", "PREFERENCES", "LSOLVER", "ENVIRONMENT",
          // commands/control_command.cpp (a user CONSUB)
          "CONTROL"});
  return t;
}

const StatementSpec* findIn(const std::vector<StatementSpec>& table, std::string_view name) {
  for (const auto& s : table)
    if (s.name == name) return &s;
  return nullptr;
}

}  // namespace

const ArgumentSpec* StatementSpec::findArgument(std::string_view canonicalName) const {
  for (const auto& a : arguments)
    if (a.name == canonicalName) return &a;
  return nullptr;
}

const std::vector<StatementSpec>& statementSchema() {
  static const std::vector<StatementSpec> table = finalStatementTable();
  return table;
}

const std::vector<StatementSpec>& commandSchema() {
  static const std::vector<StatementSpec> table = finalCommandTable();
  return table;
}

const StatementSpec* findStatementSpec(std::string_view canonicalName) {
  return findIn(statementSchema(), canonicalName);
}

const StatementSpec* findCommandSpec(std::string_view canonicalName) {
  return findIn(commandSchema(), canonicalName);
}

const char* valueTypeName(ValueType t) {
  switch (t) {
    case ValueType::Flag:
      return "flag";
    case ValueType::Integer:
      return "integer";
    case ValueType::Real:
      return "real";
    case ValueType::Word:
      return "word";
    case ValueType::WordOrNumber:
      return "word or number";
    case ValueType::Expression:
      return "expression";
    case ValueType::Text:
      return "text";
  }
  return "value";
}

}  // namespace openmss::language

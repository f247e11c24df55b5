#pragma once
// The statement and command schema: a table describing every ADAMS data-set statement and
// every command — canonical name, minimum abbreviation, identifier rule and arguments — so
// the reader can resolve abbreviations and check value types and counts in one place, and the
// model builder can ask which statements the solver supports.

#include <string>
#include <string_view>
#include <vector>

namespace openmss::language {

// What an argument's values are. Real accepts integers as well (ADAMS converts them).
enum class ValueType {
  Flag,          // no '=' and no values, e.g. GROUND
  Integer,       // identifiers and counts; "1." and "1.0" are accepted, 1.5 is not
  Real,          // numbers; a trailing D means degrees
  Word,          // names from a fixed list (allowedWords) or free names (file names, routines)
  WordOrNumber,  // either, e.g. ENVIRONMENT VALUE=off or VALUE=3
  Expression,    // a function expression, kept as raw text
  Text,          // free text to the end of the physical line, e.g. COMMENT
};

enum class IdRule { Required, Optional, NotAllowed };

inline constexpr int kUnlimited = 1 << 20;

struct ArgumentSpec {
  std::string name;  // canonical, upper case
  ValueType type = ValueType::Flag;
  int minValues = 0;  // for Flag/Expression/Text these are 0/0, 1/1, 1/1
  int maxValues = 0;
  int minAbbreviation = 0;                // 0 until the table is finalised (then >= 1)
  std::vector<std::string> aliases;       // other exact spellings, e.g. EU for REULER
  std::vector<std::string> allowedWords;  // empty: any word
  bool required = false;                  // a data-set statement without it is an error

  // Builder helpers that read well in the tables.
  ArgumentSpec& abbreviation(int n) {
    minAbbreviation = n;
    return *this;
  }
  ArgumentSpec& alias(std::string a) {
    aliases.push_back(std::move(a));
    return *this;
  }
  ArgumentSpec& mandatory() {
    required = true;
    return *this;
  }
};

struct StatementSpec {
  std::string name;  // canonical, upper case
  int minAbbreviation = 0;
  IdRule idRule = IdRule::Required;
  // Whether the solver implements this statement or command yet. The model layer decides
  // what to do with an unsupported one; the reader only reads it.
  bool solverSupported = false;
  // Commands only: one line saying what the command does, printed by HELP.
  std::string summary;
  std::vector<ArgumentSpec> arguments;

  const ArgumentSpec* findArgument(std::string_view canonicalName) const;
};

// The full tables, finalised: every name has its minimum abbreviation set.
const std::vector<StatementSpec>& statementSchema();
const std::vector<StatementSpec>& commandSchema();

// Exact canonical-name lookups (nullptr when absent).
const StatementSpec* findStatementSpec(std::string_view canonicalName);
const StatementSpec* findCommandSpec(std::string_view canonicalName);

const char* valueTypeName(ValueType t);

}  // namespace openmss::language

#pragma once
// The Dataset: an ADAMS data set (.adm) or command file (.acf) as read, before any meaning is
// attached. Statement and argument names are canonical (full, upper-case) after abbreviation
// resolution against the statement schema; every piece keeps its source location.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/compact_location.hpp"
#include "common/compact_string.hpp"
#include "common/source_location.hpp"

namespace openmss::language {

// The tree is kept lean because a data set of 500,000 statements is read whole: names and
// tokens are CompactStrings (16 bytes, no allocation up to 15 characters) and the locations of
// arguments and values CompactLocations (12 bytes; the file's path is an index into a table),
// both converting to std::string and SourceLocation where those are needed (docs/performance.md,
// "Memory of a parsed data set"). Members are ordered to leave no padding.

// One value of an argument: a number or a word, as written.
struct Value {
  enum class Kind : unsigned char { Number, Word };
  double number = 0.0;  // numeric value; already scaled by pi/180 when written with D
  CompactString text;   // the token exactly as written (upper-cased for words)
  // Added by the reader: the token in its original case (file and routine names, CNAMES),
  // without the quotes of a "quoted" word; the raw text for a Text argument.
  CompactString written;
  CompactLocation where;
  Kind kind = Kind::Number;
  bool isInteger = false;  // written with neither '.' nor exponent (and no D)
  bool degrees = false;    // written with a trailing D
  bool quoted = false;     // written between double quotes (then `text` keeps the case too)
};

struct Argument {
  CompactString name;            // canonical keyword, e.g. "REULER"; for a flag, e.g. "GROUND"
  CompactString spelled;         // as the user wrote it, e.g. "reu"
  std::vector<Value> values;     // values after '=' ("" for flags); separated by ',' or ':'
  std::vector<char> separators;  // separators[k] is the delimiter before values[k+1] (',' or ':')
  CompactString expression;      // FUNCTION=, F2=, ...: the expression with continuation commas
                                 // joined, blanks kept
  CompactLocation where;         // location of the keyword
  CompactLocation valueWhere;    // location of the first value/expression character
  bool isExpression = false;     // FUNCTION=, F2=, ... : the raw expression text is kept
  // Added by the reader: COMMENT=, TITLE=, STRING=... take the raw text to the end of the
  // physical line; it is values[0].text (case kept, trailing blanks trimmed).
  bool isText = false;
};

struct Statement {
  CompactString name;          // canonical statement or command name, e.g. "MARKER"
  CompactString spelled;       // as written
  std::optional<long> id;      // identifier after '/', when given
  std::vector<Argument> args;  // in the order written
  SourceLocation where;        // the line where the statement starts
  int lastLine = 0;            // last physical line of the statement (continuations included)

  // "MARKER/201" or "UNITS" — the subject used in diagnostics.
  std::string subject() const;
  const Argument* find(std::string_view canonicalName) const;
  bool has(std::string_view canonicalName) const { return find(canonicalName) != nullptr; }
};

struct Dataset {
  std::string file;   // path of the file read
  std::string title;  // line 1 (data sets only)
  std::vector<Statement> statements;
  bool sawEnd = false;  // an END statement was read
};

}  // namespace openmss::language

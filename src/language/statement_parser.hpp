#pragma once
// The statement parser shared by data sets and command files: it turns one group of physical
// lines — a first line and its continuation lines — into Statements, resolving names against
// the schema, checking value types and counts, and reporting every problem it finds.

#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "language/source_line.hpp"

namespace openmss::language {

enum class InputKind { DataSet, Command };

// How a physical line joins the statement text begun on an earlier line.
enum class LineJoin {
  First,      // the line a statement starts on
  Comma,      // a continuation line with ',' in column 1 (that comma is not statement text)
  Ampersand,  // the line after one that ended with '&'
};

struct LinePiece {
  const SourceLine* line = nullptr;
  LineJoin join = LineJoin::First;
};

// Parses every statement of a group (several when separated by ';'). Unknown statements are
// diagnosed and left out; statements with bad arguments are kept without those arguments.
// `previousSubject` names the statement before the group, for "this line seems to continue
// PART/2" diagnostics. `requireArguments` false reads statements that only change arguments
// of a statement read before (openmss run --set): its required arguments are not asked for.
std::vector<Statement> parseStatementGroup(const std::vector<LinePiece>& pieces, InputKind kind,
                                           const std::string& file, Diagnostics& diags,
                                           const std::string& previousSubject,
                                           bool requireArguments = true);

}  // namespace openmss::language

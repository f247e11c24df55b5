#pragma once
// Overrides of data-set arguments given on the command line (`openmss run … --set
// SPRINGDAMPER/3.K=12.5`): what a design study changes from one variant to the next
// (docs/studies.md). Each override is read by the data-set reader as the statement
// `SPRINGDAMPER/3, K=12.5`, so abbreviations, value types, D-degrees and function
// expressions are handled exactly as in a data set; its argument then replaces the one of
// that statement in the data set as read, the way a redefining command does
// (model_edits.hpp). Diagnostics are located as `--set:N:COL`, N the override's position
// on the command line, COL the column in its text.

#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"

namespace openmss::commands {

// Applies `overrides` ("STATEMENT/id.ARGUMENT=value", or "STATEMENT.ARGUMENT=value" for a
// statement without id such as ACCGRAV) to `dataset` in order. Every problem is reported in
// `diags` (unknown statement, id or argument, a malformed override); returns false when any
// override was refused (then the data set may carry the ones that were accepted).
bool applyOverrides(const std::vector<std::string>& overrides, language::Dataset& dataset,
                    Diagnostics& diags);

}  // namespace openmss::commands

#pragma once
// Readers of the ADAMS data-set language (.adm) and command files (.acf). They never throw
// and never stop at the first error: every input problem is reported in one pass through
// Diagnostics, with file, line, the statement and its id, and what to change.
// The reading rules are described in docs/language.md.

#include <string>
#include <string_view>

#include "common/diagnostics.hpp"
#include "language/command_file.hpp"
#include "language/dataset.hpp"

namespace openmss::language {

struct ReadOptions {
  // ADAMS documents an 80-column limit, but ADAMS 2012 accepted the 140-column REQUEST lines
  // of our validation models, so longer lines are read; this option warns about them.
  bool warnLongLines = false;
  // false: the statements only change arguments of statements read before (openmss run
  // --set, commands/dataset_overrides.hpp); their required arguments are not asked for.
  bool requireArguments = true;
};

// Reads a data set. Line 1 is the title; statements follow until END. Returns true when the
// file was read without errors (warnings allowed); false when it could not be opened or had
// errors. Statements are appended to `out.statements`.
bool readDatasetFile(const std::string& path, Dataset& out, Diagnostics& diags,
                     const ReadOptions& options = {});
void readDatasetText(std::string_view text, const std::string& fileName, Dataset& out,
                     Diagnostics& diags, const ReadOptions& options = {});

// Reads a command file: model file (line 1), output prefix (line 2), then commands until
// STOP. Returns true when the file was read without errors.
bool readCommandFile(const std::string& path, CommandFile& out, Diagnostics& diags);
void readCommandText(std::string_view text, const std::string& fileName, CommandFile& out,
                     Diagnostics& diags);

}  // namespace openmss::language

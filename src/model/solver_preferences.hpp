#pragma once
// PREFERENCES, LSOLVER and ENVIRONMENT statements: choices of the ADAMS solver's internals
// (threads, contact faceting, the sparse linear solver, environment variables). None of them
// changes what OpenMSS computes, so each option is accepted with one warning that names it
// and says why it has no effect (docs/commands.md, "PREFERENCES, LSOLVER, ENVIRONMENT").

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"

namespace openmss::model {

void applySolverPreferences(const language::Statement& s, Diagnostics& diags);

}  // namespace openmss::model

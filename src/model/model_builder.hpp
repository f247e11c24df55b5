#pragma once
// Dataset -> Model: resolves references, checks the model as a whole and reports every problem
// in one pass with file:line, statement and id, and what to change. The passes, their order and
// the builder of each element family: docs/language.md, "From data set to model".

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"
#include "model/settings_arguments.hpp"

namespace openmss::model {

// Returns true when the model is usable (no errors). Warnings and notes may be added either way.
bool buildModel(const language::Dataset& dataset, Model& model, Diagnostics& diags);

// Binds the host calls of a parsed expression to model measures. Adds diagnostics for unknown
// ids or functions the solver does not evaluate yet. `forForces` (a force, VARIABLE or DIFF
// function) restricts nothing any more: accelerations, reactions and force read-backs are read
// there too (docs/theory.md §4b, §4d); the callers still say what they bind.
bool bindExpression(const Model& model, const std::string& text, const SourceLocation& where,
                    const std::string& subject, bool forForces, Diagnostics& diags,
                    BoundExpression& out, bool forConstraint = false,
                    bool forRequest = false);
// forConstraint (GCON): AX, AY and AZ are accepted and read as principal angles in (-pi, pi];
// elsewhere they are refused until their cumulative (unwrapped) form exists (docs/theory.md §5c).

// DEBUG statement or command: EPRINT is supported; other dumps warn and have no effect.
void applyDebugArguments(const language::Statement& s, DebugSettings& debug, Diagnostics& diags);

}  // namespace openmss::model

#pragma once
// Dataset -> Model for GCON/id [, I=id], FUNCTION=e (docs/theory.md §5c): the expression is
// bound to model measures and checked to be a holonomic, time-independent function of marker
// positions and orientations, which is what the constraint equations can differentiate twice.

#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Needs every marker to exist (call after the markers are built).
void buildGeneralConstraints(const std::vector<const language::Statement*>& statements,
                             Model& model, Diagnostics& diags);

}  // namespace openmss::model

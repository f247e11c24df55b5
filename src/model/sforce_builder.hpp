#pragma once
// Dataset -> Model for SFORCE statements: a single-component force along the I-J line
// (TRANSLATION) or torque about z_J (ROTATION), action-reaction or ACTIONONLY, with a FUNCTION
// expression (docs/theory.md §6).

#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Model::sforces without their functions. Needs every marker.
void buildSForces(const std::vector<const language::Statement*>& statements, Model& model,
                  Diagnostics& diags);
// Binds FUNCTION= of every SFORCE built, once every element a function may read exists.
void bindSForceFunctions(const std::vector<const language::Statement*>& statements, Model& model,
                         Diagnostics& diags);

}  // namespace openmss::model

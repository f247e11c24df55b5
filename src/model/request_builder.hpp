#pragma once
// Dataset -> Model for REQUEST statements: DISPLACEMENT, VELOCITY, ACCELERATION or FORCE of
// the I marker (relative to J, in RM's axes), or up to eight expressions F1..F8. What each
// column of the .req holds: docs/language.md, "REQUEST".

#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Model::requests, their F1..F8 bound. Runs last: a request may read every element.
void buildRequests(const std::vector<const language::Statement*>& statements, Model& model,
                   Diagnostics& diags);

}  // namespace openmss::model

#pragma once
// Dataset -> Model for the constraints that couple joints: COUPLER (two or three joints'
// displacements in a linear relation) and GEAR (common velocity at a contact point), with
// their data-set checks (joint types, TYPE and SCALES counts, the CV marker's part).

#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

bool isCouplingStatement(const std::string& name);

// Needs every joint and marker to exist (call after the joints are built).
void buildCouplings(const std::vector<const language::Statement*>& statements, Model& model,
                    Diagnostics& diags);

}  // namespace openmss::model

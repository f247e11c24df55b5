#pragma once
// Dataset -> Model for UCON/id, FUNCTION=USER(r1, ..., r30) [, ROUTINE=lib::name]
// (docs/user-subroutines.md "UCON", docs/theory.md §5f): loads UCOSUB, runs its initialization
// (UCOVAR declares the part variables) and checks the declared parts and codes.

#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Needs every part and marker to exist (call after the markers are built).
void buildUserConstraints(const std::vector<const language::Statement*>& statements, Model& model,
                          Diagnostics& diags);

}  // namespace openmss::model

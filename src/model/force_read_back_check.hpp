#pragma once
// Force read-backs inside force functions (docs/theory.md §4d): an SFORCE, VFORCE, VTORQUE or
// GFORCE function that reads another element's force (SFORCE(...), VFORCE(...), FX..TM, ...)
// is evaluated by evaluating that element first. Read-backs that lead back to the element
// itself can never be ordered; they are refused here, naming the cycle.

#include "common/diagnostics.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Reports every element whose function reaches itself through force read-backs. Returns false
// when there is such a cycle.
bool checkForceReadBackCycles(const Model& model, Diagnostics& diags);

}  // namespace openmss::model

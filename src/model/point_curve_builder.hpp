#pragma once
// Dataset -> Model for PTCV (point-to-curve constraint; docs/theory.md §5d), with its data-set
// checks: the CURVE exists, I and RM lie on different parts, JFLOAT on RM's part, and I starts
// on the curve.

#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Needs every marker and CURVE to exist (call after the parts and data elements are built).
void buildPointCurves(const std::vector<const language::Statement*>& statements, Model& model,
                      Diagnostics& diags);

}  // namespace openmss::model

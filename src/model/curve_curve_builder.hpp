#pragma once
// Dataset -> Model for CVCV (curve-to-curve constraint; docs/theory.md §5e), with its data-set
// checks: both CURVEs exist and lie in the x-y plane of their RM markers, IRM and JRM lie on
// different parts, IFLOAT (JFLOAT) on IRM's (JRM's) part, and the curves start in contact.

#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Needs every marker and CURVE to exist (call after the parts and data elements are built).
void buildCurveCurves(const std::vector<const language::Statement*>& statements, Model& model,
                      Diagnostics& diags);

}  // namespace openmss::model

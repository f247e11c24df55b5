#pragma once
// Dataset -> Model for MOTION statements: a joint motion (JOINT=, along or about the joint's z
// axis; TRANSLATION or ROTATION on a cylindrical joint) or a marker-pair motion (I=, J= with one
// of X, Y, Z, B1, B2, B3), its form (DISPLACEMENT, VELOCITY, ACCELERATION with ICDISP, ICVEL)
// and its function of TIME. The equations: docs/theory.md §5.

#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Model::motions. Needs every joint and marker (buildJoints). `variables`: the VARIABLE
// statements a FUNCTION may read through VARVAL (when they are functions of TIME;
// motion_variables.hpp); other statements in the list are skipped.
void buildMotions(const std::vector<const language::Statement*>& statements,
                  const std::vector<const language::Statement*>& variables, Model& model,
                  Diagnostics& diags);

}  // namespace openmss::model

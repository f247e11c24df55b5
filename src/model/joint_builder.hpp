#pragma once
// Dataset -> Model for JOINT and JPRIM statements: the joint or primitive type, the I and J
// markers (on two parts), the type's own data (PD of RACKPIN, PITCH of SCREW) and the joint
// initial conditions (IC, ICTRAN, ICROT). The equations of each type: docs/theory.md §5.

#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Model::joints and Model::jointIndex. Needs every marker (PartBuilder::build).
void buildJoints(const std::vector<const language::Statement*>& statements, Model& model,
                 Diagnostics& diags);
// Model::jprims and Model::jprimIndex. Needs every marker.
void buildJointPrimitives(const std::vector<const language::Statement*>& statements, Model& model,
                          Diagnostics& diags);

}  // namespace openmss::model

#pragma once
// Dataset -> Model for the force elements beyond SFORCE: SPRINGDAMPER, BUSHING, FIELD, BEAM,
// VFORCE, VTORQUE, GFORCE, with the data-set checks of each (required arguments, signs,
// marker conventions) and the lookup of their read-back functions (SPDP, BUSH, ...).

#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

bool isForceElementStatement(const std::string& name);

// Builds the elements' structures (everything but expression binding, which needs every force
// element to exist first: bindForceElementFunctions).
void buildForceElements(const std::vector<const language::Statement*>& statements, Model& model,
                        Diagnostics& diags);
// NFORCE (nforce_builder.cpp): its markers and MATRIX data, checked for size.
void buildNForce(const language::Statement& s, Model& model, Diagnostics& diags);
// Binds the FX= ... TZ= expressions of VFORCE, VTORQUE and GFORCE.
void bindForceElementFunctions(const std::vector<const language::Statement*>& statements,
                               Model& model, Diagnostics& diags);

// The read-back function names SPDP, BUSH, FIELD, BEAM, VFORCE, VTORQ, GFORCE: their measure
// kind, and the index of element `id` (-1 when there is none).
bool forceElementReadBack(const std::string& function, MeasureKind* kind);
int findForceElement(const Model& model, MeasureKind kind, long id);

}  // namespace openmss::model

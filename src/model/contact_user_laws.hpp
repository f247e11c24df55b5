#pragma once
// CONTACT's user-written force laws (docs/user-subroutines.md, "CNFSUB and CFFSUB"):
// NORMAL_FUNCTION=USER(r1, ..., r30) [, NORMAL_ROUTINE=lib::name] replaces IMPACT/POISSON by
// CNFSUB, FRICTION_FUNCTION=USER(...) [, FRICTION_ROUTINE=lib::name] replaces the Coulomb
// curve's MU_STATIC ... FRICTION_TRANSITION_VELOCITY by CFFSUB.

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Loads the routines the statement names into c (its IGEOM/JGEOM already read, for the
// routines' struct). False with located diagnostics.
bool bindContactUserLaws(const language::Statement& s, const Model& model, Contact& c,
                         Diagnostics& diags);

}  // namespace openmss::model

#pragma once
// UNITS statement: the unit-consistency factor UCF (Force * UCF = Mass * Acceleration) and the
// request-file units tag.

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

void applyUnits(const language::Statement& s, Units& units, Diagnostics& diags);

}  // namespace openmss::model

#pragma once
// UNITS statement: the unit-consistency factor UCF (Force * UCF = Mass * Acceleration) and the
// request-file units tag.

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

void applyUnits(const language::Statement& s, Units& units, Diagnostics& diags);

// SI value of one unit of a canonical unit name (Units::length, ...); 1 for an unknown name.
double unitInSi(const std::string& name);
// Its symbol for GTUNTS, at most 3 characters (s, ms, mm, in, N, lbf, kg, ...).
std::string unitSymbol(const std::string& name);

}  // namespace openmss::model

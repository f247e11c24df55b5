#pragma once
// VARVAL in MOTION functions (docs/theory.md §5, "Motions reading VARIABLEs"). ADAMS requires a
// motion to be a function of time only; a data set may still write it through VARIABLEs that
// are themselves functions of TIME (the FRS5 corpus data sets: MOTION/5, FUNCTION =
// VARVAL(1001)+VARVAL(1002), each VARIABLE a function of TIME). Such a VARVAL is replaced by
// its VARIABLE's function, so the motion keeps the exact time jets (velocity and acceleration)
// every motion has; a VARIABLE that reads the system's state is refused with its reason.

#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"

namespace openmss::model {

// `text` (the FUNCTION of `motion`, at `where`) with every VARVAL(id) replaced by
// "(<VARIABLE/id's FUNCTION>)", recursively. False, with a located error, when a VARVAL names no
// VARIABLE, a user-written one, or one whose function (or a VARIABLE it reads) depends on
// anything but TIME and data elements, and for a cycle of VARIABLEs.
bool inlineTimeVariables(const language::Statement& motion, const SourceLocation& where,
                         const std::vector<const language::Statement*>& variables,
                         Diagnostics& diags, std::string& text);

}  // namespace openmss::model

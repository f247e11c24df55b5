#pragma once
// The arguments that name user-written subroutines on a statement (docs/language.md,
// "User-written subroutines"): FUNCTION=USER(r1, ..., r30) and ROUTINE=lib::name, and the
// GSE's INTERFACE=lib::deriv, lib::output, lib::update, lib::samp.

#include <optional>
#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "user/loaded_gse_routines.hpp"

namespace openmss::model {

// The constants of FUNCTION=USER(...) (each may be a constant expression such as 2*PI), or
// nullopt with a diagnostic: FUNCTION missing, not USER(...), more than 30 values, a value
// that reads the model.
// `argument` names the USER(...) argument (CONTACT: NORMAL_FUNCTION, FRICTION_FUNCTION).
std::optional<std::vector<double>> userParameters(const language::Statement& s, Diagnostics& diags,
                                                  const char* argument = "FUNCTION");

// ROUTINE=lib::name (or EVALUATE_ROUTINE=) of a one-routine element, case kept (empty parts: the defaults).
user::RoutineName elementRoutineName(const language::Statement& s,
                                     const char* argument = "ROUTINE");

// The four GSE routines' library and name: INTERFACE= entries in the order DERIV, OUTPUT,
// UPDATE, SAMP, or ROUTINE=lib (or lib::) for all four under their default names. `ok` is
// cleared with a diagnostic for a ROUTINE that names one routine (a GSE has four).
user::GseRoutineNames gseRoutineNames(const language::Statement& s, Diagnostics& diags, bool& ok);

}  // namespace openmss::model

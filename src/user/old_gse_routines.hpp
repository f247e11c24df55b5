#pragma once
// The old GSE interface (docs/user-subroutines.md): GSESUB gives x' and y from the states and
// inputs it receives as arguments; GSEXX, GSEXU, GSEYX, GSEYU, when the library has them, give
// the partials d x'/dx, d x'/du, dy/dx, dy/du (column-major), else the solver differences.

#include <memory>
#include <string>
#include <vector>

#include "user/loaded_gse_routines.hpp"

namespace openmss::user {

// Whether `library` (empty: the default library) should serve the GSE through the old
// interface: it exports GSESUB in some spelling and no GSE_DERIV / GSE_OUTPUT.
bool prefersOldGseInterface(const std::string& library, const std::string& baseDirectory);

// Loads GSESUB (required) and the four partial routines (optional) from `library` and runs
// the initialization pass (IFLAG = 1, then 3). Null with one line per problem in `errors`.
std::shared_ptr<const GseRoutines> loadOldGseRoutines(const GseDescription& description,
                                                      const std::string& library,
                                                      const std::string& baseDirectory,
                                                      std::vector<std::string>& errors);

}  // namespace openmss::user

#pragma once
// COUSUB, COUXX, COUXX2: COUPLER/id, JOINTS=..., FUNCTION=USER(r1, ..., r30) (docs/user-
// subroutines.md, "COUPLER"). The mechanics passes the coupled joints' displacements; COUSUB
// returns the constraint value phi (phi = 0 is enforced), COUXX its first and COUXX2 its
// second partials, which give the equation, its Newton matrix and its acceleration terms.

#include <memory>
#include <string>

#include "user/element_interfaces.hpp"
#include "user/element_routine.hpp"

namespace openmss::user {

struct CouplerDescription {
  ElementData element;              // subject, id, PAR, the model's data for the utilities
  int joints[3] = {0, 0, 0};        // JOINT ids as written
  char types[3] = {'R', 'R', 'R'};  // 'T' or 'R' per joint
  int count = 2;
};

// The three routines: names[0] COUSUB (required), names[1] COUXX, names[2] COUXX2. With
// `explicitly[k]` the routine must exist; otherwise it is optional (central differences of
// COUSUB replace it) and looked up only when `partialRoutines`. Runs the initialization calls
// (IFLAG = 1, then 3, at zero displacements). Null with the reason in `error`.
std::shared_ptr<const CouplerRoutine> loadCouplerRoutine(
    const CouplerDescription& coupler, const RoutineName names[3], const bool explicitly[3],
    bool partialRoutines, const std::string& baseDirectory, std::string& error);

}  // namespace openmss::user

#pragma once
// FIESUB: FIELD/id, I=, J=, FUNCTION=USER(r1, ..., r30) (docs/user-subroutines.md). The
// mechanics passes I's displacement and velocity relative to J; the routine returns the load
// and, when asked (DFLAG), its 6x6 partials, which give the Newton matrix the element's exact
// derivatives through the chain rule.

#include <memory>
#include <string>

#include "user/element_interfaces.hpp"
#include "user/element_routine.hpp"

namespace openmss::user {

// Loads FIESUB (ROUTINE=lib::name or the default library) and runs its initialization call
// (IFLAG = 1, then 3, at zero displacement and velocity). Null with the reason in `error`.
std::shared_ptr<const FieldRoutine> loadFieldRoutine(const ElementData& element,
                                                     const RoutineName& routine,
                                                     const std::string& baseDirectory,
                                                     std::string& error);

}  // namespace openmss::user

#pragma once
// CNFSUB and CFFSUB: CONTACT/id, NORMAL_FUNCTION=USER(r1, ..., r30) [, NORMAL_ROUTINE=lib::name]
// and FRICTION_FUNCTION=USER(...) [, FRICTION_ROUTINE=lib::name] (docs/user-subroutines.md,
// "CNFSUB and CFFSUB"). The mechanics calls them at each contact point with explicit arguments;
// partials the routine leaves unset come from central differences.

#include <memory>
#include <string>
#include <vector>

#include "user/contact_interfaces.hpp"
#include "user/element_routine.hpp"

namespace openmss::user {

// The CONTACT as the routines' struct carries it (sAdamsContactFriction).
struct ContactElementData {
  ElementData element;  // subject, id, par, data
  std::vector<int> igeom, jgeom;
};

// Load the routine (NORMAL_ROUTINE / FRICTION_ROUTINE or the default library and name) and run
// its initialization calls (IFLAG = 1, then 3, at zero arguments). Null with the reason in
// `error`.
std::shared_ptr<const ContactNormalRoutine> loadContactNormalRoutine(
    const ContactElementData& element, const RoutineName& routine, const std::string& baseDirectory,
    std::string& error);
std::shared_ptr<const ContactFrictionRoutine> loadContactFrictionRoutine(
    const ContactElementData& element, const RoutineName& routine, const std::string& baseDirectory,
    std::string& error);

}  // namespace openmss::user

#pragma once
// The measures behind a SYSFNC or SYSARY request (docs/user-subroutines.md, "SYSFNC and
// SYSARY"): SYSFNC names one expression function with integer arguments (DX, VARVAL, JOINT,
// ...), SYSARY a group of them (DISP = DX, DY, DZ, PSI, THETA, PHI; VEL; ACC; FORCE; ...).

#include <string>
#include <vector>

#include "expr/expression.hpp"

namespace openmss::user {

bool isSysaryName(const std::string& upperName);
// False with the reason when the name or the number of arguments is not accepted.
bool sysfncCall(const std::string& name, const int* ipar, int nsize,
                std::vector<expr::HostCall>& calls, std::string& why);
bool sysaryCalls(const std::string& name, const int* ipar, int nsize,
                 std::vector<expr::HostCall>& calls, std::string& why);

}  // namespace openmss::user

#pragma once
// The FCL narrow phase of CONTACT as a run-time module (docs/architecture.md, "FCL module"):
// libfcl's 29,000 BIND_NOW relocations cost every process 7 ms at start-up when linked in, so
// openmss_fcl.so (mechanics/contact/fcl_narrow_phase.cpp) is opened only when a model has a
// pair that needs it. This module is the one that calls dlopen (user_library.hpp).

#include <string>

namespace openmss::user {

// The name of the module's one exported function (extern "C").
inline constexpr const char* kFclEntryName = "openmss_fcl_library_contacts";

// The address of the module's entry point, opening the module on the first call (once per
// process, thread-safe). Null if it did not load; then `why` names each path tried and the
// loader's message.
void* fclModuleEntry(std::string& why);

// Whether the module has been opened in this process (a model without FCL pairs never opens it).
bool fclModuleLoaded();

}  // namespace openmss::user

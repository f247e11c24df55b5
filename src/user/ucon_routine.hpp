#pragma once
// UCOSUB and UCOVAR: UCON/id, FUNCTION=USER(r1, ..., r30) [, ROUTINE=lib::name]
// (docs/user-subroutines.md, "UCON"). The routine declares with UCOVAR, at IFLAG = 3, the part
// variables its constraint reads; the mechanics then passes their values and gets back the
// constraint value, its first partials (ARRAY) and its second partials (XMATRX).

#include <memory>
#include <string>
#include <vector>

#include "user/element_interfaces.hpp"
#include "user/element_routine.hpp"

namespace openmss::user {

// The most variables one UCON may declare (ADAMS: "as many as thirty").
inline constexpr int kMaxUconVariables = 30;

// What UCOVAR declared: parts[k] (PART ids as written) and codes[k], in the order of q.
struct UconVariables {
  std::vector<int> parts;
  std::vector<int> codes;
};

// Loads UCOSUB under `name` (default name UCOSUB) and runs its initialization (IFLAG = 1, then
// 3, where it must call UCOVAR). Null with the reason in `error` (no routine, UCOVAR not called
// or called with unequal or too long lists, a fatal condition in the routine).
std::shared_ptr<const UserConstraintRoutine> loadUserConstraintRoutine(
    const ElementData& element, const RoutineName& name, const std::string& baseDirectory,
    UconVariables& declared, std::string& error);

}  // namespace openmss::user

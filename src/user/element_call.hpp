#pragma once
// What the utility subroutines (utility_subroutines.cpp) ask of the element routine that is
// running on this thread (element_routine.cpp). Internal to src/user.

#include <string>

#include "user/element_routine.hpp"

namespace openmss::user::detail {

// Empty functions, one in each file of exported utilities: calling them links those files
// into the program from the static library, so that a user library finds every utility when
// it is loaded (RTLD_NOW), even one nothing in OpenMSS calls.
void anchorUtilitySubroutines();
void anchorMathUtilities();
void anchorDataUtilities();
void anchorConversionUtilities();
void anchorSplineReader();
inline void anchorUtilities() {
  anchorUtilitySubroutines();
  anchorMathUtilities();
  anchorDataUtilities();
  anchorConversionUtilities();
  anchorSplineReader();
}

// The model data of the running routine's model (null: none, or no routine running).
const ModelData* elementModelData();

// True while an element routine runs on this thread.
bool elementCallActive();
// SYSFNC / SYSARY of the running routine: in the dependency pass they record the measures and
// return zeros; in an evaluation they return the values the host supplied. False with a
// message for the running routine's fatal error when the request cannot be served.
bool elementSysfnc(const std::string& name, const int* ipar, int nsize, double* value);
bool elementSysary(const std::string& name, const int* ipar, int nsize, double* values, int* count);
bool elementSyspar(const std::string& name, const int* ipar, int nsize, const double* partials,
                   int npartl);
bool elementNeedsPartials();
// MODE (the analysis code of docs/expressions.md) for GETMOD and GETINM: recorded as a measure
// in the dependency pass like a SYSFNC call (0 there). False outside an evaluation subroutine.
bool elementMode(double* mode);
double elementTime();
// ERRMES with a stopping end flag (or any other fatal condition) in the running routine.
void elementFatal(const std::string& text);
// The running routine's subject ("SFORCE/3") and ADAMS name ("SFOSUB"), for messages.
std::string elementWho();

}  // namespace openmss::user::detail

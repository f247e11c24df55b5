#pragma once
// Evaluation of an expression without a model, for the command-line calculator: only numbers,
// constants, TIME and the functions evaluated by this module. Expressions that need a model
// (marker and force measures, VARVAL, MODE, ...) are refused with a diagnostic.

#include <string>

#include "common/diagnostics.hpp"

namespace openmss::expr {

// On success stores the value and d value / d TIME (either pointer may be null) and returns
// true. On failure adds diagnostics located at "<command line>" and returns false.
bool evaluateStandalone(const std::string& text, double time, double* value, double* dvalueDtime,
                        Diagnostics& diags);

}  // namespace openmss::expr

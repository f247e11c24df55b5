#pragma once
// The arguments of the INTEGRATOR, EQUILIBRIUM, IC and KINEMATICS statements and commands applied
// to their settings (model/analysis_settings.hpp). Apart from the settings themselves so that the
// layers that only read the settings (mechanics, analysis) do not see the language layer.

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/analysis_settings.hpp"

namespace openmss::model {

// Apply the arguments of an INTEGRATOR statement/command (or of the FORTRAN-era GSTIFF,
// WSTIFF, DSTIFF commands: `method` then names the integrator they select). DEFAULT resets
// everything first. Out-of-range values and arguments without an implementation are errors.
bool applyIntegratorArguments(const language::Statement& s, IntegratorSettings& settings,
                              Diagnostics& diags, const char* method = nullptr);

// Apply the arguments of an EQUILIBRIUM or IC statement/command. Unsupported arguments
// (the FORTRAN dynamic-relaxation options of EQUILIBRIUM) and out-of-range values are errors.
// DEFAULT resets everything first. Returns false when an error was added.
bool applyEquilibriumArguments(const language::Statement& s, EquilibriumSettings& settings,
                               Diagnostics& diags);
bool applyInitialConditionArguments(const language::Statement& s,
                                    InitialConditionSettings& settings, Diagnostics& diags);
// KINEMATICS: AMAXIT and APATTERN are accepted with a warning (the accelerations are one
// direct linear solve, so they have no effect); bad values and unknown arguments are errors.
bool applyKinematicArguments(const language::Statement& s, KinematicSettings& settings,
                             Diagnostics& diags);

}  // namespace openmss::model

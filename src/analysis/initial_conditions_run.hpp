#pragma once
// The initial-condition analysis (docs/theory.md §7): positions assembled with the IC
// parameters (EXACT, JOINT IC= held), then velocities, user algebraic equations and
// accelerations with the constraint forces. Every transient and linear analysis starts with it
// unless the run state already holds a consistent state; SIMULATE/INITIAL_CONDITIONS runs it
// alone, up to the phase it names.

#include "analysis/analysis_context.hpp"
#include "analysis/run_settings.hpp"
#include "mechanics/initial_conditions.hpp"

namespace openmss::analysis {

// Position assembly at the run state's time with the IC parameters; warns for each EXACT
// coordinate the constraints changed. A redundant equation left violated makes it fail.
mechanics::AssemblyResult assembleForInitialConditions(const AnalysisContext& run);

// Writes what the assembly moved to the message file; reports and returns false when it could
// not close the constraints.
bool reportAssembly(const AnalysisContext& run, const mechanics::AssemblyResult& r);

// The residuals of the velocity and acceleration phases at the run state: the largest velocity
// constraint error and the largest force-balance error (checked against the IC and KINEMATICS
// statements' VERROR and AERROR).
void phaseResiduals(const AnalysisContext& run, double& verr, double& aerr);

// All phases at the run state's time; on success the run state holds the consistent state and
// is marked initialized.
bool solveInitialConditions(const AnalysisContext& run);

// SIMULATE/INITIAL_CONDITIONS: the phases up to `settings.last`, their residual checks against
// VERROR and AERROR, and one output step.
bool runInitialConditions(const AnalysisContext& run, const InitialConditionsRun& settings);

}  // namespace openmss::analysis

#pragma once
// SIMULATE/TRANSIENT, /DYNAMICS and /KINEMATICS: the transient analyses over the output times
// of one request. runTransient checks that the request fits the model and picks the kind
// (TRANSIENT is kinematic for a model without degrees of freedom and nothing to integrate);
// runKinematics and runDynamics are the two drivers (kinematic_run.cpp, dynamic_run.cpp).
// Each first runs the initial conditions and writes the first output step when the run
// state is not initialized yet, and leaves the run state at the last output.

#include "analysis/analysis_context.hpp"
#include "analysis/run_settings.hpp"

namespace openmss::analysis {

bool runTransient(const AnalysisContext& run, const TransientRun& settings);

// Position, velocity and acceleration analyses at each output time (zero degrees of freedom).
bool runKinematics(const AnalysisContext& run, const TransientRun& settings);

// The equations of motion integrated with the model's INTEGRATOR settings
// (analysis/integrator_factory.hpp), SENSOR events and GSE samples on the way. A SENSOR with
// HALT sets RunState::halted.
bool runDynamics(const AnalysisContext& run, const TransientRun& settings);

// Shared by the two drivers (transient_run.cpp): the initial conditions and first output step
// when needed, the analysis mode, the "Begin Simulation" banner; and the closing lines.
bool beginTransient(const AnalysisContext& run, bool kinematic);
void endTransient(const AnalysisContext& run);

}  // namespace openmss::analysis

#pragma once
// LINEAR/EIGENSOL and LINEAR/STATEMAT (docs/theory.md, "Linear analysis"): the equations
// linearised about the run state (the initial conditions first when no analysis has run
// yet), then the eigenvalues and mode shapes to the message file, or the state matrices to
// files.

#include "analysis/analysis_context.hpp"
#include "analysis/run_settings.hpp"

namespace openmss::analysis {

bool runLinear(const AnalysisContext& run, const LinearRun& settings);

}  // namespace openmss::analysis

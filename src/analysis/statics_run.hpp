#pragma once
// SIMULATE/STATICS (docs/theory.md, "Statics"): one static equilibrium at the run state's
// time, or a quasi-static sequence of equilibria at the output times while the motions
// advance. Afterwards the run state holds the last equilibrium with the velocities and
// accelerations the motions demand, so that a dynamic analysis can start from it.

#include "analysis/analysis_context.hpp"
#include "analysis/run_settings.hpp"

namespace openmss::analysis {

bool runStatics(const AnalysisContext& run, const StaticsRun& settings);

}  // namespace openmss::analysis

#pragma once
// SIMULATE/{TRANSIENT | DYNAMICS | KINEMATICS | STATICS | INITIAL_CONDITIONS} read into the
// typed request of the analysis it asks for (analysis/run_settings.hpp). Errors are located
// at the command; nothing runs here.

#include <optional>
#include <variant>

#include "analysis/run_settings.hpp"
#include "common/diagnostics.hpp"
#include "language/dataset.hpp"

namespace openmss::commands {

using SimulateRequest =
    std::variant<analysis::TransientRun, analysis::StaticsRun, analysis::InitialConditionsRun>;

// `now` is the run state's time: DURATION counts from it, END must lie after it.
std::optional<SimulateRequest> readSimulate(const language::Statement& command, double now,
                                            Diagnostics& diags);

}  // namespace openmss::commands

#pragma once
// LINEAR/EIGENSOL [, NODAMPIN] [, NOVECTOR] and LINEAR/STATEMAT [, PINPUT=id] [, POUTPUT=id]
// [, FORMAT=MATLAB | MATRIXX] [, FILE=name] read into the typed request of the linear
// analysis (analysis/run_settings.hpp). Errors are located at the command or its argument.

#include <optional>
#include <string>

#include "analysis/run_settings.hpp"
#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::commands {

// `outputDirectory` and `outputPrefix` place the state-matrix files when FILE= is absent or
// relative.
std::optional<analysis::LinearRun> readLinear(const language::Statement& command,
                                              const model::Model& model,
                                              const std::string& outputDirectory,
                                              const std::string& outputPrefix, Diagnostics& diags);

}  // namespace openmss::commands

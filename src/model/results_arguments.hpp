#pragma once
// RESULTS statement and the REQUEST arguments that name .res components (CNAMES): what the
// .res writer honours, read from the data set, with a located warning for each argument it
// does not honour (docs/output-files.md, "RESULTS arguments").

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/results_settings.hpp"

namespace openmss::model {

// Reads RESULTS and the CNAMES, CUNITS, CLABELS, RESULTS_NAME of every REQUEST.
ResultsSettings readResultsSettings(const language::Dataset& dataset, Diagnostics& diags);

}  // namespace openmss::model

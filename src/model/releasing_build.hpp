#pragma once
// The model build of the callers that drop the statement tree after it (openmss check,
// Session::loadModel): model_builder.hpp's buildModel, releasing the arguments of each CONTACT
// statement once its contact is built. A data set of 500,000 CONTACTs then never holds its
// whole statement tree and all its contacts at once (docs/performance.md, "Memory of a parsed
// data set"). The CONTACT statements keep their name, id and location; the diagnostics are
// those of buildModel.

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

bool buildModelReleasingContacts(language::Dataset& dataset, Model& model, Diagnostics& diags);

}  // namespace openmss::model

#pragma once
// The header and directory of a model's request file: the title, the units tag of its UNITS
// statement, and one directory entry per REQUEST (docs/output-files.md).

#include <vector>

#include "model/model.hpp"
#include "output/request_file.hpp"

namespace openmss::output {

// The header of `model`'s request file. `unitsKnown` is set false when the request-file tag
// of the model's units is not known: the header then names SI although the values are in the
// model's units, and the caller warns.
RequestFileHeader requestFileHeader(const model::Model& model, bool* unitsKnown);

// One directory entry per REQUEST, in Model::requests order.
std::vector<RequestEntry> requestEntries(const model::Model& model);

}  // namespace openmss::output

#pragma once
// COUPLER/id, JOINTS=..., [TYPE=...,] FUNCTION=USER(r1, ..., r30) [, ROUTINE=lib::cousub
// [, lib::couxx, lib::couxx2]]: loads COUSUB/COUXX/COUXX2 into the coupler
// (docs/user-subroutines.md, "COUPLER").

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// `c` has its joints and rotation flags; fills c.user. False with located diagnostics.
bool bindUserCoupler(const language::Statement& s, const Model& model, Coupler& c,
                     Diagnostics& diags);

}  // namespace openmss::model

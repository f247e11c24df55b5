#pragma once
// Dataset -> Model for CONTACT (docs/theory.md §6c): the GRAPHICS solids each side names, the
// normal law (IMPACT or POISSON) and Coulomb friction, with a located diagnostic for every
// geometry or argument the solver does not simulate.

#include <functional>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Builds every CONTACT of `statements` (after parts and markers), reading the GRAPHICS
// statements of `dataset` they name. `done`, when given, is called with each statement once
// nothing more is read from it (buildModelReleasingContacts releases its arguments).
void buildContacts(const std::vector<const language::Statement*>& statements,
                   const language::Dataset& dataset, Model& model, Diagnostics& diags,
                   const std::function<void(const language::Statement&)>& done = {});

// The index of CONTACT/id in model.contacts, -1 when there is none.
int findContact(const Model& model, long id);

}  // namespace openmss::model

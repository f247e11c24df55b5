#pragma once
// What the commands of a session have changed in the model: which elements ACTIVATE and
// DEACTIVATE switched off, and which statements a redefining command (SFORCE/id, FUNCTION=...,
// ACCGRAV/ KGRAV=..., PART/id, MASS=...) rewrote. The Dataset as read is never edited: the model
// of the next analysis is built from the Dataset with these edits laid over it
// (docs/commands.md, "How commands change the model"). Kept apart from the Model so that a run
// state can save and restore it.

#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"

namespace openmss::commands {

// A statement kind and id, e.g. {"JOINT", 12}; statements without an id (ACCGRAV) use 0.
using ElementKey = std::pair<std::string, long>;

struct ModelEdits {
  // Elements deactivated (absent from the model built from the edits).
  std::set<ElementKey> inactive;
  // Redefining commands in the order given; each merges its arguments into the statement it
  // names (a later command wins; an argument replaces those it excludes, e.g. VELOCITY replaces
  // DISPLACEMENT in a MOTION).
  std::vector<language::Statement> redefinitions;

  bool empty() const { return inactive.empty() && redefinitions.empty(); }
};

// The data set with `edits` laid over it: inactive statements removed, redefinitions merged.
// A redefinition of a statement without id that the data set lacks (ACCGRAV) adds it.
language::Dataset editedDataset(const language::Dataset& dataset, const ModelEdits& edits);

// Merges the arguments of a redefining command into `target` (LIST is not merged).
void mergeArguments(const language::Statement& command, language::Statement& target);

// The statements of `dataset` named `kind` (ids in data-set order; empty when none).
std::vector<long> statementIds(const language::Dataset& dataset, const std::string& kind);

// Statement kinds that a redefining command addresses without an id (one per data set).
bool isSingletonStatement(const std::string& kind);

}  // namespace openmss::commands

#pragma once
// The state a reprocessed model starts from: after ACTIVATE, DEACTIVATE or a redefining
// command the model is built again (model_edits.hpp) and the next analysis starts from the
// last state of the old one, as ADAMS does (docs/commands.md, "Reprocessing"): the time, the
// pose and velocity of every moving part, and the values of the user states (VARIABLE, DIFF,
// LSE/TFSISO, GSE) that both models have, and the expression history of the elements that
// remain (turn counts, DELAY histories, SENVAL; docs/theory.md §11c). The initial conditions
// are solved again.

#include "analysis/run_state.hpp"
#include "mechanics/multibody_system.hpp"

namespace openmss::commands {

// Copies the carried values of `from` (a state of `fromSystem`) into `to` (a fresh state of
// `toSystem`). Both models come from the same data set, so they have the same parts; a part
// whose centre-of-mass frame was redefined (PART/id, CM=) keeps the motion of its body.
void carryOverState(const mechanics::MultibodySystem& fromSystem, const analysis::RunState& from,
                    const mechanics::MultibodySystem& toSystem, analysis::RunState& to);

}  // namespace openmss::commands

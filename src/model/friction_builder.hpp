#pragma once
// Dataset -> Model for FRICTION (joint friction, docs/theory.md "Joint friction"): the joint it
// acts on (translational, revolute, cylindrical, spherical, Hooke or universal), the friction
// coefficients, velocities, lengths and switches with ADAMS's defaults and ranges; and the
// FRICTION(id, comp) read-back in functions.

#include <functional>
#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "expr/expression.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

// Needs every joint (call after the joints are built).
void buildFrictions(const std::vector<const language::Statement*>& statements, Model& model,
                    Diagnostics& diags);

// FRICTION(id, comp) with comp 1..22 (docs/theory.md, "Joint friction", read-back table):
// false when `call` is not FRICTION; otherwise fills `m` or reports through `fail`.
bool bindFrictionMeasure(const Model& model, const expr::HostCall& call, Measure& m,
                         const std::function<void(const std::string&, const std::string&)>& fail);

}  // namespace openmss::model

#pragma once
// Dataset -> Model for SENSOR statements (docs/theory.md, "Sensors"), the binding of
// SENVAL(id). (GSE, once rejected here, is built in model/user_equation_builder.cpp.)

#include <string>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"
#include "model/user_equation_builder.hpp"

namespace openmss::model {

// Creates Model::sensors from the SENSOR statements, with every check that does not need the
// expressions (VALUE, the test, ERROR, DT, STEPSIZE, the actions the solver cannot perform).
// Runs before any expression is bound so that SENVAL(id) can be resolved anywhere.
void buildSensors(const language::Dataset& dataset, Model& model, Diagnostics& diags);
// Binds FUNCTION= and EVALUATE= of every sensor built by buildSensors.
void bindSensorFunctions(const language::Dataset& dataset, Model& model, Diagnostics& diags);

// SENVAL(id): fills `m` and returns true when `call` is SENVAL (calling `fail` for a wrong id).
bool bindSensorMeasure(const Model& model, const expr::HostCall& call, Measure& m,
                       const BindFailure& fail);

}  // namespace openmss::model

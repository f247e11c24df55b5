#pragma once
// Dataset -> Model for the data elements SPLINE, CURVE, MATRIX and STRING, with their checks
// (value counts, increasing X and Z, matrix sizes, curve orders, references between them), and
// the binding of the expression functions that read them (AKISPL, CUBSPL, CURVE).

#include <string>

#include "common/diagnostics.hpp"
#include "expr/expression.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

bool isDataElementStatement(const std::string& name);

// Builds every SPLINE, MATRIX, CURVE and STRING of the data set into the model. Runs before any
// expression is bound, so expressions anywhere in the file may use them.
void buildDataElements(const language::Dataset& dataset, Model& model, Diagnostics& diags);

// Binds each data call of `expression` to the model's SPLINE or CURVE. An unknown id is an
// error at the call's column (where.column is the column of the expression's first character).
bool bindDataCalls(const Model& model, expr::Expression& expression, const SourceLocation& where,
                   const std::string& subject, Diagnostics& diags);

}  // namespace openmss::model

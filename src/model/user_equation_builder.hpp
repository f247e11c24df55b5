#pragma once
// Dataset -> Model for the user equations (docs/theory.md §4a): VARIABLE, DIFF, ARRAY, LSE,
// TFSISO, PINPUT, POUTPUT, with the data-set checks of each (required arguments, array sizes
// and kinds, references), and the binding of VARVAL, DIF, DIF1, ARYVAL, PINVAL, POUVAL.

#include <functional>
#include <string>
#include <vector>

#include "common/diagnostics.hpp"
#include "expr/expression.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"

namespace openmss::model {

bool isUserEquationStatement(const std::string& name);

// Builds the elements (everything but the FUNCTION expressions, which may read any of them:
// bindUserEquationFunctions). LSE reads its MATRIX statements from the data set.
void buildUserEquations(const std::vector<const language::Statement*>& statements,
                        const language::Dataset& dataset, Model& model, Diagnostics& diags);
// Binds the FUNCTION= expressions of VARIABLE and DIFF.
void bindUserEquationFunctions(const std::vector<const language::Statement*>& statements,
                               Model& model, Diagnostics& diags);

// VARVAL(id), DIF(id), DIF1(id), ARYVAL(id, n), PINVAL(id, n), POUVAL(id, n): fills `m` and
// returns true when `call` is one of them (calling `fail` for a wrong id or position).
using BindFailure = std::function<void(const std::string& what, const std::string& hint)>;
bool bindUserMeasure(const Model& model, const expr::HostCall& call, Measure& m,
                     const BindFailure& fail);

}  // namespace openmss::model

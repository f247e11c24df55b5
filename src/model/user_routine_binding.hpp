#pragma once
// FUNCTION=USER(...) on a one-routine element (SFORCE, VFORCE, VTORQUE, GFORCE, VARIABLE,
// DIFF, MOTION, REQUEST, SENSOR): loads the evaluation subroutine (ROUTINE=lib::name or the
// default library and name), runs its dependency pass, and binds each output the element uses
// as an expression over the measures the subroutine declared (docs/user-subroutines.md).

#include <memory>
#include <vector>

#include "common/diagnostics.hpp"
#include "language/dataset.hpp"
#include "model/model.hpp"
#include "user/element_routine.hpp"

namespace openmss::model {

// bindExpression (model_builder.hpp) for an expression already parsed into out.expression: a
// USER(...) bound to its subroutine binds the measures the subroutine declared. Defined in
// model_builder.cpp, next to bindExpression.
bool bindParsedExpression(const Model& model, const SourceLocation& where,
                          const std::string& subject, bool forForces, Diagnostics& diags,
                          BoundExpression& out, bool forConstraint = false,
                          bool forRequest = false);

// The directory user libraries are looked for in first: the data set's.
std::string userLibraryDirectory(const Model& model);

// `fn` is the statement's USER(...) argument, `routineArgument` the one naming its routine;
// outputs[k] receives routine output k (nullptr: unused). False with located diagnostics when the
// library, the routine or a measure it reads is missing; the element is then not simulated.
bool bindUserRoutine(const Model& model, const language::Statement& s, const language::Argument& fn,
                     user::RoutineKind kind, user::ElementData element,
                     const std::vector<BoundExpression*>& outputs, bool forForces,
                     Diagnostics& diags, bool forRequest = false,
                     const char* routineArgument = "ROUTINE");

// What GTARAY, GTSTRG, GTCURV, AKISPL and CUBSPL read from a user routine of this model.
std::shared_ptr<const user::ModelData> userModelData(const Model& model);

// FIELD/id, FUNCTION=USER(...): loads FIESUB into f.user. False with located diagnostics.
bool bindUserField(const Model& model, const language::Statement& s, model::LinearField& f,
                   Diagnostics& diags);

}  // namespace openmss::model

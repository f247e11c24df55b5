#include "model/user_routine_binding.hpp"

#include <filesystem>

#include "model/model_builder.hpp"
#include "model/user_subroutine_arguments.hpp"

namespace openmss::model {

std::string userLibraryDirectory(const Model& model) {
  const std::string dir = std::filesystem::path(model.file).parent_path().string();
  return dir.empty() ? "." : dir;
}

namespace {

// What GTARAY, GTSTRG, GTCURV, AKISPL and CUBSPL read (shared with the model's own data).
std::shared_ptr<const user::ModelData> modelData(const Model& model) {
  auto d = std::make_shared<user::ModelData>();
  for (const SplineData& s : model.splines)
    if (s.spline) d->splines[s.id] = s.spline;
  for (const CurveData& c : model.curves)
    if (c.curve) d->curves[c.id] = c.curve;
  for (const DataArray& a : model.arrays)
    if (a.kind == DataArray::Kind::IC || a.kind == DataArray::Kind::Constants)
      d->arrays[a.id] = a.numbers;
  for (const StringData& s : model.strings) d->strings[s.id] = s.text;
  return d;
}

}  // namespace

bool bindUserRoutine(const Model& model, const language::Statement& s, const language::Argument& fn,
                     user::RoutineKind kind, user::ElementData element,
                     const std::vector<BoundExpression*>& outputs, bool forForces,
                     Diagnostics& diags, bool forRequest, const char* routineArgument) {
  expr::Expression parsed;
  if (!expr::Expression::parse(fn.expression, fn.valueWhere, s.subject(), diags, parsed))
    return false;
  const expr::UserCall* call = parsed.userCall();
  if (!call) return false;  // the caller checked that FUNCTION is USER(...)
  element.subject = s.subject();
  element.id = s.id ? *s.id : 0;
  element.par = call->arguments;
  element.data = modelData(model);
  std::string error;
  const user::RoutineName name = elementRoutineName(s, routineArgument);
  std::shared_ptr<user::ElementRoutine> routine =
      user::loadElementRoutine(kind, element, name, userLibraryDirectory(model), error);
  if (!routine) {
    diags.error(fn.where, s.subject(), error,
                std::string("Supply the library that defines ") + user::routineName(kind) +
                    " (ROUTINE=lib::name on the statement, or openmss run --user-library LIB); "
                    "docs/user-subroutines.md says how to build one.");
    return false;
  }
  bool ok = true;
  for (size_t k = 0; k < outputs.size(); ++k) {
    if (!outputs[k]) continue;
    BoundExpression b;
    b.expression = parsed;
    expr::bindUserFunction(b.expression, routine->component(static_cast<int>(k)),
                           routine->dependencies());
    if (bindParsedExpression(model, fn.valueWhere, s.subject(), forForces, diags, b, false,
                             forRequest))
      *outputs[k] = std::move(b);
    else
      ok = false;
    if (!ok) break;  // the same measures fail for every output: report them once
  }
  return ok;
}

}  // namespace openmss::model

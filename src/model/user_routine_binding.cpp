#include "model/user_routine_binding.hpp"

#include <filesystem>

#include "model/model_builder.hpp"
#include "model/units_table.hpp"
#include "model/user_subroutine_arguments.hpp"
#include "user/field_routine.hpp"

namespace openmss::model {

std::string userLibraryDirectory(const Model& model) {
  const std::string dir = std::filesystem::path(model.file).parent_path().string();
  return dir.empty() ? "." : dir;
}

// What GTARAY, GTSTRG, GTCURV, AKISPL and CUBSPL read (shared with the model's own data).
std::shared_ptr<const user::ModelData> userModelData(const Model& model) {
  auto d = std::make_shared<user::ModelData>();
  for (const SplineData& s : model.splines)
    if (s.spline) d->splines[s.id] = s.spline;
  for (const CurveData& c : model.curves)
    if (c.curve) d->curves[c.id] = c.curve;
  for (const DataArray& a : model.arrays)
    if (a.kind == DataArray::Kind::IC || a.kind == DataArray::Kind::Constants)
      d->arrays[a.id] = a.numbers;
  for (const StringData& s : model.strings) d->strings[s.id] = s.text;
  // SYSTEM=NONE: consistent units of no stated size (scales 1, blank names).
  d->unitsGiven = model.units.given;
  const bool named = model.units.description.rfind("consistent", 0) != 0;
  const std::string* names[4] = {&model.units.time, &model.units.length, &model.units.force,
                                 &model.units.mass};
  for (int k = 0; k < 4; ++k) {
    d->unitScales[static_cast<size_t>(k)] = named ? unitInSi(*names[k]) : 1.0;
    std::string symbol = named ? unitSymbol(*names[k]) : "";
    symbol.resize(3, ' ');
    d->unitNames += symbol;
  }
  return d;
}

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
  element.data = userModelData(model);
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

bool bindUserField(const Model& model, const language::Statement& s, LinearField& f,
                   Diagnostics& diags) {
  // FUNCTION=USER replaces the matrices: ADAMS's FIELD takes one or the other.
  bool ok = true;
  for (const char* name : {"KMATRIX", "CMATRIX", "CRATIO", "LENGTH", "FORCE"})
    if (const language::Argument* a = s.find(name)) {
      diags.error(a->where, s.subject(),
                  std::string(name) + " with FUNCTION=USER(...): FIESUB gives the whole load",
                  std::string("Remove ") + name + ", or FUNCTION to use the matrices.");
      ok = false;
    }
  const auto par = userParameters(s, diags);
  if (!par || !ok) return false;
  user::ElementData e;
  e.subject = s.subject();
  e.id = s.id ? *s.id : 0;
  e.par = *par;
  e.i = model.markers[static_cast<size_t>(f.iMarker)].id;
  e.j = model.markers[static_cast<size_t>(f.jMarker)].id;
  e.data = userModelData(model);
  std::string error;
  f.user = user::loadFieldRoutine(e, elementRoutineName(s), userLibraryDirectory(model), error);
  if (!f.user) {
    diags.error(s.find("FUNCTION")->where, s.subject(), error,
                "Supply the library that defines FIESUB (ROUTINE=lib::name on the statement, or "
                "openmss run --user-library LIB); docs/user-subroutines.md says how to build one.");
    return false;
  }
  return true;
}

}  // namespace openmss::model

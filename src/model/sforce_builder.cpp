#include "model/sforce_builder.hpp"

#include <utility>

#include "model/model_builder.hpp"
#include "model/part_builder.hpp"
#include "model/statement_arguments.hpp"
#include "model/user_routine_binding.hpp"

namespace openmss::model {

using language::Argument;
using language::Statement;

void buildSForces(const std::vector<const Statement*>& statements, Model& model,
                  Diagnostics& diags) {
  for (const Statement* s : statements) {
    if (!s->id) continue;
    StatementArguments a(*s, diags);
    SForce f;
    f.id = *s->id;
    f.where = s->where;
    f.iMarker = markerReference(model, *s, "I", diags);
    f.jMarker = markerReference(model, *s, "J", diags);
    f.rotation = s->has("ROTATION");
    if (s->has("ROTATION") == s->has("TRANSLATION"))
      a.error(s->where, "give exactly one of TRANSLATION and ROTATION",
              "Add TRANSLATION (a force along I-J) or ROTATION (a torque about zJ).");
    f.actionOnly = s->has("ACTIONONLY");
    if (!s->has("FUNCTION")) {
      a.require("FUNCTION", "<expression>");
      continue;
    }
    if (f.iMarker < 0 || f.jMarker < 0) continue;
    model.sforces.push_back(std::move(f));
  }
}

void bindSForceFunctions(const std::vector<const Statement*>& statements, Model& model,
                         Diagnostics& diags) {
  // Model::sforces holds the statements that built, in statement order.
  size_t k = 0;
  for (const Statement* s : statements) {
    if (k >= model.sforces.size() || !s->id || model.sforces[k].id != *s->id) continue;
    const Argument* fn = s->find("FUNCTION");
    if (fn->expression.rfind("USER", 0) == 0) {
      SForce& f = model.sforces[k];
      user::ElementData e;
      e.i = model.markers[static_cast<size_t>(f.iMarker)].id;
      e.j = model.markers[static_cast<size_t>(f.jMarker)].id;
      e.actionOnly = f.actionOnly;
      e.rotation = f.rotation;
      bindUserRoutine(model, *s, *fn, user::RoutineKind::Sfosub, e, {&f.function}, true, diags);
    } else {
      bindExpression(model, fn->expression, fn->valueWhere, s->subject(), true, diags,
                     model.sforces[k].function);
    }
    ++k;
  }
}

}  // namespace openmss::model

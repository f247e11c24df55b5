#include "model/request_builder.hpp"

#include <string>
#include <utility>

#include "model/model_builder.hpp"
#include "model/part_builder.hpp"
#include "model/statement_arguments.hpp"
#include "model/user_routine_binding.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// F1..F8 as request columns; false when one of them does not bind.
bool bindColumns(const Statement& s, Model& model, Request& r, Diagnostics& diags) {
  bool ok = true;
  for (int c = 0; c < 8; ++c) {
    const Argument* fa = s.find(("F" + std::to_string(c + 1)).c_str());
    if (!fa) continue;
    BoundExpression b;
    if (bindExpression(model, fa->expression, fa->valueWhere, s.subject(), false, diags, b,
                       /*forConstraint=*/false, /*forRequest=*/true))
      r.columns[c] = std::move(b);
    else
      ok = false;
  }
  return ok;
}

void buildRequest(const Statement& s, Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  Request r;
  r.id = *s.id;
  r.where = s.where;
  if (const Argument* c = s.find("COMMENT"))
    r.comment = c->expression.empty() && !c->values.empty() ? c->values[0].text : c->expression;
  static const std::pair<const char*, Request::Kind> kinds[] = {
      {"DISPLACEMENT", Request::Kind::Displacement},
      {"VELOCITY", Request::Kind::Velocity},
      {"ACCELERATION", Request::Kind::Acceleration},
      {"FORCE", Request::Kind::Force}};
  int nKinds = 0;
  for (const auto& [name, kind] : kinds)
    if (s.has(name)) {
      r.kind = kind;
      ++nKinds;
    }
  bool hasF = false;
  for (int c = 0; c < 8; ++c) hasF |= s.has(("F" + std::to_string(c + 1)).c_str());
  if (const Argument* fn = s.find("FUNCTION")) {
    // REQSUB's eight values are the request's columns, as F1..F8 would be.
    if (fn->expression.rfind("USER", 0) != 0 || nKinds > 0 || hasF) {
      a.error(*fn, "FUNCTION= must be USER(r1[,...,r30]) and excludes the other kinds",
              "Keep FUNCTION=USER(...) (REQSUB) alone, or use F1..F8 expressions.");
      return;
    }
    std::vector<BoundExpression> b(8);
    std::vector<BoundExpression*> outputs;
    for (BoundExpression& x : b) outputs.push_back(&x);
    user::ElementData e;
    e.comment = r.comment;
    if (!bindUserRoutine(model, s, *fn, user::RoutineKind::Reqsub, e, outputs, false, diags,
                         /*forRequest=*/true))
      return;
    for (size_t c = 0; c < 8; ++c) r.columns[c] = std::move(b[c]);
    model.requests.push_back(std::move(r));
    return;
  }
  if (nKinds > 1 || (nKinds == 1 && hasF)) {
    a.error(s.where, "DISPLACEMENT, VELOCITY, ACCELERATION, FORCE and F1..F8 exclude each other",
            "Keep one kind of request per REQUEST statement.");
    return;
  }
  if (nKinds == 0 && !hasF) {
    a.error(s.where, "the request asks for nothing",
            "Add DISPLACEMENT, VELOCITY, ACCELERATION or FORCE with I=, or F2=... "
            "expressions.");
    return;
  }
  if (nKinds == 1) {
    r.iMarker = markerReference(model, s, "I", diags);
    if (s.has("J")) r.jMarker = markerReference(model, s, "J", diags);
    if (s.has("RM")) r.rmMarker = markerReference(model, s, "RM", diags);
    if (r.iMarker < 0) return;
  } else if (!bindColumns(s, model, r, diags)) {
    return;
  }
  model.requests.push_back(std::move(r));
}

}  // namespace

void buildRequests(const std::vector<const Statement*>& statements, Model& model,
                   Diagnostics& diags) {
  for (const Statement* s : statements)
    if (s->id) buildRequest(*s, model, diags);
}

}  // namespace openmss::model

#include "model/general_constraint_builder.hpp"

#include <algorithm>

#include "model/model_builder.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// Measures a GCON may read: functions of the marker poses alone, so the equation is holonomic
// and its first and second derivatives follow from the marker frames.
bool isPositionMeasure(MeasureKind kind) {
  switch (kind) {
    case MeasureKind::DX: case MeasureKind::DY: case MeasureKind::DZ: case MeasureKind::DM:
    case MeasureKind::AX: case MeasureKind::AY: case MeasureKind::AZ:
    case MeasureKind::PSI: case MeasureKind::THETA: case MeasureKind::PHI:
    case MeasureKind::YAW: case MeasureKind::PITCH: case MeasureKind::ROLL:
      return true;
    default:
      return false;
  }
}

int markerOf(const Statement& s, const char* name, const Model& model, Diagnostics& diags) {
  const Argument* a = s.find(name);
  if (!a || a->values.empty()) return -1;
  const long id = static_cast<long>(a->values[0].number);
  auto it = model.markerIndex.find(id);
  if (it == model.markerIndex.end()) {
    diags.error(a->where, s.subject(),
                std::string(name) + "=" + std::to_string(id) + ": marker " + std::to_string(id) +
                    " does not exist",
                "Use the id of a MARKER statement of this data set.");
    return -2;
  }
  if (model.markers[it->second].floating) {
    diags.error(a->where, s.subject(),
                std::string(name) + "=" + std::to_string(id) + ": marker " + std::to_string(id) +
                    " is FLOATING",
                "Use a fixed marker.");
    return -2;
  }
  return it->second;
}

void buildOne(const Statement& s, Model& model, Diagnostics& diags) {
  GeneralConstraint g;
  g.id = *s.id;
  g.where = s.where;
  bool ok = true;
  if (const Argument* j = s.find("J")) {
    diags.error(j->where, s.subject(), "GCON has no J marker",
                "Remove J=; the FUNCTION names every marker it reads, and I= the marker whose "
                "reaction is reported.");
    ok = false;
  }
  g.iMarker = markerOf(s, "I", model, diags);
  if (g.iMarker == -2) ok = false;
  const Argument* fn = s.find("FUNCTION");
  if (!fn) {
    diags.error(s.where, s.subject(), "FUNCTION is missing",
                "Give FUNCTION=<expression>, the quantity the constraint holds at zero.");
    return;
  }
  if (fn->expression.rfind("USER", 0) == 0 || s.has("ROUTINE")) {
    diags.error(fn->where, s.subject(), "FUNCTION=USER(...) (GCOSUB) is not supported yet",
                "Write the constraint as an expression.");
    return;
  }
  if (!bindExpression(model, fn->expression, fn->valueWhere, s.subject(), false, diags,
                      g.function, /*forConstraint=*/true))
    return;
  const auto& calls = g.function.expression.hostCalls();
  std::vector<int> markers;
  auto note = [&markers](int m) {
    if (m >= 0 && std::find(markers.begin(), markers.end(), m) == markers.end())
      markers.push_back(m);
  };
  for (size_t k = 0; k < calls.size(); ++k) {
    const Measure& m = g.function.measures[k];
    if (!isPositionMeasure(m.kind)) {
      SourceLocation at = fn->valueWhere;
      if (at.column > 0) at.column += calls[k].column - 1;
      diags.error(at, s.subject(),
                  calls[k].name + " at column " + std::to_string(calls[k].column) +
                      " of the expression cannot appear in a GCON",
                  "A GCON may read marker displacements and angles only (DX, DY, DZ, DM, AX, "
                  "AY, AZ, PSI, THETA, PHI, YAW, PITCH, ROLL); velocity (non-holonomic) "
                  "constraints are not supported yet.");
      ok = false;
      continue;
    }
    note(m.i);
    note(m.j);
    note(m.k);
  }
  if (g.function.expression.dependsOnTime()) {
    diags.error(fn->valueWhere, s.subject(), "the FUNCTION depends on TIME",
                "Time-dependent (rheonomic) GCONs are not supported yet; drive the motion with "
                "a MOTION statement.");
    ok = false;
  }
  if (ok && calls.empty()) {
    diags.error(fn->valueWhere, s.subject(), "the FUNCTION reads no marker",
                "A GCON constrains marker positions or angles, e.g. FUNCTION=DZ(2,1).");
    ok = false;
  }
  if (static_cast<int>(markers.size()) > GeneralConstraint::kMaxMarkers ||
      static_cast<int>(calls.size()) > GeneralConstraint::kMaxMeasures) {
    diags.error(fn->valueWhere, s.subject(),
                "the FUNCTION reads " + std::to_string(markers.size()) + " markers and " +
                    std::to_string(calls.size()) + " distinct measures",
                "A GCON may read at most " + std::to_string(GeneralConstraint::kMaxMarkers) +
                    " markers and " + std::to_string(GeneralConstraint::kMaxMeasures) +
                    " measures; split it into several GCONs.");
    ok = false;
  }
  if (ok) model.gcons.push_back(std::move(g));
}

}  // namespace

void buildGeneralConstraints(const std::vector<const Statement*>& statements, Model& model,
                             Diagnostics& diags) {
  for (const Statement* s : statements) {
    if (!s->id) continue;  // the reader reports a statement without an id
    buildOne(*s, model, diags);
  }
}

}  // namespace openmss::model

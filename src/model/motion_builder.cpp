#include "model/motion_builder.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "model/data_element_builder.hpp"
#include "model/motion_variables.hpp"
#include "model/part_builder.hpp"
#include "model/statement_arguments.hpp"
#include "model/user_routine_binding.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// DISPLACEMENT (the default), VELOCITY or ACCELERATION, and the ICs that go with the last two.
bool motionForm(StatementArguments& a, Motion& m) {
  const Statement& s = a.statement();
  int nForms = 0;
  for (const auto& [name, form] : {std::pair{"DISPLACEMENT", Motion::Form::Displacement},
                                   std::pair{"VELOCITY", Motion::Form::Velocity},
                                   std::pair{"ACCELERATION", Motion::Form::Acceleration}})
    if (s.has(name)) {
      m.form = form;
      ++nForms;
    }
  if (nForms > 1) {
    a.error(s.where, "DISPLACEMENT, VELOCITY and ACCELERATION exclude each other",
            "Keep one of them (DISPLACEMENT is the default).");
    return false;
  }
  return true;
}

// ADAMS reads ICDISP and ICVEL on every motion; they only matter where the function is
// integrated, so elsewhere they warn.
void motionInitialConditions(StatementArguments& a, Motion& m, Diagnostics& diags) {
  const Statement& s = a.statement();
  if (s.has("ICDISP") && m.form == Motion::Form::Displacement)
    diags.warning(s.find("ICDISP")->where, s.subject(),
                  "ICDISP has no effect on a displacement motion (its function gives the "
                  "displacement)",
                  "Remove ICDISP, or make the motion VELOCITY or ACCELERATION.");
  if (s.has("ICVEL") && m.form != Motion::Form::Acceleration)
    diags.warning(s.find("ICVEL")->where, s.subject(),
                  "ICVEL has no effect unless the motion is ACCELERATION",
                  "Remove ICVEL, or make the motion ACCELERATION.");
  m.icDisp = a.real("ICDISP").value_or(0.0);
  m.icVel = a.real("ICVEL").value_or(0.0);
}

// JOINT=: along (translational) or about (revolute) the joint's z axis; a cylindrical joint
// needs TRANSLATION or ROTATION. Returns false when the motion is dropped.
bool jointMotion(StatementArguments& a, const Model& model, Motion& m) {
  const Statement& s = a.statement();
  for (const char* axis : {"X", "Y", "Z", "B1", "B2", "B3"})
    if (s.has(axis))
      a.error(*s.find(axis), std::string(axis) + " applies to marker-pair (I=, J=) motions only",
              "Remove it; a joint motion acts along or about the joint's z axis.");
  auto jid = a.id("JOINT");
  if (!jid) return false;
  auto it = model.jointIndex.find(*jid);
  if (it == model.jointIndex.end()) {
    a.error(*s.find("JOINT"), "JOINT/" + std::to_string(*jid) + " does not exist (or is invalid)",
            "Use the id of a JOINT statement of this data set.");
    return false;
  }
  m.joint = it->second;
  const Joint& joint = model.joints[m.joint];
  m.iMarker = joint.iMarker;
  m.jMarker = joint.jMarker;
  JointType jt = joint.type;
  if (jt == JointType::Revolute) {
    m.rotation = true;
  } else if (jt == JointType::Translational) {
    m.rotation = false;
  } else if (jt == JointType::Cylindrical) {
    if (s.has("TRANSLATION") == s.has("ROTATION")) {
      a.error(s.where, "a motion on a cylindrical joint needs exactly one of TRANSLATION, ROTATION",
              "Add TRANSLATION or ROTATION.");
      return false;
    }
    m.rotation = s.has("ROTATION");
  } else {
    a.error(s.where,
            std::string("a joint motion needs a revolute, translational or cylindrical "
                        "joint; JOINT/") +
                std::to_string(*jid) + " is " + jointTypeName(jt),
            "Drive a revolute, translational or cylindrical joint, or use I=, J= with "
            "X, Y, Z, B1, B2 or B3.");
    return false;
  }
  m.axis = m.rotation ? 5 : 2;
  return true;
}

// I=, J= with one of X, Y, Z (translation of I in J's axes) or B1, B2, B3 (body 1-2-3 angles
// of I relative to J). Returns false when the motion is dropped.
bool markerMotion(StatementArguments& a, const Model& model, Motion& m, Diagnostics& diags) {
  const Statement& s = a.statement();
  m.iMarker = markerReference(model, s, "I", diags);
  m.jMarker = markerReference(model, s, "J", diags);
  int nAxes = 0;
  static const char* kAxes[6] = {"X", "Y", "Z", "B1", "B2", "B3"};
  for (int k = 0; k < 6; ++k)
    if (s.has(kAxes[k])) {
      m.axis = k;
      ++nAxes;
    }
  if (nAxes != 1) {
    a.error(s.where,
            nAxes == 0 ? "a marker-pair motion needs its direction"
                       : "more than one direction is given",
            "Give exactly one of X, Y, Z (translation of I in J's axes) or B1, B2, B3 "
            "(body 1-2-3 rotation angles of I relative to J).");
    return false;
  }
  for (const char* jointOnly : {"TRANSLATION", "ROTATION"})
    if (s.has(jointOnly))
      a.error(*s.find(jointOnly), std::string(jointOnly) + " applies to joint motions only",
              "Remove it; X, Y, Z, B1, B2 or B3 gives the direction.");
  if (m.iMarker < 0 || m.jMarker < 0) return false;
  if (model.markers[m.iMarker].part == model.markers[m.jMarker].part) {
    a.error(s.where, "I and J markers are on the same part",
            "A motion acts between two parts: put I and J on different parts.");
    return false;
  }
  m.rotation = m.axis >= 3;
  return true;
}

// FUNCTION=USER(...): MOTSUB gives the function and its time derivatives (IORD 0, 1, 2).
bool userMotion(const Statement& s, const Argument& f, const Model& model, Motion& m,
                Diagnostics& diags) {
  user::ElementData e;
  e.joint = m.joint >= 0 ? model.joints[static_cast<size_t>(m.joint)].id : 0;
  e.i = model.markers[static_cast<size_t>(m.iMarker)].id;
  e.j = model.markers[static_cast<size_t>(m.jMarker)].id;
  e.motionType = m.rotation ? "ROTATION" : "TRANSLATION";
  e.motionWhich = "XYZ123"[m.axis];
  e.motionDva = m.form == Motion::Form::Displacement ? "DISPLACEMENT"
                : m.form == Motion::Form::Velocity   ? "VELOCITY"
                                                     : "ACCELERATION";
  BoundExpression b;
  if (!bindUserRoutine(model, s, f, user::RoutineKind::Motsub, e, {&b}, true, diags)) return false;
  m.function = std::move(b.expression);
  return true;
}

// FUNCTION=: an expression of TIME (and data elements) only, VARVAL of VARIABLEs that are
// functions of TIME included (motion_variables.hpp). Returns false when it is not.
bool motionFunction(StatementArguments& a, const Model& model,
                    const std::vector<const Statement*>& variables, Motion& m, Diagnostics& diags) {
  const Statement& s = a.statement();
  const Argument* f = s.find("FUNCTION");
  if (!f) {
    a.require("FUNCTION", "<expression of TIME>");
    return false;
  }
  if (f->expression.rfind("USER", 0) == 0) return userMotion(s, *f, model, m, diags);
  if (!expr::Expression::parse(f->expression, f->valueWhere, s.subject(), diags, m.function))
    return false;
  const auto& calls = m.function.hostCalls();
  if (!calls.empty() && std::all_of(calls.begin(), calls.end(),
                                    [](const expr::HostCall& c) { return c.name == "VARVAL"; })) {
    std::string text = f->expression;
    if (!inlineTimeVariables(s, f->valueWhere, variables, diags, text)) return false;
    if (!expr::Expression::parse(text, f->valueWhere, s.subject(), diags, m.function)) return false;
  }
  if (!bindDataCalls(model, m.function, f->valueWhere, s.subject(), diags)) return false;
  if (m.function.delayCount() > 0) {
    // A motion needs exact velocity and acceleration (time jets) of its function; the
    // recorded DELAY history gives neither yet.
    a.error(f->valueWhere, "DELAY is not supported in MOTION functions yet",
            "Write the delayed motion directly as a function of TIME (e.g. "
            "SIN(TIME-0.5) for DELAY(SIN(TIME), 0.5, 0)).");
    return false;
  }
  if (!m.function.hostCalls().empty()) {
    a.error(
        f->valueWhere,
        "a MOTION function may depend on TIME only, but it calls " + m.function.hostCalls()[0].name,
        "Rewrite the function in terms of TIME.");
    return false;
  }
  return true;
}

void buildMotion(const Statement& s, const std::vector<const Statement*>& variables, Model& model,
                 Diagnostics& diags) {
  StatementArguments a(s, diags);
  Motion m;
  m.id = *s.id;
  m.where = s.where;
  if (!motionForm(a, m)) return;
  motionInitialConditions(a, m, diags);
  const bool onJoint = s.has("JOINT");
  if (onJoint == (s.has("I") || s.has("J"))) {
    a.error(s.where,
            onJoint ? "JOINT= excludes I= and J=" : "the motion names no joint and no markers",
            "Give JOINT=<id> (with TRANSLATION or ROTATION on a cylindrical joint), or "
            "I=<id>, J=<id> with one of X, Y, Z, B1, B2, B3.");
    return;
  }
  if (onJoint ? !jointMotion(a, model, m) : !markerMotion(a, model, m, diags)) return;
  if (!motionFunction(a, model, variables, m, diags)) return;
  model.motions.push_back(std::move(m));
}

}  // namespace

void buildMotions(const std::vector<const Statement*>& statements,
                  const std::vector<const Statement*>& variables, Model& model,
                  Diagnostics& diags) {
  for (const Statement* s : statements)
    if (s->id) buildMotion(*s, variables, model, diags);
}

}  // namespace openmss::model

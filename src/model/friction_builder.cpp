#include "model/friction_builder.hpp"

#include "model/statement_arguments.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

bool frictionJointKind(JointType t) {
  return t == JointType::Translational || t == JointType::Revolute || t == JointType::Cylindrical ||
         t == JointType::Spherical || t == JointType::Hooke || t == JointType::Universal;
}

// A number > 0 read into `out` (kept at its default when absent).
void positiveArgument(StatementArguments& a, const char* name, double& out) {
  const std::optional<double> v = a.real(name);
  if (!v) return;
  if (!(*v > 0.0)) {
    a.error(*a.find(name), std::string(name) + " must be greater than zero",
            "Give a positive " + std::string(name) + ".");
    return;
  }
  out = *v;
}

// INPUTS=ALL | NONE | PRELOAD:REACTION_FORCE:BENDING_MOMENT:TORSIONAL_MOMENT.
void readInputs(StatementArguments& a, Friction& f) {
  const Argument* inputs = a.find("INPUTS");
  if (!inputs) return;
  f.usePreload = f.useReactionForce = f.useBendingMoment = f.useTorsionalMoment = false;
  for (const language::Value& v : inputs->values) {
    if (v.text == "ALL") {
      f.usePreload = f.useReactionForce = f.useBendingMoment = f.useTorsionalMoment = true;
    } else if (v.text == "PRELOAD") {
      f.usePreload = true;
    } else if (v.text == "REACTION_FORCE") {
      f.useReactionForce = true;
    } else if (v.text == "BENDING_MOMENT") {
      f.useBendingMoment = true;
    } else if (v.text == "TORSIONAL_MOMENT") {
      f.useTorsionalMoment = true;
    }
    // NONE: every switch off.
  }
  if (inputs->values.size() > 1)
    for (const language::Value& v : inputs->values)
      if (v.text == "ALL" || v.text == "NONE")
        a.error(*inputs, "INPUTS: " + v.text + " cannot be combined with other inputs",
                "Give INPUTS=ALL, INPUTS=NONE, or a list of PRELOAD, REACTION_FORCE, "
                "BENDING_MOMENT, TORSIONAL_MOMENT.");
}

// Arguments that only some joint kinds use (ADAMS's table of inputs per joint): given on
// another kind they would have no effect, so they are refused rather than ignored.
void checkArgumentsForJoint(StatementArguments& a, const Friction& f, JointType type) {
  const std::string kind = jointTypeName(type);
  auto refuse = [&](const char* name, const std::string& which) {
    if (const Argument* arg = a.find(name))
      a.error(*arg, std::string(name) + " has no effect on a " + kind + " joint",
              "Remove it; " + std::string(name) + " applies to " + which + " joints.");
  };
  const bool pin = type == JointType::Revolute || type == JointType::Cylindrical ||
                   type == JointType::Hooke || type == JointType::Universal;
  const bool arms =
      type == JointType::Revolute || type == JointType::Hooke || type == JointType::Universal;
  const bool overlap = type == JointType::Translational || type == JointType::Cylindrical;
  if (!pin) refuse("PIN_RADIUS", "revolute, cylindrical, Hooke and universal");
  if (type != JointType::Spherical) refuse("BALL_RADIUS", "spherical");
  if (!arms) refuse("BENDING_REACTION_ARM", "revolute, Hooke and universal");
  if (!arms && type != JointType::Translational)
    refuse("FRICTION_ARM", "translational, revolute, Hooke and universal");
  if (!overlap) refuse("INITIAL_OVERLAP", "translational and cylindrical");
  (void)f;
}

void buildFriction(const Statement& s, Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  Friction f;
  f.id = *s.id;
  f.where = s.where;
  a.require("JOINT",
            "<id of a translational, revolute, cylindrical, spherical, Hooke or "
            "universal joint>");
  a.require("MU_STATIC", "<static coefficient of friction>");
  a.require("MU_DYNAMIC", "<dynamic coefficient of friction>");
  const std::optional<long> jointId = a.id("JOINT");
  const std::optional<double> muS = a.real("MU_STATIC"), muD = a.real("MU_DYNAMIC");
  if (jointId) {
    auto it = model.jointIndex.find(*jointId);
    if (it == model.jointIndex.end()) {
      a.error(*a.find("JOINT"), "joint " + std::to_string(*jointId) + " does not exist",
              "Use the id of a JOINT statement of this data set.");
    } else {
      const Joint& j = model.joints[it->second];
      if (!frictionJointKind(j.type)) {
        a.error(*a.find("JOINT"),
                "JOINT/" + std::to_string(j.id) + " is a " + jointTypeName(j.type) +
                    " joint, and FRICTION acts only on translational, revolute, cylindrical, "
                    "spherical, Hooke and universal joints",
                "Put the friction on a joint of one of those kinds, or model it with an "
                "SFORCE or GFORCE.");
      } else {
        f.joint = it->second;
        checkArgumentsForJoint(a, f, j.type);
      }
    }
  }
  if (muS) {
    if (*muS < 0.0) a.error(*a.find("MU_STATIC"), "MU_STATIC must not be negative", "");
    f.muStatic = *muS;
  }
  if (muD) {
    if (*muD < 0.0) a.error(*a.find("MU_DYNAMIC"), "MU_DYNAMIC must not be negative", "");
    f.muDynamic = *muD;
  }
  positiveArgument(a, "STICTION_TRANSITION_VELOCITY", f.stictionVelocity);
  positiveArgument(a, "MAX_STICTION_DEFORMATION", f.maxStictionDeformation);
  positiveArgument(a, "FRICTION_ARM", f.frictionArm);
  positiveArgument(a, "BENDING_REACTION_ARM", f.bendingArm);
  positiveArgument(a, "BALL_RADIUS", f.ballRadius);
  positiveArgument(a, "PIN_RADIUS", f.pinRadius);
  positiveArgument(a, "INITIAL_OVERLAP", f.initialOverlap);
  if (const std::optional<double> p = a.real("FRICTION_FORCE_PRELOAD")) {
    if (*p < 0.0)
      a.error(*a.find("FRICTION_FORCE_PRELOAD"), "FRICTION_FORCE_PRELOAD must not be negative",
              "Give the preload's magnitude (the friction opposes the slip whatever its sign).");
    else
      f.preload = *p;
  }
  if (const std::optional<std::string> e = a.word("EFFECT"))
    f.effect = *e == "STICTION"  ? Friction::Effect::Stiction
               : *e == "SLIDING" ? Friction::Effect::Sliding
                                 : Friction::Effect::All;
  readInputs(a, f);
  f.inactiveStatic = a.has("INACTIVE");
  if (a.ok() && f.joint >= 0 && muS && muD) model.frictions.push_back(f);
}

}  // namespace

void buildFrictions(const std::vector<const Statement*>& statements, Model& model,
                    Diagnostics& diags) {
  for (const Statement* s : statements) buildFriction(*s, model, diags);
}

bool bindFrictionMeasure(const Model& model, const expr::HostCall& call, Measure& m,
                         const std::function<void(const std::string&, const std::string&)>& fail) {
  if (call.name != "FRICTION") return false;
  m.kind = MeasureKind::FrictionOutput;
  const long id = call.args.empty() ? 0 : call.args[0];
  m.component = call.args.size() > 1 ? static_cast<int>(call.args[1]) : 0;
  for (size_t k = 0; k < model.frictions.size(); ++k)
    if (model.frictions[k].id == id) m.element = static_cast<int>(k);
  if (m.element < 0)
    fail("FRICTION/" + std::to_string(id) + " does not exist",
         "Use the id of a FRICTION statement of this data set.");
  if (m.component < 1 || m.component > 22)
    fail("the index must be 1 to 22",
         "1-3 friction force, 4-6 friction torque, 7-12 coefficients, 13 static coefficient, "
         "14-19 slip velocities, 20-22 creep (J axes); docs/theory.md, \"Joint friction\".");
  return true;
}

}  // namespace openmss::model

#include "model/joint_builder.hpp"

#include <string>

#include "model/part_builder.hpp"
#include "model/statement_arguments.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// The joint type keyword: the number of type keywords given (exactly one is valid).
int jointType(const Statement& s, JointType& type) {
  static const std::pair<const char*, JointType> types[] = {
      {"REVOLUTE", JointType::Revolute},
      {"SPHERICAL", JointType::Spherical},
      {"UNIVERSAL", JointType::Universal},
      {"HOOKE", JointType::Hooke},
      {"TRANSLATIONAL", JointType::Translational},
      {"CYLINDRICAL", JointType::Cylindrical},
      {"FIXED", JointType::Fixed},
      {"CONVEL", JointType::Convel},
      {"PLANAR", JointType::Planar},
      {"RACKPIN", JointType::RackPin},
      {"SCREW", JointType::Screw}};
  int nTypes = 0;
  for (const auto& [name, t] : types)
    if (s.has(name)) {
      type = t;
      ++nTypes;
    }
  return nTypes;
}

// PD (rack-and-pinion) and PITCH (screw) belong to their joint type and are required there.
// Returns false when the joint's own data is missing or invalid (the joint is then dropped).
bool jointData(StatementArguments& a, bool oneType, Joint& j) {
  const Statement& s = a.statement();
  const bool rackPin = oneType && j.type == JointType::RackPin;
  const bool screw = oneType && j.type == JointType::Screw;
  bool ok = true;
  if (rackPin) {
    a.require("PD", "<pitch diameter of the pinion>");
    j.pitchDiameter = a.real("PD").value_or(0.0);
    if (s.has("PD") && !(j.pitchDiameter > 0.0)) {
      a.error(*s.find("PD"), "PD must be positive",
              "Give the pinion's pitch diameter, PD=<value> > 0.");
      ok = false;
    }
  } else if (s.has("PD")) {
    a.error(*s.find("PD"), "PD applies to RACKPIN joints only", "Remove PD.");
  }
  if (screw) {
    a.require("PITCH", "<travel per turn>");
    j.pitch = a.real("PITCH").value_or(0.0);
    if (s.has("PITCH") && j.pitch == 0.0) {
      a.error(*s.find("PITCH"), "PITCH must not be zero",
              "Give the translation per turn, PITCH=<value> (negative: left-handed).");
      ok = false;
    }
  } else if (s.has("PITCH")) {
    a.error(*s.find("PITCH"), "PITCH applies to SCREW joints only", "Remove PITCH.");
  }
  if ((rackPin && !s.has("PD")) || (screw && !s.has("PITCH"))) ok = false;
  return ok;
}

// Joint initial conditions: IC on revolute (rotation) and translational (translation) joints,
// ICTRAN and ICROT on cylindrical joints; displacement [, velocity]. Held by the
// initial-condition analysis (mechanics/initial_conditions.cpp).
void jointInitialConditions(StatementArguments& a, Joint& j) {
  const Statement& s = a.statement();
  auto icPair = [&](const char* name, std::optional<double>& disp, std::optional<double>& vel) {
    const Argument* ic = s.find(name);
    if (!ic) return;
    if (ic->values.size() >= 1) disp = ic->values[0].number;
    if (ic->values.size() >= 2) vel = ic->values[1].number;
  };
  const bool icAllowed = j.type == JointType::Revolute || j.type == JointType::Translational;
  if (s.has("IC") && !icAllowed)
    a.error(*s.find("IC"),
            std::string("IC applies to revolute and translational joints; this joint is ") +
                jointTypeName(j.type),
            j.type == JointType::Cylindrical ? "Use ICTRAN= and ICROT= on a cylindrical joint."
                                             : "Remove IC.");
  for (const char* name : {"ICTRAN", "ICROT"})
    if (s.has(name) && j.type != JointType::Cylindrical)
      a.error(*s.find(name), std::string(name) + " applies to cylindrical joints only",
              j.type == JointType::Revolute || j.type == JointType::Translational
                  ? "Use IC= on a revolute or translational joint."
                  : "Remove it.");
  if (j.type == JointType::Revolute) icPair("IC", j.icRotation, j.icRotationVelocity);
  if (j.type == JointType::Translational) icPair("IC", j.icTranslation, j.icTranslationVelocity);
  if (j.type == JointType::Cylindrical) {
    icPair("ICTRAN", j.icTranslation, j.icTranslationVelocity);
    icPair("ICROT", j.icRotation, j.icRotationVelocity);
  }
}

bool onSamePart(const Model& model, int i, int j) {
  return i >= 0 && j >= 0 && model.markers[i].part == model.markers[j].part;
}

void buildJoint(const Statement& s, Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  Joint j;
  j.id = *s.id;
  j.where = s.where;
  int nTypes = jointType(s, j.type);
  if (nTypes == 0)
    a.error(s.where, "the joint type is missing",
            "Add one of CONVEL, CYLINDRICAL, FIXED, HOOKE, PLANAR, RACKPIN, REVOLUTE, "
            "SCREW, SPHERICAL, TRANSLATIONAL, UNIVERSAL.");
  else if (nTypes > 1)
    a.error(s.where, "more than one joint type is given", "Keep exactly one joint type.");
  j.iMarker = markerReference(model, s, "I", diags);
  j.jMarker = markerReference(model, s, "J", diags);
  if (!jointData(a, nTypes == 1, j)) nTypes = -1;
  if (nTypes == 1) jointInitialConditions(a, j);
  // Joint friction written inline by ADAMS/View (FRICTION=ON or PRELOAD_ONLY with MU_STAT_ROT,
  // INNER_RADIUS, ...): its mapping to the FRICTION statement is not published; without
  // FRICTION=ON those arguments have no effect (friction off), as in ADAMS/View.
  if (const Argument* fr = s.find("FRICTION");
      fr && !fr->values.empty() && fr->values[0].text != "OFF")
    a.error(*fr, "inline joint friction (FRICTION=" + fr->values[0].text + ") is not supported",
            "Write a FRICTION statement on this joint instead (docs/theory.md, \"Joint "
            "friction\").");
  // Without FRICTION=ON the inline friction data have no effect: say so once, naming them,
  // rather than ignore them silently.
  if (const Argument* fr = s.find("FRICTION"); !fr || fr->values.empty() ||
                                               fr->values[0].text == "OFF") {
    std::string given;
    for (const Argument& arg : s.args)
      for (const char* name :
           {"DELTA_V", "MAXIMUM_DEFORMATION", "MU_DYN_ROT", "MU_STAT_ROT", "MAX_FRIC_ROT",
            "MU_DYN_TRANS", "MU_STAT_TRANS", "MAX_FRIC_TRANS", "PRELOAD_RADIAL", "PRELOAD_AXIAL",
            "INNER_RADIUS", "OUTER_RADIUS", "PIN_RADIUS", "BALL_RADIUS", "FRICTION_ARM",
            "REACTION_ARM", "OVERLAP_DELTA"})
        if (arg.name == name) given += (given.empty() ? "" : ", ") + arg.name;
    if (!given.empty())
      diags.warning(s.where, s.subject(),
                    "the inline friction data (" + given +
                        ") have no effect: friction is off without FRICTION=ON, as in ADAMS/View",
                    "To model joint friction write a FRICTION statement on this joint "
                    "(docs/theory.md, \"Joint friction\"); remove these arguments to silence "
                    "this warning.");
  }
  if (onSamePart(model, j.iMarker, j.jMarker))
    a.error(s.where,
            "I and J markers are on the same part (PART/" +
                std::to_string(model.parts[model.markers[j.iMarker].part].id) + ")",
            "A joint connects two parts: put I and J on different parts.");
  if (nTypes == 1 && j.iMarker >= 0 && j.jMarker >= 0) {
    model.jointIndex[j.id] = static_cast<int>(model.joints.size());
    model.joints.push_back(j);
  }
}

void buildJointPrimitive(const Statement& s, Model& model, Diagnostics& diags) {
  StatementArguments a(s, diags);
  JPrim p;
  p.id = *s.id;
  p.where = s.where;
  static const std::pair<const char*, JPrimType> types[] = {
      {"ATPOINT", JPrimType::AtPoint},
      {"INLINE", JPrimType::InLine},
      {"INPLANE", JPrimType::InPlane},
      {"ORIENTATION", JPrimType::Orientation},
      {"PARALLEL_AXES", JPrimType::ParallelAxes},
      {"PERPENDICULAR", JPrimType::Perpendicular}};
  int nTypes = 0;
  for (const auto& [name, type] : types)
    if (s.has(name)) {
      p.type = type;
      ++nTypes;
    }
  if (nTypes != 1)
    a.error(s.where,
            nTypes == 0 ? "the joint primitive type is missing"
                        : "more than one joint primitive type is given",
            "Give exactly one of ATPOINT, INLINE, INPLANE, ORIENTATION, PARALLEL_AXES, "
            "PERPENDICULAR.");
  p.iMarker = markerReference(model, s, "I", diags);
  p.jMarker = markerReference(model, s, "J", diags);
  if (onSamePart(model, p.iMarker, p.jMarker)) {
    a.error(s.where,
            "I and J markers are on the same part (PART/" +
                std::to_string(model.parts[model.markers[p.iMarker].part].id) + ")",
            "A joint primitive connects two parts: put I and J on different parts.");
    return;
  }
  if (nTypes == 1 && p.iMarker >= 0 && p.jMarker >= 0) {
    model.jprimIndex[p.id] = static_cast<int>(model.jprims.size());
    model.jprims.push_back(p);
  }
}

}  // namespace

void buildJoints(const std::vector<const Statement*>& statements, Model& model,
                 Diagnostics& diags) {
  for (const Statement* s : statements)
    if (s->id) buildJoint(*s, model, diags);
}

void buildJointPrimitives(const std::vector<const Statement*>& statements, Model& model,
                          Diagnostics& diags) {
  for (const Statement* s : statements)
    if (s->id) buildJointPrimitive(*s, model, diags);
}

}  // namespace openmss::model

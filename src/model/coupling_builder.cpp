#include "model/coupling_builder.hpp"

#include "model/user_coupler_binding.hpp"

namespace openmss::model {
namespace {

using language::Argument;
using language::Statement;

// The index of JOINTS value k, -1 (with a diagnostic) when no such joint exists.
int jointOf(const Statement& s, const Argument& joints, size_t k, const Model& model,
            Diagnostics& diags) {
  const long id = static_cast<long>(joints.values[k].number);
  auto it = model.jointIndex.find(id);
  if (it == model.jointIndex.end()) {
    diags.error(joints.where, s.subject(),
                "JOINTS: joint " + std::to_string(id) + " does not exist",
                "Use the id of a JOINT statement of this data set.");
    return -1;
  }
  return it->second;
}

bool rotates(JointType t) { return t == JointType::Revolute || t == JointType::Cylindrical; }
bool translates(JointType t) {
  return t == JointType::Translational || t == JointType::Cylindrical;
}

void buildCoupler(const Statement& s, Model& model, Diagnostics& diags) {
  Coupler c;
  c.id = *s.id;
  c.where = s.where;
  const Argument* joints = s.find("JOINTS");
  const Argument* scales = s.find("SCALES");
  if (!joints) {
    diags.error(s.where, s.subject(), "JOINTS is missing", "Give JOINTS=<id>,<id>[,<id>].");
    return;
  }
  // FUNCTION=USER(...): COUSUB's phi replaces the linear relation (user_coupler_binding.cpp).
  const bool user = s.has("FUNCTION");
  if (user && scales) {
    diags.error(scales->where, s.subject(),
                "SCALES with FUNCTION=USER(...): COUSUB gives the whole constraint",
                "Remove SCALES, or FUNCTION to use the linear relation.");
    return;
  }
  if (!user && s.has("ROUTINE")) {
    diags.error(s.find("ROUTINE")->where, s.subject(), "ROUTINE= without FUNCTION=USER(...)",
                "Add FUNCTION=USER(r1[,...,r30]) or remove ROUTINE=.");
    return;
  }
  const size_t n = joints->values.size();
  bool ok = true;
  for (size_t k = 0; k < n; ++k) {
    const int j = jointOf(s, *joints, k, model, diags);
    if (j < 0) {
      ok = false;
      continue;
    }
    c.joints.push_back(j);
  }
  if (!ok) return;
  // TYPE: T or R per joint; by default what the joint allows (a cylindrical joint must say).
  const Argument* type = s.find("TYPE");
  if (type && type->values.size() != n)
    diags.error(type->where, s.subject(),
                "TYPE has " + std::to_string(type->values.size()) + " values for " +
                    std::to_string(n) + " joints",
                "Give one T (translation) or R (rotation) per joint.");
  for (size_t k = 0; k < n; ++k) {
    const Joint& j = model.joints[c.joints[k]];
    bool rotation = rotates(j.type);
    if (type && k < type->values.size()) rotation = type->values[k].text == "R";
    else if (j.type == JointType::Cylindrical)
      diags.error(s.where, s.subject(),
                  "JOINT/" + std::to_string(j.id) +
                      " is cylindrical: say which of its displacements is coupled",
                  "Give TYPE= with T or R for each joint.");
    if ((rotation && !rotates(j.type)) || (!rotation && !translates(j.type))) {
      diags.error(type ? type->where : s.where, s.subject(),
                  "JOINT/" + std::to_string(j.id) + " (" + jointTypeName(j.type) + ") has no " +
                      (rotation ? "rotation" : "translation") + " to couple",
                  "COUPLER couples revolute (R), translational (T) and cylindrical (T or R) "
                  "joints.");
      ok = false;
    }
    c.rotation.push_back(rotation);
  }
  if (user) {
    c.scales.assign(n, 1.0);  // unused: the equation is COUSUB's phi
    if (ok && bindUserCoupler(s, model, c, diags)) model.couplers.push_back(std::move(c));
    return;
  }
  // SCALES: r1 q1 + r2 q2 [+ r3 q3] = 0; with one value fewer than joints, r1 = 1.
  const size_t ns = scales ? scales->values.size() : 0;
  if (ns == n) {
    for (size_t k = 0; k < n; ++k) c.scales.push_back(scales->values[k].number);
  } else if (ns + 1 == n) {
    c.scales.push_back(1.0);
    for (size_t k = 0; k < ns; ++k) c.scales.push_back(scales->values[k].number);
  } else {
    diags.error(scales ? scales->where : s.where, s.subject(),
                "SCALES needs " + std::to_string(n - 1) + " or " + std::to_string(n) +
                    " values for " + std::to_string(n) + " joints",
                "Give SCALES=r2 (r1 = 1) or SCALES=r1,r2 for two joints; r2,r3 or r1,r2,r3 for "
                "three.");
    ok = false;
  }
  if (ok && c.scales[0] == 0.0) {
    diags.error(scales->where, s.subject(), "the first scale must not be zero",
                "Give a non-zero r1.");
    ok = false;
  }
  if (ok) model.couplers.push_back(std::move(c));
}

void buildGear(const Statement& s, Model& model, Diagnostics& diags) {
  Gear g;
  g.id = *s.id;
  g.where = s.where;
  const Argument* joints = s.find("JOINTS");
  const Argument* cv = s.find("CV");
  if (!joints || !cv) {
    diags.error(s.where, s.subject(), !joints ? "JOINTS is missing" : "CV is missing",
                "Give JOINTS=<id>,<id> and CV=<marker on the carrier>.");
    return;
  }
  bool ok = true;
  for (size_t k = 0; k < 2 && k < joints->values.size(); ++k) {
    g.joints[k] = jointOf(s, *joints, k, model, diags);
    if (g.joints[k] < 0) {
      ok = false;
      continue;
    }
    const Joint& j = model.joints[g.joints[k]];
    if (!rotates(j.type) && !translates(j.type)) {
      diags.error(joints->where, s.subject(),
                  "JOINT/" + std::to_string(j.id) + " is " + jointTypeName(j.type) +
                      "; a gear turns or slides in a revolute, translational or cylindrical joint",
                  "Name revolute, translational or cylindrical joints in JOINTS=.");
      ok = false;
    }
  }
  const long cvId = static_cast<long>(cv->values.at(0).number);
  auto it = model.markerIndex.find(cvId);
  if (it == model.markerIndex.end()) {
    diags.error(cv->where, s.subject(), "CV=" + std::to_string(cvId) + ": marker does not exist",
                "Use the id of a MARKER statement of this data set.");
    return;
  }
  g.cvMarker = it->second;
  if (!ok) return;
  // The carrier is the CV marker's part: each joint must connect its gear to it.
  const int carrier = model.markers[g.cvMarker].part;
  for (int k = 0; k < 2; ++k) {
    const Joint& j = model.joints[g.joints[k]];
    if (model.markers[j.iMarker].part != carrier && model.markers[j.jMarker].part != carrier) {
      diags.error(cv->where, s.subject(),
                  "the CV marker's part (PART/" + std::to_string(model.parts[carrier].id) +
                      ") is not connected by JOINT/" + std::to_string(j.id),
                  "Put the CV marker on the carrier, the part both joints connect their gears to.");
      ok = false;
    }
  }
  if (ok) model.gears.push_back(g);
}

}  // namespace

bool isCouplingStatement(const std::string& name) { return name == "COUPLER" || name == "GEAR"; }

void buildCouplings(const std::vector<const Statement*>& statements, Model& model,
                    Diagnostics& diags) {
  for (const Statement* s : statements) {
    if (!s->id) continue;
    if (s->name == "COUPLER") buildCoupler(*s, model, diags);
    else buildGear(*s, model, diags);
  }
}

}  // namespace openmss::model

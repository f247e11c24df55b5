#include "mechanics/constraint_set.hpp"

namespace openmss::mechanics {
namespace {

const char* kAxis[3] = {"X", "Y", "Z"};

ConstraintEquation point(int axis, const model::Joint& j, int index) {
  ConstraintEquation e;
  e.kind = ConstraintEquation::Kind::Point;
  e.axisJ = axis;
  e.iMarker = j.iMarker;
  e.jMarker = j.jMarker;
  e.joint = index;
  e.label = std::string(kAxis[axis]) + " (I-J)";
  return e;
}

ConstraintEquation dotEq(int ai, int aj, const model::Joint& j, int index) {
  ConstraintEquation e;
  e.kind = ConstraintEquation::Kind::Dot;
  e.axisI = ai;
  e.axisJ = aj;
  e.iMarker = j.iMarker;
  e.jMarker = j.jMarker;
  e.joint = index;
  e.label = std::string(kAxis[ai]) + "i." + kAxis[aj] + "j";
  return e;
}

ConstraintEquation along(int aj, const model::Joint& j, int index) {
  ConstraintEquation e;
  e.kind = ConstraintEquation::Kind::Along;
  e.axisJ = aj;
  e.iMarker = j.iMarker;
  e.jMarker = j.jMarker;
  e.joint = index;
  e.label = std::string(kAxis[aj]) + "j.(I-J)";
  return e;
}

}  // namespace

int ConstraintSet::equationCount(model::JointType t) {
  switch (t) {
    case model::JointType::Revolute: return 5;
    case model::JointType::Spherical: return 3;
    case model::JointType::Universal: return 4;
    case model::JointType::Hooke: return 4;
    case model::JointType::Translational: return 5;
    case model::JointType::Cylindrical: return 4;
    case model::JointType::Fixed: return 6;
  }
  return 0;
}

ConstraintSet::ConstraintSet(const model::Model& model) {
  using JT = model::JointType;
  for (int k = 0; k < static_cast<int>(model.joints.size()); ++k) {
    const model::Joint& j = model.joints[k];
    const bool coincident = j.type == JT::Revolute || j.type == JT::Spherical ||
                            j.type == JT::Universal || j.type == JT::Hooke || j.type == JT::Fixed;
    if (coincident)
      for (int a = 0; a < 3; ++a) eqs_.push_back(point(a, j, k));
    switch (j.type) {
      case JT::Revolute:
        eqs_.push_back(dotEq(2, 0, j, k));  // zI stays parallel to zJ
        eqs_.push_back(dotEq(2, 1, j, k));
        break;
      case JT::Universal:
        eqs_.push_back(dotEq(2, 2, j, k));  // the two cross-pin axes stay perpendicular
        break;
      case JT::Hooke:
        eqs_.push_back(dotEq(0, 1, j, k));  // xI and yJ outline the cross piece
        break;
      case JT::Fixed:
        eqs_.push_back(dotEq(2, 0, j, k));
        eqs_.push_back(dotEq(2, 1, j, k));
        eqs_.push_back(dotEq(0, 1, j, k));
        break;
      case JT::Translational:
        eqs_.push_back(dotEq(2, 0, j, k));
        eqs_.push_back(dotEq(2, 1, j, k));
        eqs_.push_back(dotEq(0, 1, j, k));  // no rotation about the common z axis
        eqs_.push_back(along(0, j, k));     // I origin stays on the zJ line
        eqs_.push_back(along(1, j, k));
        break;
      case JT::Cylindrical:
        eqs_.push_back(dotEq(2, 0, j, k));
        eqs_.push_back(dotEq(2, 1, j, k));
        eqs_.push_back(along(0, j, k));
        eqs_.push_back(along(1, j, k));
        break;
      case JT::Spherical:
        break;
    }
  }
  for (int k = 0; k < static_cast<int>(model.motions.size()); ++k) {
    const model::Motion& m = model.motions[k];
    const model::Joint& j = model.joints[m.joint];
    ConstraintEquation e;
    e.kind = m.rotation ? ConstraintEquation::Kind::MotionRotation
                        : ConstraintEquation::Kind::MotionTranslation;
    e.iMarker = j.iMarker;
    e.jMarker = j.jMarker;
    e.motion = k;
    e.label = m.rotation ? "rotation about Zj" : "translation along Zj";
    eqs_.push_back(e);
  }
}

std::string ConstraintSet::describe(int k, const model::Model& model) const {
  const ConstraintEquation& e = eqs_[k];
  if (e.joint >= 0) {
    const model::Joint& j = model.joints[e.joint];
    return "JOINT/" + std::to_string(j.id) + " (" + model::jointTypeName(j.type) +
           ") equation " + e.label;
  }
  return "MOTION/" + std::to_string(model.motions[e.motion].id) + " equation " + e.label;
}

}  // namespace openmss::mechanics

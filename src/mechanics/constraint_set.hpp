#pragma once
// The constraint equations of a model: every joint and motion expanded into scalar equations
// built from a few geometric primitives (docs/theory.md, "Constraints"). Each equation is
// written once, templated on the scalar; its Jacobian with respect to body virtual
// displacements (delta r in ground, delta pi in body axes) comes from forward-mode AD.

#include <string>
#include <vector>

#include "common/vec3.hpp"
#include "mechanics/pose.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

struct ConstraintEquation {
  enum class Kind {
    Point,        // component `axisJ` (0,1,2 = x,y,z of ground) of P_I - P_J
    Dot,          // (axis `axisI` of I) . (axis `axisJ` of J)
    Along,        // (axis `axisJ` of J) . (P_I - P_J)
    MotionRotation,     // angle of x_I about z_J from x_J, minus f(t) (wrapped to +-pi)
    MotionTranslation,  // z_J . (P_I - P_J) minus f(t)
  };
  Kind kind = Kind::Point;
  int axisI = 0;
  int axisJ = 0;
  int iMarker = -1;
  int jMarker = -1;
  int joint = -1;   // index into Model::joints, or -1
  int motion = -1;  // index into Model::motions, or -1
  std::string label;  // ADAMS-style, e.g. "Zi.Xj", "X (I-J)"
  bool active = true;  // false once found redundant: its multiplier is held at zero
};

template <class S>
struct Frame {
  V3<S> p;
  M3<S> a;
};

class ConstraintSet {
 public:
  ConstraintSet() = default;
  explicit ConstraintSet(const model::Model& model);

  const std::vector<ConstraintEquation>& equations() const { return eqs_; }
  std::vector<ConstraintEquation>& equations() { return eqs_; }
  int size() const { return static_cast<int>(eqs_.size()); }
  // "JOINT/1 (REVOLUTE) equation Zi.Xj"
  std::string describe(int k, const model::Model& model) const;
  // Number of scalar equations a joint type imposes (Gruebler count, seed Table 1).
  static int equationCount(model::JointType t);

  // Geometric part of equation k for the given marker frames (motion function not included).
  template <class S>
  static S geometry(const ConstraintEquation& eq, const Frame<S>& i, const Frame<S>& j);

 private:
  std::vector<ConstraintEquation> eqs_;
};

template <class S>
S ConstraintSet::geometry(const ConstraintEquation& eq, const Frame<S>& i, const Frame<S>& j) {
  using K = ConstraintEquation::Kind;
  switch (eq.kind) {
    case K::Point:
      return (i.p - j.p)[eq.axisJ];
    case K::Dot:
      return dot(i.a.c[eq.axisI], j.a.c[eq.axisJ]);
    case K::Along:
      return dot(j.a.c[eq.axisJ], i.p - j.p);
    case K::MotionRotation:
      return atan2Of(dot(i.a.c[0], j.a.c[1]), dot(i.a.c[0], j.a.c[0]));
    case K::MotionTranslation:
      return dot(j.a.c[2], i.p - j.p);
  }
  return S(0.0);
}

}  // namespace openmss::mechanics

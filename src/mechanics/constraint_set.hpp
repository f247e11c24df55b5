#pragma once
// The constraint equations of a model: every joint and motion expanded into scalar equations
// built from a few geometric primitives (docs/theory.md, "Constraints"). Each equation is
// written once, templated on the scalar; its Jacobian with respect to body virtual
// displacements (delta r in ground, delta pi in body axes) comes from forward-mode AD.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "common/vec3.hpp"
#include "mechanics/pose.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

struct ConstraintEquation {
  enum class Kind {
    Point,              // component `axisJ` (0,1,2 = x,y,z of ground) of P_I - P_J
    Dot,                // (axis `axisI` of I) . (axis `axisJ` of J)
    Along,              // (axis `axisJ` of J) . (P_I - P_J)
    MotionRotation,     // angle of x_I about z_J from x_J, minus f(t) (wrapped to +-pi)
    MotionTranslation,  // (axis `axisJ` of J) . (P_I - P_J) minus f(t)
    MotionAngle,        // body 1-2-3 angle `axisI` (0,1,2 = B1,B2,B3) of I rel J minus f(t)
    Convel,             // x_I.y_J + y_I.x_J: mirror symmetry of I and J about the bisecting plane
    RackPin,            // z_J.(P_I - P_J) - ratio * (angle of x_I about z_I from z_J) - offset
    Screw,              // z_J.(P_I - P_J) - ratio * (angle of x_I about z_J from x_J) - offset
  };
  Kind kind = Kind::Point;
  int axisI = 0;
  int axisJ = 0;
  int iMarker = -1;
  int jMarker = -1;
  int joint = -1;   // index into Model::joints, or -1
  int motion = -1;  // index into Model::motions, or -1
  int jprim = -1;   // index into Model::jprims, or -1
  // RackPin and Screw: travel per radian (PD/2, PITCH/2pi) and the equation's value at the
  // data set's configuration, so that the data set satisfies it; the value is taken modulo
  // one turn's travel (2 pi ratio), which tracks cumulative pinion/screw angles without state.
  double ratio = 0.0;
  double offset = 0.0;
  std::string label;   // ADAMS-style, e.g. "Zi.Xj", "X (I-J)"
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
  static int equationCount(model::JPrimType t);
  // 6 (moving parts) - the equations of every joint, joint primitive and motion (seed Table 1).
  static int grueblerCount(const model::Model& model);
  // True when the equation compares an atan2 angle with a motion target that may grow without
  // bound: the residual takes the difference modulo 2 pi.
  static bool wrapsAngle(const ConstraintEquation& eq) {
    return eq.kind == ConstraintEquation::Kind::MotionRotation ||
           (eq.kind == ConstraintEquation::Kind::MotionAngle && eq.axisI != 1);
  }

  // Geometric part of equation k for the given marker frames (motion function not included).
  template <class S>
  static S geometry(const ConstraintEquation& eq, const Frame<S>& i, const Frame<S>& j);

 private:
  std::vector<ConstraintEquation> eqs_;
};

template <class S>
S ConstraintSet::geometry(const ConstraintEquation& eq, const Frame<S>& i, const Frame<S>& j) {
  using K = ConstraintEquation::Kind;
  // The value minus whole periods, the period being one turn's travel; the rounding is locally
  // constant, so derivatives pass through unchanged.
  auto modTurn = [&eq](const S& v) {
    const double period = 2.0 * std::numbers::pi * std::abs(eq.ratio);
    return v - period * std::round(valueOf(v) / period);
  };
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
      return dot(j.a.c[eq.axisJ], i.p - j.p);
    case K::MotionAngle: {
      // R = A_J^T A_I = Rx(b1) Ry(b2) Rz(b3); R(a,b) = (axis a of J).(axis b of I).
      const S r02 = dot(j.a.c[0], i.a.c[2]);
      const S r12 = dot(j.a.c[1], i.a.c[2]);
      const S r22 = dot(j.a.c[2], i.a.c[2]);
      if (eq.axisI == 0) return atan2Of(-r12, r22);
      if (eq.axisI == 1) return atan2Of(r02, sqrtOf(r12 * r12 + r22 * r22));
      return atan2Of(-dot(j.a.c[0], i.a.c[1]), dot(j.a.c[0], i.a.c[0]));
    }
    case K::Convel:
      return dot(i.a.c[0], j.a.c[1]) + dot(i.a.c[1], j.a.c[0]);
    case K::RackPin: {
      const S angle = atan2Of(-dot(j.a.c[2], i.a.c[1]), dot(j.a.c[2], i.a.c[0]));
      return modTurn(dot(j.a.c[2], i.p - j.p) - eq.ratio * angle - eq.offset);
    }
    case K::Screw: {
      const S angle = atan2Of(dot(i.a.c[0], j.a.c[1]), dot(i.a.c[0], j.a.c[0]));
      return modTurn(dot(j.a.c[2], i.p - j.p) - eq.ratio * angle - eq.offset);
    }
  }
  return S(0.0);
}

}  // namespace openmss::mechanics

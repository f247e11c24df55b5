#pragma once
// The constraint equations of a model: every joint and motion expanded into scalar equations
// built from a few geometric primitives (docs/theory.md, "Constraints"). Each equation is
// written once, templated on the scalar; its Jacobian with respect to body virtual
// displacements (delta r in ground, delta pi in body axes) comes from forward-mode AD.

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "common/curve_contact.hpp"
#include "common/curve_projection.hpp"
#include "common/vec3.hpp"
#include "mechanics/pose.hpp"
#include "mechanics/user_coupler_value.hpp"
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
    RackPin,            // z_J.(P_I - P_J) + ratio * (angle of x_I about z_I from z_J) - offset
    Screw,              // z_J.(P_I - P_J) - ratio * (angle of x_I about z_J from x_J) - offset
    Coupled,            // sum of terms scale * (joint displacement - reference): COUPLER, GEAR
    General,            // a GCON's FUNCTION of marker measures (general_constraint.hpp)
    User,               // a UCON's UCOSUB F(q) of part variables (user_constraint_value.hpp)
    PointCurve,         // PTCV: normal component `axisI` (0, 1) of I's offset from the
                        // nearest point of `curve` in J's (RM's) frame; helper axis `axisJ`
                        // (common/curve_projection.hpp, docs/theory.md §5d)
    CurveCurve,         // CVCV: component `axisI` (0: common normal, 1: z of I) of the gap
                        // between `curve` in I's (IRM's) frame and `curveJ` in J's (JRM's)
                        // (common/curve_contact.hpp, docs/theory.md §5e)
  };
  // Coupled: one joint displacement of marker pair `pair` (0: iMarker, jMarker; 1, 2: the pairs
  // in moreMarkers), the rotation of x_I about z_J from x_J or the translation z_J.(P_I - P_J),
  // measured from `reference` (its value at the data set's configuration). Rotations are
  // unwrapped against the cumulative angle committed at the last accepted state, so that whole
  // turns accumulate: run-state storage (ExpressionRunState::coupledAngles, entry `slot`)
  // that `committed` points into once MultibodySystem::setRunState has bound it (null: the
  // data set's angle). Evaluations only read it, so Newton trials and rejected steps never
  // move the turn count; the driver commits after each accepted step (docs/theory.md §5b).
  struct CoupledTerm {
    int pair = 0;
    bool rotation = true;
    double scale = 1.0;
    double reference = 0.0;
    int slot = -1;                      // rotation terms: 0, 1, ... over the whole set
    const double* committed = nullptr;  // run-state storage of this term's committed angle
    double unwrapReference() const { return committed ? *committed : reference; }
  };
  Kind kind = Kind::Point;
  int axisI = 0;
  int axisJ = 0;
  int iMarker = -1;
  int jMarker = -1;
  int joint = -1;   // index into Model::joints, or -1
  int motion = -1;  // index into Model::motions, or -1
  int jprim = -1;   // index into Model::jprims, or -1
  int coupler = -1;  // index into Model::couplers, or -1
  int gear = -1;     // index into Model::gears, or -1
  int gcon = -1;     // index into Model::gcons, or -1
  int ucon = -1;     // index into Model::ucons, or -1
  int ptcv = -1;     // index into Model::ptcvs, or -1
  int cvcv = -1;     // index into Model::cvcvs, or -1
  // PointCurve: the curve (owned by the Model) and the samples of its nearest-point search.
  // CurveCurve: I's curve here, J's in curveJ, each with the samples of its coarse search.
  const BSplineCurve* curve = nullptr;
  int curveSamples = 0;
  const BSplineCurve* curveJ = nullptr;
  int curveSamplesJ = 0;
  // PointCurve, CurveCurve: the committed curve parameter(s) of the last accepted state, the
  // warm start of the search (run-state storage ExpressionRunState::curveParameters from entry
  // `curveSlot`, one for a PTCV, two for a CVCV; null or NaN: global search only).
  int curveSlot = -1;
  const double* warm = nullptr;
  // General: the GCON's bound FUNCTION (owned by the Model) and, per measure k, the frame slots
  // (indices s of eq.marker(s)) of its markers i, j and k; -1 = ground.
  const model::BoundExpression* function = nullptr;
  // User: per variable k of q, {frame slot, UCOVAR code, 0}.
  std::vector<std::array<int, 3>> measureSlots;
  const user::UserConstraintRoutine* userConstraint = nullptr;  // User: UCOSUB
  // Markers beyond iMarker and jMarker the equation reads (Coupled: I2, J2 [, I3, J3]);
  // geometry() receives the frames of iMarker, jMarker, then these.
  std::vector<int> moreMarkers;
  std::vector<CoupledTerm> terms;
  // Coupled, COUPLER with FUNCTION=USER: the equation is the routine's phi of the terms'
  // displacements (q - reference; their scales are unused), user_coupler_value.hpp.
  const user::CouplerRoutine* userCoupler = nullptr;
  // RackPin and Screw: travel per radian (PD/2, PITCH/2pi) and the equation's value at the
  // data set's configuration, so that the data set satisfies it; the value is taken modulo
  // one turn's travel (2 pi ratio), which tracks cumulative pinion/screw angles without state.
  double ratio = 0.0;
  double offset = 0.0;
  std::string label;   // ADAMS-style, e.g. "Zi.Xj", "X (I-J)"
  bool active = true;  // false once found redundant: its multiplier is held at zero

  static constexpr int kMaxMarkers = 6;
  int markerCount() const { return 2 + static_cast<int>(moreMarkers.size()); }
  int marker(int s) const { return s == 0 ? iMarker : s == 1 ? jMarker : moreMarkers[s - 2]; }
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
  // Points each coupled rotation term at angles[term.slot] (null: unbind), see CoupledTerm.
  void bindCoupledAngles(const double* angles);
  // Points each curve equation at parameters[eq.curveSlot] (null: unbind), see `warm`.
  void bindCurveParameters(const double* parameters);
  // The number of run-state curve parameters (slots) of the PTCV and CVCV equations.
  int curveParameterCount() const { return curveParameterCount_; }
  int size() const { return static_cast<int>(eqs_.size()); }
  // "JOINT/1 (REVOLUTE) equation Zi.Xj"
  std::string describe(int k, const model::Model& model) const;
  // Number of scalar equations a joint type imposes (Gruebler count, docs/theory.md §5).
  static int equationCount(model::JointType t);
  static int equationCount(model::JPrimType t);
  // 6 (moving parts) - the equations of every joint, joint primitive and motion (docs/theory.md §5).
  static int grueblerCount(const model::Model& model);
  // The initial-condition equations of the joints (IC, ICTRAN, ICROT displacements): the joint
  // coordinate minus the given value. They are not part of the DAE; the initial-condition
  // analysis adds them to the active equations (initial_conditions.hpp). `velocity` is the
  // given velocity of the same coordinate, or NaN.
  struct JointInitialCondition {
    ConstraintEquation equation;  // MotionRotation or MotionTranslation, joint = the joint
    double displacement = 0.0;
    double velocity = 0.0;
    bool hasDisplacement = false;
    bool hasVelocity = false;
  };
  static std::vector<JointInitialCondition> jointInitialConditions(const model::Model& model);
  // True when the equation compares an atan2 angle with a motion target that may grow without
  // bound: the residual takes the difference modulo 2 pi.
  static bool wrapsAngle(const ConstraintEquation& eq) {
    return eq.kind == ConstraintEquation::Kind::MotionRotation ||
           (eq.kind == ConstraintEquation::Kind::MotionAngle && eq.axisI != 1);
  }

  // Geometric part of equation k for the given marker frames (motion function not included):
  // frames[s] is the frame of eq.marker(s), s < eq.markerCount().
  template <class S>
  static S geometry(const ConstraintEquation& eq, const Frame<S>* frames);
  template <class S>
  static S geometry(const ConstraintEquation& eq, const Frame<S>& i, const Frame<S>& j) {
    const Frame<S> f[2] = {i, j};
    return geometry(eq, f);
  }

 private:
  std::vector<ConstraintEquation> eqs_;
  int curveParameterCount_ = 0;
};

// GCON equations (general_constraint.hpp, included at the end of this header).
template <class S>
S generalConstraintValue(const ConstraintEquation& eq, const Frame<S>* frames);
// UCON equations (user_constraint_value.hpp, included at the end of this header).
template <class S>
S userConstraintValue(const ConstraintEquation& eq, const Frame<S>* frames);

template <class S>
S ConstraintSet::geometry(const ConstraintEquation& eq, const Frame<S>* frames) {
  using K = ConstraintEquation::Kind;
  const Frame<S>& i = frames[0];
  const Frame<S>& j = frames[1];
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
      // ADAMS's sign (docs/theory.md §5): turning the pinion by +theta about z_I moves it by
      // -(PD/2) theta along z_J relative to the rack.
      const S angle = atan2Of(-dot(j.a.c[2], i.a.c[1]), dot(j.a.c[2], i.a.c[0]));
      return modTurn(dot(j.a.c[2], i.p - j.p) + eq.ratio * angle - eq.offset);
    }
    case K::Screw: {
      const S angle = atan2Of(dot(i.a.c[0], j.a.c[1]), dot(i.a.c[0], j.a.c[0]));
      return modTurn(dot(j.a.c[2], i.p - j.p) - eq.ratio * angle - eq.offset);
    }
    case K::Coupled: {
      S sum(0.0);
      S displacements[3] = {S(0.0), S(0.0), S(0.0)};
      int n = 0;
      for (const ConstraintEquation::CoupledTerm& term : eq.terms) {
        const Frame<S>& fi = frames[2 * term.pair];
        const Frame<S>& fj = frames[2 * term.pair + 1];
        S q;
        if (term.rotation) {
          q = atan2Of(dot(fi.a.c[0], fj.a.c[1]), dot(fi.a.c[0], fj.a.c[0]));
          // Whole turns: the rounding is locally constant, derivatives pass through.
          const double twoPi = 2.0 * std::numbers::pi;
          q = q + twoPi * std::round((term.unwrapReference() - valueOf(q)) / twoPi);
        } else {
          q = dot(fj.a.c[2], fi.p - fj.p);
        }
        if (eq.userCoupler && n < 3) displacements[n++] = q - term.reference;
        sum = sum + term.scale * (q - term.reference);
      }
      if (eq.userCoupler) return userCouplerValue(*eq.userCoupler, displacements, n);
      return sum;
    }
    case K::General:
      return generalConstraintValue(eq, frames);
    case K::User:
      return userConstraintValue(eq, frames);
    case K::PointCurve:
      return pointCurveResiduals(*eq.curve, eq.axisJ, eq.curveSamples, j.a.tmul(i.p - j.p),
                                 eq.warm)[eq.axisI];
    case K::CurveCurve:
      return curveCurveResiduals(*eq.curve, eq.curveSamples, *eq.curveJ, eq.curveSamplesJ, i.p,
                                 i.a, j.p, j.a, eq.warm)[eq.axisI];
  }
  return S(0.0);
}

}  // namespace openmss::mechanics

#include "mechanics/general_constraint.hpp"
#include "mechanics/user_constraint_value.hpp"


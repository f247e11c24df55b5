#pragma once
// Measures that read more than positions and velocities (docs/theory.md §4b): accelerations
// (ACCX..ACCM, WDTX..WDTM), which are y' of the velocity entries of the DAE state, and the
// reactions of joints, joint primitives and motions (JOINT, JPRIM, MOTION), which are linear in
// the multipliers in y. Both are templated on the scalar like every other measure, so that a
// force or VARIABLE function reading them puts its exact partials with respect to y' and the
// multipliers into the Newton matrix dG/dy + cj dG/dy'.

#include <cmath>

#include "common/dual.hpp"
#include "common/vec3.hpp"
#include "mechanics/constraint_set.hpp"
#include "mechanics/pose.hpp"
#include "mechanics/state_layout.hpp"
#include "model/measure.hpp"
#include "model/model.hpp"

namespace openmss::mechanics {

// What the residual lends a function besides y: the state derivative y' (accelerations) and the
// constraint equations (reactions from the multipliers in y). A null yp reads as zero
// accelerations (statics); a null constraint set as zero reactions.
template <class T>
struct DynamicReads {
  const T* yp = nullptr;
  const ConstraintSet* constraints = nullptr;
  // Force read-backs (SFORCE(...), SPDP, BUSH, ..., FX..TM; docs/theory.md §4d): the applied
  // force elements behind a type-erased pointer to their evaluator (force_read_back.hpp), so
  // that this header, which the force elements include, need not know them. Null: read as 0.
  const void* forces = nullptr;
  bool (*forceReadBack)(const void* forces, const model::Measure& ms, double t, const T* y,
                        const DynamicReads<T>* reads, T* out) = nullptr;
};

// True for the measure kinds dynamicMeasure evaluates (the model builder allows the same).
inline bool isDynamicMeasure(model::MeasureKind kind) {
  return model::readsAccelerationOrReaction(kind);
}

// Acceleration of a marker's origin and angular acceleration of its part, ground axes:
// p'' = v' + alpha x s + w x (w x s), alpha = A w_body' (s = the marker's offset from the CM).
template <class T>
void markerAcceleration(const model::Model& m, const StateLayout& l, int marker, const T* y,
                        const T* yp, V3<T>& acceleration, V3<T>& alpha) {
  acceleration = V3<T>(T(0.0), T(0.0), T(0.0));
  alpha = acceleration;
  if (marker < 0) return;
  const int body = m.parts[m.markers[marker].part].body;
  if (body < 0) return;
  const BodyPose<T> pose = bodyPose(l, body, y);
  const V3<T> s = pose.a * V3<T>::from(m.markers[marker].position);
  const V3<T> centripetal = cross(pose.wg, cross(pose.wg, s));
  if (yp == nullptr) {
    acceleration = centripetal;
    return;
  }
  const T* q = yp + l.body(body);
  const V3<T> vdot(q[StateLayout::kV], q[StateLayout::kV + 1], q[StateLayout::kV + 2]);
  const V3<T> wdot(q[StateLayout::kW], q[StateLayout::kW + 1], q[StateLayout::kW + 2]);
  alpha = pose.a * wdot;
  acceleration = vdot + cross(alpha, s) + centripetal;
}

// Second derivatives taken in the frame of marker l (the l argument of ACCX..WDTM;
// docs/theory.md §11b): with d = p_I - p_J, w = w_I - w_J and w_l, alpha_l the angular velocity
// and acceleration of l in ground, d''_l = d'' - alpha_l x d - 2 w_l x d' + w_l x (w_l x d) and
// w'_l = w' - w_l x w. `acc` and `wdt` hold the ground derivatives d'' and w' on entry.
template <class T>
void inFrameOfL(const model::Model& m, const StateLayout& l, const model::Measure& ms,
                const T* y, const T* yp, V3<T>& acc, V3<T>& wdt) {
  auto state = [&](int marker) {
    if (marker >= 0) return markerState(m, l, marker, y);
    MarkerState<T> g;
    g.p = g.pdot = g.w = V3<T>(T(0.0), T(0.0), T(0.0));
    return g;
  };
  const MarkerState<T> i = state(ms.i), j = state(ms.j), f = state(ms.l);
  V3<T> af, alphaf;
  markerAcceleration(m, l, ms.l, y, yp, af, alphaf);
  const V3<T> d = i.p - j.p, dd = i.pdot - j.pdot, w = i.w - j.w;
  acc = acc - cross(alphaf, d) - T(2.0) * cross(f.w, dd) + cross(f.w, cross(f.w, d));
  wdt = wdt - cross(f.w, w);
}

// The derivative of equation eq's geometry along virtual displacement `dir` of the part that
// carries marker slot `side` (0-2: translation along ground axes, 3-5: rotation about the part's
// own axes; `origin`, `axes` that part's frame): A <- A (I + [e_k] x) turns the part's points
// and axes about its k-th body axis. The residual's constraint force -C^T lambda uses this same
// function (MultibodySystem::virtualDerivative), so reactions read here are the forces the
// residual applies.
template <class T>
T virtualGeometryDerivative(const ConstraintEquation& eq, const Frame<T>* frames, int side,
                            int dir, const V3<T>& origin, const M3<T>& axes) {
  using S = Dual<T>;
  Frame<S> f[ConstraintEquation::kMaxMarkers];
  for (int s = 0; s < eq.markerCount(); ++s)
    for (int c = 0; c < 3; ++c) {
      f[s].p[c] = S(frames[s].p[c], T(0.0));
      for (int r = 0; r < 3; ++r) f[s].a.c[r][c] = S(frames[s].a.c[r][c], T(0.0));
    }
  if (dir < 3) {
    f[side].p[dir].d = T(1.0);
  } else {
    V3<T> ek(T(0.0), T(0.0), T(0.0));
    ek[dir - 3] = T(1.0);
    const V3<T> dp = axes * cross(ek, axes.tmul(frames[side].p - origin));
    for (int c = 0; c < 3; ++c) f[side].p[c].d = dp[c];
    for (int r = 0; r < 3; ++r) {
      const V3<T> da = axes * cross(ek, axes.tmul(frames[side].a.c[r]));
      for (int c = 0; c < 3; ++c) f[side].a.c[r][c].d = da[c];
    }
  }
  return ConstraintSet::geometry(eq, f).d;
}

// Force on the part of `marker` and torque about the marker's origin (ground axes) exerted by
// the active equations that `take(eq)` selects: -C^T lambda of those equations, as
// MultibodySystem::reactionOf computes it for the outputs.
template <class T, class Pick>
void constraintReactionOn(const model::Model& m, const StateLayout& l,
                          const ConstraintSet& constraints, Pick&& take, int marker, const T* y,
                          V3<T>& force, V3<T>& torque) {
  const V3<T> zero(T(0.0), T(0.0), T(0.0));
  force = zero;
  V3<T> bodyTorque = zero;
  const int body = m.parts[m.markers[marker].part].body;
  V3<T> origin = zero;
  M3<T> axes = M3<T>::from(Eigen::Matrix3d::Identity().eval());
  if (body >= 0) {
    const BodyPose<T> pose = bodyPose(l, body, y);
    origin = pose.r;
    axes = pose.a;
  }
  const auto& eqs = constraints.equations();
  for (int k = 0; k < static_cast<int>(eqs.size()); ++k) {
    const ConstraintEquation& eq = eqs[k];
    if (!eq.active || !take(eq)) continue;
    const T& lambda = y[l.lambda(k)];
    Frame<T> frames[ConstraintEquation::kMaxMarkers];
    for (int s = 0; s < eq.markerCount(); ++s) {
      const MarkerState<T> ms = markerState(m, l, eq.marker(s), y);
      frames[s] = {ms.p, ms.a};
    }
    for (int side = 0; side < eq.markerCount(); ++side) {
      if (eq.marker(side) != marker) continue;
      for (int dir = 0; dir < 6; ++dir) {
        const T d = virtualGeometryDerivative(eq, frames, side, dir, origin, axes);
        if (dir < 3) force[dir] = force[dir] - d * lambda;
        else bodyTorque[dir - 3] = bodyTorque[dir - 3] - d * lambda;
      }
    }
  }
  const V3<T> pm = markerState(m, l, marker, y).p;
  torque = axes * bodyTorque - cross(pm - origin, force);
}

// The same for the active equations of one joint, joint primitive or motion, as
// MultibodySystem::elementReaction computes it for the outputs.
template <class T>
void constraintElementReaction(const model::Model& m, const StateLayout& l,
                               const ConstraintSet& constraints, model::MeasureKind kind,
                               int element, int marker, const T* y, V3<T>& force,
                               V3<T>& torque) {
  using K = model::MeasureKind;
  constraintReactionOn(
      m, l, constraints,
      [&](const ConstraintEquation& eq) {
        return kind == K::JointForce    ? eq.joint == element
               : kind == K::MotionForce ? eq.motion == element
                                        : eq.jprim == element;
      },
      marker, y, force, torque);
}

// |a| with a zero derivative at a = 0 (a reaction that vanishes has no direction).
template <class T>
T magnitudeOf(const V3<T>& a) {
  const T squared = dot(a, a);
  if (valueOf(squared) == 0.0) return T(0.0);
  return sqrtOf(squared);
}

// Value of an acceleration or reaction measure; false for any other kind.
template <class T>
bool dynamicMeasure(const model::Model& m, const StateLayout& l, const model::Measure& ms,
                    const T* y, const DynamicReads<T>* reads, T* out) {
  using K = model::MeasureKind;
  if (!isDynamicMeasure(ms.kind)) return false;
  const M3<T> k = ms.k >= 0 ? markerState(m, l, ms.k, y).a
                            : M3<T>::from(Eigen::Matrix3d::Identity().eval());
  const T* yp = reads != nullptr ? reads->yp : nullptr;
  V3<T> ai, alphai, aj, alphaj;
  switch (ms.kind) {
    case K::ACCX: case K::ACCY: case K::ACCZ: case K::ACCM:
    case K::WDTX: case K::WDTY: case K::WDTZ: case K::WDTM: {
      // Time derivatives in ground: relative accelerations are plain differences.
      markerAcceleration(m, l, ms.i, y, yp, ai, alphai);
      markerAcceleration(m, l, ms.j, y, yp, aj, alphaj);
      V3<T> acc = ai - aj, wdt = alphai - alphaj;
      if (ms.l >= 0) inFrameOfL(m, l, ms, y, yp, acc, wdt);
      switch (ms.kind) {
        case K::ACCX: *out = dot(acc, k.c[0]); break;
        case K::ACCY: *out = dot(acc, k.c[1]); break;
        case K::ACCZ: *out = dot(acc, k.c[2]); break;
        case K::ACCM: *out = magnitudeOf(acc); break;
        case K::WDTX: *out = dot(wdt, k.c[0]); break;
        case K::WDTY: *out = dot(wdt, k.c[1]); break;
        case K::WDTZ: *out = dot(wdt, k.c[2]); break;
        default: *out = magnitudeOf(wdt); break;
      }
      return true;
    }
    default:
      break;
  }
  // JOINT, JPRIM, MOTION (id, jflag, comp, rm): at the element's I or J marker.
  if (reads == nullptr || reads->constraints == nullptr) {
    *out = T(0.0);
    return true;
  }
  int iMarker = -1, jMarker = -1;
  if (ms.kind == K::JointForce) {
    iMarker = m.joints[ms.element].iMarker;
    jMarker = m.joints[ms.element].jMarker;
  } else if (ms.kind == K::MotionForce) {
    iMarker = m.motions[ms.element].iMarker;
    jMarker = m.motions[ms.element].jMarker;
  } else {
    iMarker = m.jprims[ms.element].iMarker;
    jMarker = m.jprims[ms.element].jMarker;
  }
  V3<T> force, torque;
  constraintElementReaction(m, l, *reads->constraints, ms.kind, ms.element,
                            ms.atJ == 1 ? jMarker : iMarker, y, force, torque);
  switch (ms.component) {
    case 1: *out = magnitudeOf(force); break;
    case 2: case 3: case 4: *out = dot(force, k.c[ms.component - 2]); break;
    case 5: *out = magnitudeOf(torque); break;
    default: *out = dot(torque, k.c[ms.component - 6]); break;
  }
  return true;
}

}  // namespace openmss::mechanics
